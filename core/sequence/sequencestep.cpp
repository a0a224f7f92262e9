#include "sequence/sequencestep.h"

#include <QStringList>

namespace stepcom {

namespace {

QString axesText(const QMap<int, double> &axes, int decimals)
{
    QStringList parts;
    for (auto it = axes.begin(); it != axes.end(); ++it)
        parts << QStringLiteral("motor%1 %2").arg(it.key()).arg(it.value(), 0, 'f', decimals);
    return parts.join(QLatin1String(", "));
}

} // namespace

QString SequenceStep::kindWord(Kind kind)
{
    switch (kind) {
    case Kind::Home:
        return QStringLiteral("home");
    case Kind::MoveTo:
        return QStringLiteral("move_to");
    case Kind::MoveBy:
        return QStringLiteral("move_by");
    case Kind::WaitInput:
        return QStringLiteral("wait_input");
    case Kind::Output:
        return QStringLiteral("output");
    case Kind::Outputs:
        return QStringLiteral("outputs");
    case Kind::Dwell:
        return QStringLiteral("dwell_ms");
    case Kind::Repeat:
        return QStringLiteral("repeat");
    case Kind::Speed:
        return QStringLiteral("speed");
    }
    return {};
}

QString SequenceStep::describe() const
{
    switch (kind) {
    case Kind::Home: {
        if (homeInOrder)
            return tr("home in the set order");
        QStringList motors;
        for (int m : homeMotors)
            motors << QStringLiteral("motor%1").arg(m);
        return tr("home %1").arg(motors.join(QLatin1String(", ")));
    }
    case Kind::MoveTo:
        return point.isEmpty() ? tr("move to %1").arg(axesText(axes, 2))
                               : tr("move to %1 (%2)").arg(point, axesText(axes, 2));
    case Kind::MoveBy:
        return tr("move by %1").arg(axesText(axes, 2));
    case Kind::WaitInput:
        if (timeoutMs > 0)
            return (on ? tr("wait for IN%1 ON (at most %2 s)")
                       : tr("wait for IN%1 OFF (at most %2 s)"))
                .arg(number)
                .arg(timeoutMs / 1000.0, 0, 'g', 6);
        return (on ? tr("wait for IN%1 ON") : tr("wait for IN%1 OFF")).arg(number);
    case Kind::Output:
        return (on ? tr("output %1 ON") : tr("output %1 OFF")).arg(number);
    case Kind::Outputs:
        return on ? tr("all outputs ON") : tr("all outputs OFF");
    case Kind::Dwell:
        return tr("dwell %1 ms").arg(dwellMs);
    case Kind::Repeat:
        return tr("repeat %n time(s)", nullptr, count);
    case Kind::Speed:
        return tr("speed %1 rpm").arg(axesText(axes, 0));
    }
    return {};
}

} // namespace stepcom
