#include "widgets/docks/messageview.h"

#include <QDateTime>
#include <QEvent>
#include <QListWidget>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>

namespace stepcom {

MessageView::MessageView(QWidget *parent)
    : QWidget(parent)
    , m_list(new QListWidget(this))
    , m_clear(new QPushButton(this))
{
    m_list->setWordWrap(true);
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_list);
    // Two messages are enough in view; the page needs the height more (1024×600).
    // Small icons beside a line of text: a row as high as the text, not as a large icon.
    const int icon = m_list->style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, m_list);
    m_list->setIconSize(QSize(icon, icon));
    const int row = std::max(m_list->fontMetrics().height(), icon) + 6;
    m_list->setMinimumHeight(2 * row + 2 * m_list->frameWidth());
    layout->addWidget(m_clear, 0, Qt::AlignRight);
    connect(m_clear, &QPushButton::clicked, m_list, &QListWidget::clear);
    m_clear->setText(tr("C&lear messages"));
}

void MessageView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        m_clear->setText(tr("C&lear messages"));
    QWidget::changeEvent(event);
}

void MessageView::add(DeviceSession::Severity severity, const QString &text)
{
    const QStyle::StandardPixmap icon =
        severity == DeviceSession::Severity::Error     ? QStyle::SP_MessageBoxCritical
        : severity == DeviceSession::Severity::Warning ? QStyle::SP_MessageBoxWarning
                                                       : QStyle::SP_MessageBoxInformation;
    auto *item = new QListWidgetItem(
        style()->standardIcon(icon),
        QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss  ")) + text);
    m_list->addItem(item);
    while (m_list->count() > 2000)
        delete m_list->takeItem(0);
    m_list->scrollToBottom();
}

QStringList MessageView::texts() const
{
    QStringList out;
    for (int i = 0; i < m_list->count(); ++i)
        out << m_list->item(i)->text();
    return out;
}

int MessageView::count() const
{
    return m_list->count();
}

} // namespace stepcom
