#include "widgets/fields/led.h"

#include <QPainter>

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

void Led::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const qreal d = std::min(width(), height()) - 2.0;
    const QRectF r((width() - d) / 2.0, (height() - d) / 2.0, d, d);
    const QColor frame = palette().color(QPalette::WindowText);
    p.setPen(QPen(frame, 1.0));
    switch (m_state) {
    case State::Unknown:
        p.setBrush(Qt::NoBrush);
        break;
    case State::Off:
        p.setBrush(palette().color(QPalette::Mid));
        break;
    case State::On:
        p.setBrush(m_on);
        break;
    }
    p.drawEllipse(r);
}

} // namespace stepcom
