#include "motion/pathsetup.h"

#include "map/registermap.h"

namespace stepcom::interpolation {

namespace {

// Distance units of a coordinate or speed register; 0 when the map or the values lack it.
double units(const RegisterMap &map, const RawValue &raw, const QString &key)
{
    const Parameter *p = map.find(key);
    return p ? p->toEngineering(raw(key).value_or(0)) : 0.0;
}

Point point(const RegisterMap &map, const RawValue &raw, const QString &prefix, const char *name)
{
    const QString base = prefix + QLatin1String(name);
    return {units(map, raw, base + QStringLiteral("_x")),
            units(map, raw, base + QStringLiteral("_y"))};
}

bool isOne(const RawValue &raw, const QString &key)
{
    return raw(key).value_or(0) == 1;
}

} // namespace

ArcSetup arcSetup(const RegisterMap &map, const RawValue &raw)
{
    const QString prefix = QStringLiteral("arc.");
    ArcSetup a;
    a.enabled = isOne(raw, prefix + QStringLiteral("enabled"));
    a.mode = isOne(raw, prefix + QStringLiteral("mode")) ? ArcMode::ThreePoints : ArcMode::Centre;
    a.start = point(map, raw, prefix, "start");
    a.end = point(map, raw, prefix, "end");
    a.centre = point(map, raw, prefix, "center");
    a.middle = point(map, raw, prefix, "middle");
    a.counterClockwise = isOne(raw, prefix + QStringLiteral("direction"));
    a.speedRpm = units(map, raw, prefix + QStringLiteral("speed"));
    return a;
}

LineSetup lineSetup(const RegisterMap &map, const RawValue &raw)
{
    const QString prefix = QStringLiteral("line.");
    LineSetup l;
    l.enabled = isOne(raw, prefix + QStringLiteral("enabled"));
    l.start = point(map, raw, prefix, "start");
    l.end = point(map, raw, prefix, "end");
    l.speedRpm = units(map, raw, prefix + QStringLiteral("speed"));
    return l;
}

MotorParameters motorParameters(const RegisterMap &map, int motor, const RawValue &raw)
{
    auto value = [&](const char *local) -> std::optional<double> {
        const Parameter *p =
            map.blockParameter(QStringLiteral("motor"), motor, QLatin1String(local));
        if (!p)
            return std::nullopt;
        const std::optional<qint64> r = raw(p->key);
        if (!r)
            return std::nullopt;
        return p->toEngineering(*r);
    };
    MotorParameters m;
    m.stepAngle = value("step_angle");
    m.microsteps = value("microsteps");
    m.startHz = value("start_frequency");
    m.accelHzPerMs = value("accel_frequency");
    m.rpm = value("speed");
    m.pitch = value("pitch");
    m.distance = value("move_distance");
    return m;
}

std::optional<Point> arcCentre(const ArcSetup &arc)
{
    if (arc.mode == ArcMode::ThreePoints)
        return InterpolationPath::circleCentre(arc.start, arc.middle, arc.end);
    return arc.centre;
}

ArcPath arcPath(const ArcSetup &arc)
{
    ArcPath result;
    const std::optional<Point> centre = arcCentre(arc);
    if (!centre) {
        result.problem = ArcProblem::PointsOnALine;
        return result;
    }
    result.path =
        InterpolationPath::arcAroundCentre(arc.start, arc.end, *centre, arc.counterClockwise);
    if (!result.path)
        result.problem = ArcProblem::OnTheCentre;
    return result;
}

InterpolationPath linePath(const LineSetup &line)
{
    return InterpolationPath::line(line.start, line.end);
}

} // namespace stepcom::interpolation
