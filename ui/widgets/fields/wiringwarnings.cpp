#include "widgets/fields/wiringwarnings.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>

namespace stepcom {

WiringWarnings::WiringWarnings(QWidget *parent)
    : QFrame(parent)
    , m_layout(new QVBoxLayout(this))
{
    setFrameShape(QFrame::StyledPanel);
    setFrameShadow(QFrame::Plain);
    rebuild();
}

void WiringWarnings::setWarnings(const QList<WiringWarning> &warnings, bool known)
{
    m_warnings = warnings;
    m_known = known;
    rebuild();
}

QStringList WiringWarnings::texts() const
{
    QStringList out;
    for (const QLabel *l : m_texts)
        out << l->text();
    return out;
}

void WiringWarnings::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange || event->type() == QEvent::StyleChange)
        rebuild();
    QFrame::changeEvent(event);
}

void WiringWarnings::rebuild()
{
    qDeleteAll(m_rows);
    m_rows.clear();
    m_texts.clear();
    const bool alarming = !m_warnings.isEmpty();
    // Tooltip colours are the palette's own "note" colours: visible in light and dark themes.
    setAutoFillBackground(alarming);
    setBackgroundRole(alarming ? QPalette::ToolTipBase : QPalette::Window);
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    auto addRow = [&](QStyle::StandardPixmap pixmap, const QString &text) {
        auto *row = new QWidget(this);
        auto *h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        auto *icon = new QLabel(row);
        icon->setPixmap(style()->standardIcon(pixmap, nullptr, this).pixmap(iconSize, iconSize));
        icon->setAlignment(Qt::AlignTop);
        auto *label = new QLabel(text, row);
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        if (alarming)
            label->setForegroundRole(QPalette::ToolTipText);
        h->addWidget(icon);
        h->addWidget(label, 1);
        m_layout->addWidget(row);
        m_rows << row;
        m_texts << label;
    };
    if (!m_known) {
        addRow(QStyle::SP_MessageBoxQuestion,
               tr("The wiring is not known yet: connect and read the controller."));
        return;
    }
    if (m_warnings.isEmpty()) {
        addRow(QStyle::SP_DialogApplyButton, tr("No suspicious wiring found."));
        return;
    }
    for (const WiringWarning &w : m_warnings) {
        QStyle::StandardPixmap pixmap = QStyle::SP_MessageBoxWarning;
        if (w.severity == WiringWarning::Severity::Error)
            pixmap = QStyle::SP_MessageBoxCritical;
        else if (w.severity == WiringWarning::Severity::Info)
            pixmap = QStyle::SP_MessageBoxInformation;
        addRow(pixmap, w.message);
    }
}

} // namespace stepcom
