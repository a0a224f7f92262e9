#include "widgets/fields/verticalscrollarea.h"

#include <QEvent>
#include <QScrollBar>
#include <QStyle>

namespace stepcom {

VerticalScrollArea::VerticalScrollArea(QWidget *content, QWidget *parent)
    : QScrollArea(parent)
{
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setWidget(content);
    content->installEventFilter(this);
}

QSize VerticalScrollArea::minimumSizeHint() const
{
    const QSize base = QScrollArea::minimumSizeHint();
    if (!widget())
        return base;
    // Room for the scroll bar even while it is hidden: it comes when values make the content
    // taller, and the content must not lose width then.
    const int bar = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, this);
    const QMargins m = contentsMargins();
    return {widget()->minimumSizeHint().width() + bar + m.left() + m.right(), base.height()};
}

bool VerticalScrollArea::event(QEvent *event)
{
    if (event->type() == QEvent::LayoutRequest)
        updateGeometry();
    return QScrollArea::event(event);
}

bool VerticalScrollArea::eventFilter(QObject *watched, QEvent *event)
{
    // The content's needs changed (values read, language switched): ask the layout again.
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        updateGeometry();
    return QScrollArea::eventFilter(watched, event);
}

} // namespace stepcom
