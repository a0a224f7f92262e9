#include "replay/replayslider.h"

#include <QHelpEvent>
#include <QPainter>
#include <QSet>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QToolTip>

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace stepcom {

namespace {
constexpr int kNear = 3; // pixels either side of a marker that its tooltip covers
constexpr int kMaxTipLines = 12;
} // namespace

ReplaySlider::ReplaySlider(QWidget *parent)
    : QSlider(Qt::Horizontal, parent)
{
    setObjectName(QStringLiteral("replaySlider"));
    setRange(0, 0);
    setPageStep(10000);
    setSingleStep(1000);
    // Room below the handle for the markers.
    setMinimumHeight(fontMetrics().height() * 2);
}

void ReplaySlider::setEvents(const QList<ReplayEvent> &events, qint64 durationMs)
{
    m_events = events;
    m_duration = std::max<qint64>(0, durationMs);
    setRange(0, int(std::min<qint64>(m_duration, std::numeric_limits<int>::max())));
    update();
}

QRect ReplaySlider::groove() const
{
    QStyleOptionSlider opt;
    initStyleOption(&opt);
    const QRect handle =
        style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, this);
    // The handle's centre runs from half its width to the width less that.
    return QRect(handle.width() / 2, 0, width() - handle.width(), height());
}

int ReplaySlider::xOf(qint64 ms) const
{
    const QRect g = groove();
    if (maximum() <= 0)
        return g.left();
    return g.left() + int(double(std::clamp<qint64>(ms, 0, maximum())) * g.width() / maximum());
}

QStringList ReplaySlider::textsAt(int x) const
{
    QStringList out;
    for (const ReplayEvent &e : m_events) {
        if (std::abs(xOf(e.ms) - x) > kNear)
            continue;
        if (out.size() == kMaxTipLines) {
            out << QStringLiteral("…");
            break;
        }
        out << QStringLiteral("%1 s  %2")
                   .arg(double(e.ms) / 1000.0, 0, 'f', 3)
                   .arg(e.device > 0 ? QStringLiteral("id %1: %2").arg(e.device).arg(e.text)
                                     : e.text);
    }
    return out;
}

QColor ReplaySlider::colorOf(ReplayEvent::Kind kind)
{
    switch (kind) {
    case ReplayEvent::Kind::Write:
        return QColor(0x1f, 0x6f, 0xd1); // blue
    case ReplayEvent::Kind::Command:
        return QColor(0x2e, 0x8b, 0x57); // green
    case ReplayEvent::Kind::EmergencyStop:
        return QColor(0xd0, 0x10, 0x10); // red
    case ReplayEvent::Kind::Exception:
    case ReplayEvent::Kind::Timeout:
    case ReplayEvent::Kind::LateAnswer:
        return QColor(0xe0, 0x8a, 0x00); // orange
    case ReplayEvent::Kind::LinkUp:
    case ReplayEvent::Kind::LinkDown:
    case ReplayEvent::Kind::Restart:
    case ReplayEvent::Kind::PossibleRestart:
        return QColor(0x80, 0x40, 0xa0); // purple
    case ReplayEvent::Kind::User:
        break;
    }
    return QColor(0x60, 0x60, 0x60);
}

void ReplaySlider::paintEvent(QPaintEvent *event)
{
    QSlider::paintEvent(event);
    QPainter painter(this);
    const int top = height() * 2 / 3;
    // A line per pixel and kind, however many events fall there (a dead line: thousands).
    QSet<qint64> drawn;
    for (const ReplayEvent &e : m_events) {
        const int x = xOf(e.ms);
        const qint64 place = qint64(x) * 16 + int(e.kind);
        if (drawn.contains(place))
            continue;
        drawn.insert(place);
        // An E-STOP is drawn taller: it is what an engineer looks for first.
        const int from = e.kind == ReplayEvent::Kind::EmergencyStop ? height() / 3 : top;
        painter.setPen(QPen(colorOf(e.kind), 2));
        painter.drawLine(x, from, x, height() - 1);
    }
}

bool ReplaySlider::event(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        const QStringList texts = textsAt(help->pos().x());
        if (texts.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), texts.join(QLatin1Char('\n')), this);
        return true;
    }
    return QSlider::event(event);
}

} // namespace stepcom
