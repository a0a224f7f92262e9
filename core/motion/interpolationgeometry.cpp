#include "motion/interpolationgeometry.h"

#include "map/registermap.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stepcom::interpolation {

namespace {

// Two points closer than half a register count are the same point for the controller.
constexpr double kSamePoint = 0.005;

double distance(Point a, Point b)
{
    return std::hypot(b.x - a.x, b.y - a.y);
}

bool same(Point a, Point b)
{
    return distance(a, b) < kSamePoint;
}

QString number(double v)
{
    return QString::number(v, 'f', 2);
}

QString pointText(Point p)
{
    return QStringLiteral("(%1, %2)").arg(number(p.x), number(p.y));
}

void fillArc(Geometry &g, const InterpolationPath &path)
{
    g.path = path;
    g.sweepDegrees = path.sweep() * 180.0 / std::numbers::pi;
    g.length = path.length();
}

// Does the arc swept from `path`'s start pass the point `p` (seen from the centre)?
bool sweepContains(const InterpolationPath &path, Point p)
{
    const Point c = path.centre();
    const double startAngle = std::atan2(path.start().y - c.y, path.start().x - c.x);
    const double angle = std::atan2(p.y - c.y, p.x - c.x);
    constexpr double twoPi = 2 * std::numbers::pi;
    double along = std::fmod(angle - startAngle, twoPi); // counter-clockwise from the start
    if (along < 0)
        along += twoPi;
    if (path.sweep() < 0)
        along = along == 0 ? 0 : twoPi - along;
    return along <= std::abs(path.sweep()) + 1e-9;
}

bool positive(const std::optional<double> &v)
{
    return v && std::isfinite(*v) && *v > 0;
}

struct AxisRates
{
    double stepsPerUnit = 0;
    double start = 0; // pulses per ms
    double top = 0;
    double accel = 0; // pulses per ms per ms
};

std::optional<AxisRates> ratesOf(const MotorParameters &m, double rpm)
{
    const std::optional<double> ppr =
        m.stepAngle && m.microsteps ? motorderived::pulsesPerRevolution(*m.stepAngle, *m.microsteps)
                                    : std::nullopt;
    if (!ppr || !positive(m.pitch) || !positive(m.startHz) || !positive(m.accelHzPerMs) ||
        !(rpm > 0))
        return std::nullopt;
    AxisRates r;
    r.stepsPerUnit = *ppr / *m.pitch;
    r.top = rpm * *ppr / 60.0 / 1000.0;
    r.start = std::min(*m.startHz / 1000.0, r.top);
    r.accel = *m.accelHzPerMs / 1000.0;
    return r;
}

// How far (pulses) a move of `total` pulses has gone after `t` ms: the continuous trapezoid of
// RampMover (start at the start rate, gain accel per ms, brake to arrive at the start rate).
double travelledAt(double total, const AxisRates &r, double t)
{
    const double rampDistance = (r.top * r.top - r.start * r.start) / (2 * r.accel);
    double peak = r.top;
    double rampMs = (r.top - r.start) / r.accel;
    double cruiseMs = 0;
    if (2 * rampDistance > total) {
        peak = std::sqrt(r.start * r.start + r.accel * total);
        rampMs = (peak - r.start) / r.accel;
    } else {
        cruiseMs = (total - 2 * rampDistance) / r.top;
    }
    const double up = r.start * rampMs + r.accel * rampMs * rampMs / 2;
    if (t <= rampMs)
        return std::min(total, r.start * t + r.accel * t * t / 2);
    if (t <= rampMs + cruiseMs)
        return std::min(total, up + peak * (t - rampMs));
    const double d = t - rampMs - cruiseMs;
    return std::min(total, up + peak * cruiseMs + peak * d - r.accel * d * d / 2);
}

} // namespace

