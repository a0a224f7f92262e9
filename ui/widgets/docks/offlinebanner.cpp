#include "widgets/docks/offlinebanner.h"

#include "base/language.h"
#include "profile/profiledocument.h"

#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace stepcom {

OfflineBanner::OfflineBanner(ProfileDocument *document, QWidget *parent)
    : QFrame(parent)
    , m_document(document)
    , m_title(new QLabel(this))
    , m_variance(new QLabel(this))
{
    setObjectName(QStringLiteral("offlineBanner"));
    // The colour of "a file, not a machine": the same in the light and the dark palette.
    setStyleSheet(QStringLiteral("QFrame#offlineBanner { background: #d6e6ff; border: 1px solid "
                                 "#4a78c2; } QFrame#offlineBanner QLabel { color: black; }"));
    m_title->setObjectName(QStringLiteral("offlineBannerTitle"));
    m_title->setWordWrap(true);
    m_title->setTextFormat(Qt::PlainText);
    m_variance->setObjectName(QStringLiteral("offlineBannerVariance"));
    m_variance->setWordWrap(true);
    m_variance->setTextFormat(Qt::PlainText);
    m_variance->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_variance);
    connect(document, &ProfileDocument::changed, this, &OfflineBanner::refresh);
    refresh();
}

QString OfflineBanner::text() const
{
    return m_title->text();
}

QString OfflineBanner::varianceText() const
{
    return m_variance->text();
}

void OfflineBanner::refresh()
{
    setVisible(m_document->isOpen());
    if (!m_document->isOpen())
        return;
    QString title = tr("Editing the profile file %1 — no controller. Nothing here moves or "
                       "writes a controller; connect to compare the values with one and apply "
                       "them.")
                        .arg(m_document->displayName());
    if (m_document->isModified())
        title += QLatin1Char(' ') + tr("Edits not saved yet.");
    m_title->setText(title);
    const QStringList lines = m_document->varianceLines(Language::instance().current());
    m_variance->setText(
        lines.isEmpty()
            ? QString()
            : tr("This map cannot take everything the file holds (saved again, the file keeps "
                 "it; settings it lacks are filled with factory values when you save):") +
                  QStringLiteral("\n• ") + lines.join(QStringLiteral("\n• ")));
    m_variance->setVisible(!lines.isEmpty());
}

void OfflineBanner::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QFrame::changeEvent(event);
}

} // namespace stepcom
