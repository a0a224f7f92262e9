#include "motion/interpolationtiming.h"

#include "motion/trapezoid.h"

#include <algorithm>
#include <cmath>

namespace stepcom::interpolation {

namespace {

bool positive(const std::optional<double> &v)
{
    return v && std::isfinite(*v) && *v > 0;
}

// A motor's pulses per distance unit and its ramp in pulses per ms, at `rpm`.
struct AxisRates
{
    double stepsPerUnit = 0;
    RampRates ramp;
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
    r.ramp = RampRates::fromHz(*m.startHz, rpm * *ppr / 60.0, *m.accelHzPerMs);
    return r;
}

std::optional<double> stepsPerUnit(const MotorParameters &m)
{
    if (!m.stepAngle || !m.microsteps || !m.pitch)
        return std::nullopt;
    const std::optional<double> ppr =
        motorderived::pulsesPerRevolution(*m.stepAngle, *m.microsteps);
    return ppr ? motorderived::pulsesPerUnit(*ppr, *m.pitch) : std::nullopt;
}

} // namespace

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
    return motorderived::moveTimeMs(pulses, *motor1.startHz, *motor1.accelHzPerMs,
                                    r->ramp.top * 1000.0);
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
                                                         *m.accelHzPerMs, r.ramp.top * 1000.0)
                                    .value_or(0.0);
        };
        tx = timeOf(px, motor1, *rx);
        ty = timeOf(py, motor2, *ry);
        a.timeMs = std::max(tx, ty);
    }
    if (std::abs(dx) >= kSamePoint && std::abs(dy) >= kSamePoint && std::abs(tx - ty) > 1e-6) {
        Point corner;
        if (tx < ty) { // x arrives first; where is y then?
            const double done =
                a.exact ? Trapezoid(py, ry->ramp).travelledAt(tx) / ry->stepsPerUnit : tx;
            corner = {to.x, from.y + std::copysign(std::min(done, std::abs(dy)), dy)};
        } else {
            const double done =
                a.exact ? Trapezoid(px, rx->ramp).travelledAt(ty) / rx->stepsPerUnit : ty;
            corner = {from.x + std::copysign(std::min(done, std::abs(dx)), dx), to.y};
        }
        a.points << corner;
    }
    a.points << to;
    return a;
}

std::optional<PathTargets> pathTargets(Point start, Point end, const MotorParameters &motor1,
                                       const MotorParameters &motor2)
{
    const std::optional<double> sx = stepsPerUnit(motor1);
    const std::optional<double> sy = stepsPerUnit(motor2);
    if (!sx || !sy)
        return std::nullopt;
    auto counts = [&](Point p) {
        return Counts{motorderived::positionCounts(motorderived::wholePulses(p.x, *sx), *sx),
                      motorderived::positionCounts(motorderived::wholePulses(p.y, *sy), *sy)};
    };
    return PathTargets{counts(start), counts(end)};
}

} // namespace stepcom::interpolation
