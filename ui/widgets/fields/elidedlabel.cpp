#include "widgets/fields/elidedlabel.h"

#include <QEvent>
#include <QResizeEvent>

namespace stepcom {

ElidedLabel::ElidedLabel(QWidget *parent)
    : QLabel(parent)
{
    setTextFormat(Qt::PlainText);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void ElidedLabel::setFullText(const QString &text)
{
    const QString simple = text.simplified();
    if (simple == m_full)
        return;
    m_full = simple;
    updateGeometry();
    elide();
}

void ElidedLabel::setMinimumChars(int chars)
{
    m_minimumChars = chars;
    updateGeometry();
}

void ElidedLabel::setFullToolTip(const QString &tip)
{
    m_tip = tip;
    elide();
}

QSize ElidedLabel::sizeHint() const
{
    const QMargins m = contentsMargins();
    return {m_full.isEmpty() ? 0
                             : fontMetrics().horizontalAdvance(m_full) + m.left() + m.right() + 1,
            QLabel::minimumSizeHint().height()};
}

QSize ElidedLabel::minimumSizeHint() const
{
    const int least = fontMetrics().averageCharWidth() * m_minimumChars;
    return {std::min(sizeHint().width(), least), QLabel::minimumSizeHint().height()};
}

void ElidedLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    elide();
}

void ElidedLabel::changeEvent(QEvent *event)
{
    QLabel::changeEvent(event);
    if (event->type() == QEvent::FontChange) {
        updateGeometry();
        elide();
    }
}

void ElidedLabel::elide()
{
    const QString shown =
        fontMetrics().elidedText(m_full, Qt::ElideRight, std::max(0, contentsRect().width()));
    if (shown != text())
        setText(shown);
    setToolTip(shown == m_full ? m_tip : m_full);
}

} // namespace stepcom
