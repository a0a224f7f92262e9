#include "widgets/fields/led.h"

#include "widgets/fields/statetone.h"

#include <QPainter>

#include <algorithm>

namespace stepcom {

Led::Led(QWidget *parent)
    : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void Led::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    update();
}

void Led::setOnColor(const QColor &color)
{
    m_on = color;
    update();
}

QSize Led::sizeHint() const
{
    const int d = fontMetrics().height();
    return {d, d};
}

QColor Led::litColor() const
{
    return withContrast(m_on, palette().color(backgroundRole()), kMinContrast);
}

void Led::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    // A ring wide enough to read as one at any scale, inside the widget.
    const qreal ring = std::max(1.0, std::min(width(), height()) / 9.0);
    const qreal d = std::min(width(), height()) - ring - 1.0;
    const QRectF r((width() - d) / 2.0, (height() - d) / 2.0, d, d);
    switch (m_state) {
    case State::Unknown: {
        QPen dotted(stateColour(StateTone::Unknown, palette(), backgroundRole()), ring);
        dotted.setStyle(Qt::DotLine);
        p.setPen(dotted);
        p.setBrush(Qt::NoBrush);
        break;
    }
    case State::Off:
        p.setPen(QPen(palette().color(QPalette::WindowText), ring));
        p.setBrush(Qt::NoBrush);
        break;
    case State::On:
        p.setPen(QPen(palette().color(QPalette::WindowText), 1.0));
        p.setBrush(litColor());
        break;
    }
    p.drawEllipse(r);
}

} // namespace stepcom