Geometry arc(const ArcInput &in)
{
    Geometry g;
    g.arc = true;
    g.start = in.start;
    g.end = in.end;
    if (in.mode == ArcMode::ThreePoints) {
        g.middle = in.middle;
        if (same(in.start, in.end)) {
            g.error = QCoreApplication::translate(
                "stepcom::InterpolationGeometry",
                "Start and end are the same point: three points cannot describe a full "
                "circle. Use the centre mode for a full circle.");
            return g;
        }
        if (same(in.middle, in.start) || same(in.middle, in.end)) {
            g.error = QCoreApplication::translate(
                          "stepcom::InterpolationGeometry",
                          "The middle point %1 is the same as the start or the end point: three "
                          "distinct points are needed.")
                          .arg(pointText(in.middle));
            return g;
        }
        const std::optional<Point> c = InterpolationPath::circleCentre(in.start, in.middle, in.end);
        if (!c) {
            g.error = QCoreApplication::translate(
                "stepcom::InterpolationGeometry",
                "Start, middle and end are on one straight line: no circle passes "
                "through them. Use the line editor for a straight move.");
            return g;
        }
        g.centre = *c;
    } else {
        g.centre = in.centre;
    }
    const Point c = *g.centre;
    g.startRadius = distance(in.start, c);
    g.endRadius = distance(in.end, c);
    g.radiusDifference = std::abs(g.endRadius - g.startRadius);
    if (g.startRadius < kSamePoint) {
        g.error = QCoreApplication::translate("stepcom::InterpolationGeometry",
                                              "The start point is the centre: the radius is zero.");
        return g;
    }
    if (g.endRadius < kSamePoint) {
        g.error = QCoreApplication::translate("stepcom::InterpolationGeometry",
                                              "The end point is the centre: the radius is zero.");
        return g;
    }
    if (g.radiusDifference > kRadiusTolerance + 1e-9) {
        g.error = QCoreApplication::translate(
                      "stepcom::InterpolationGeometry",
                      "Start and end are not the same distance from the centre: start radius %1, "
                      "end radius %2, difference %3 (at most %4 allowed).")
                      .arg(number(g.startRadius), number(g.endRadius), number(g.radiusDifference),
                           number(kRadiusTolerance));
        return g;
    }
    const std::optional<InterpolationPath> path =
        InterpolationPath::arcAroundCentre(in.start, in.end, c, in.counterClockwise);
    if (!path) {
        g.error = QCoreApplication::translate("stepcom::InterpolationGeometry",
                                              "The start point is the centre: the radius is zero.");
        return g;
    }
    fillArc(g, *path);
    g.fullCircle = same(in.start, in.end);
    if (g.fullCircle)
        g.notes << QCoreApplication::translate(
            "stepcom::InterpolationGeometry",
            "Start and end are the same point: this is a full circle.");
    if (in.mode == ArcMode::ThreePoints && !sweepContains(*path, in.middle))
        g.notes << QCoreApplication::translate(
            "stepcom::InterpolationGeometry",
            "The arc in the chosen direction does not pass through the middle point: "
            "the controller goes the other way round the circle. Change the direction "
            "to pass through it.");
    g.valid = true;
    return g;
}

Geometry line(Point start, Point end)
{
    Geometry g;
    g.start = start;
    g.end = end;
    if (same(start, end)) {
        g.error = QCoreApplication::translate(
                      "stepcom::InterpolationGeometry",
                      "Start and end are the same point %1: the line has no length.")
                      .arg(pointText(start));
        return g;
    }
    g.path = InterpolationPath::line(start, end);
    g.length = g.path->length();
    g.valid = true;
    return g;
}

std::optional<double> pathUnitsPerSecond(double speedRpm, const MotorParameters &motor1)
{
    if (!motor1.pitch)
        return std::nullopt;
    return motorderived::unitsPerSecond(speedRpm, *motor1.pitch);
}

std::optional<double> pathTimeMs(double length, double speedRpm, const MotorParameters &motor1)
{
    const std::optional<AxisRates> r = ratesOf(motor1, speedRpm);
    if (!r || !(length > 0))
        return std::nullopt;
    const auto pulses = qint64(std::llround(length * r->stepsPerUnit));
    if (pulses == 0)
        return 0.0;
    return motorderived::moveTimeMs(pulses, *motor1.startHz, *motor1.accelHzPerMs, r->top * 1000.0);
}

Approach approach(Point from, Point to, const MotorParameters &motor1,
                  const MotorParameters &motor2)
{
    Approach a;
    a.points << from;
    const double dx = to.x - from.x;
    const double dy = to.y - from.y;
    if (std::abs(dx) < kSamePoint && std::abs(dy) < kSamePoint)
        return a; // already there: no approach
    const std::optional<AxisRates> rx = ratesOf(motor1, motor1.rpm.value_or(0));
    const std::optional<AxisRates> ry = ratesOf(motor2, motor2.rpm.value_or(0));
    a.exact = rx && ry;
    double tx = std::abs(dx);
    double ty = std::abs(dy);
    double px = 0; // pulses of each axis's move
    double py = 0;
    if (a.exact) {
        px = std::round(std::abs(dx) * rx->stepsPerUnit);
        py = std::round(std::abs(dy) * ry->stepsPerUnit);
        auto timeOf = [](double pulses, const MotorParameters &m, const AxisRates &r) {
            return pulses < 1 ? 0.0
                              : motorderived::moveTimeMs(qint64(pulses), *m.startHz,
                                                         *m.accelHzPerMs, r.top * 1000.0)
                                    .value_or(0.0);
        };
        tx = timeOf(px, motor1, *rx);
        ty = timeOf(py, motor2, *ry);
        a.timeMs = std::max(tx, ty);
    }
    if (std::abs(dx) >= kSamePoint && std::abs(dy) >= kSamePoint && std::abs(tx - ty) > 1e-6) {
        Point corner;
        if (tx < ty) { // x arrives first; where is y then?
            const double done = a.exact ? travelledAt(py, *ry, tx) / ry->stepsPerUnit : tx;
            corner = {to.x, from.y + std::copysign(std::min(done, std::abs(dy)), dy)};
        } else {
            const double done = a.exact ? travelledAt(px, *rx, ty) / rx->stepsPerUnit : ty;
            corner = {from.x + std::copysign(std::min(done, std::abs(dx)), dx), to.y};
        }
        a.points << corner;
    }
    a.points << to;
    return a;
}

MotorParameters motorParameters(const RegisterMap &map, int motor,
                                const std::function<std::optional<qint64>(const QString &)> &raw)
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

} // namespace stepcom::interpolation
