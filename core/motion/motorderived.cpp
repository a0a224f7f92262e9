#include "motion/motorderived.h"

#include "motion/rampmover.h"
#include "motion/trapezoid.h"

#include <algorithm>
#include <cmath>

namespace stepcom::motorderived {

namespace {

bool positive(double v)
{
    return std::isfinite(v) && v > 0;
}

std::optional<double> nonZero(double v)
{
    if (!std::isfinite(v) || v == 0)
        return std::nullopt;
    return v;
}

// More ticks than this (a ramp of minutes) are estimated from the continuous trapezoid instead.
constexpr qint64 kMaxSimulatedTicks = 2'000'000;

} // namespace

std::optional<double> pulsesPerRevolution(double stepAngle, double microsteps)
{
    if (!positive(stepAngle) || !positive(microsteps))
        return std::nullopt;
    return nonZero(360.0 / stepAngle * microsteps);
}

std::optional<double> pulseRateHz(double rpm, double pulsesPerRev)
{
    if (!positive(rpm) || !positive(pulsesPerRev))
        return std::nullopt;
    return nonZero(rpm * pulsesPerRev / 60.0);
}

std::optional<double> unitsPerSecond(double rpm, double pitch)
{
    if (!positive(rpm) || !positive(pitch))
        return std::nullopt;
    return nonZero(rpm * pitch / 60.0);
}

std::optional<double> pulsesPerUnit(double pulsesPerRev, double pitch)
{
    if (!positive(pulsesPerRev) || !positive(pitch))
        return std::nullopt;
    return nonZero(pulsesPerRev / pitch);
}

double wholePulses(double units, double pulsesPerUnit)
{
    return std::round(units * pulsesPerUnit);
}

qint64 positionCounts(double pulses, double pulsesPerUnit)
{
    return qint64(std::llround(pulses / pulsesPerUnit * 100.0));
}

std::optional<double> revolutionsPerMove(double distance, double pitch)
{
    if (!positive(pitch))
        return std::nullopt;
    return nonZero(std::abs(distance) / pitch);
}

std::optional<qint64> pulsesPerMove(double distance, double pitch, double pulsesPerRev)
{
    if (!positive(pitch) || !positive(pulsesPerRev) || !std::isfinite(distance))
        return std::nullopt;
    // The simulator's single move: round(distance × pulses per distance unit).
    const auto pulses = qint64(wholePulses(std::abs(distance), pulsesPerRev / pitch));
    if (pulses == 0)
        return std::nullopt;
    return pulses;
}

std::optional<double> rampTimeMs(double startHz, double accelHzPerMs, double topHz)
{
    if (!positive(startHz) || !positive(accelHzPerMs) || !positive(topHz))
        return std::nullopt;
    return std::max(0.0, (topHz - startHz) / accelHzPerMs);
}

std::optional<double> moveTimeMs(qint64 pulses, double startHz, double accelHzPerMs, double topHz)
{
    if (pulses == 0 || !positive(startHz) || !positive(accelHzPerMs) || !positive(topHz))
        return std::nullopt;
    // The simulator's units: pulses per ms and pulses per ms gained each ms.
    const RampRates rates = RampRates::fromHz(startHz, topHz, accelHzPerMs);
    const double top = rates.top;
    const double accel = rates.accel;
    const double distance = double(std::abs(pulses));
    const double from = rates.effectiveStart();
    if ((top - from) / accel > double(kMaxSimulatedTicks) / 4 || distance / from > 1e12)
        return Trapezoid(distance, rates).durationMs();

    RampMover mover;
    mover.setRates(rates);
    mover.moveTo(distance);
    qint64 ticks = 0;
    qint64 loops = 0;
    const double brake = (top * top - from * from) / (2 * accel);
    while (mover.isMoving()) {
        if (mover.rate() >= top) {
            // Cruising: jump the whole ticks that cannot reach the braking point, one by one
            // would take seconds on a long move. One tick of margin keeps the brake exact.
            const double remaining = mover.target() - mover.position();
            const double skip = std::floor((remaining - brake - top) / top) - 1;
            if (skip >= 1) {
                mover.setPosition(mover.position() + skip * top);
                ticks += qint64(skip);
            }
        }
        mover.tick();
        ++ticks;
        if (++loops > kMaxSimulatedTicks)
            return Trapezoid(distance, rates).durationMs();
    }
    return double(ticks);
}

MotorDerived derive(const MotorParameters &p)
{
    MotorDerived d;
    if (p.stepAngle && p.microsteps)
        d.pulsesPerRev = pulsesPerRevolution(*p.stepAngle, *p.microsteps);
    if (p.rpm && d.pulsesPerRev)
        d.pulseRateHz = pulseRateHz(*p.rpm, *d.pulsesPerRev);
    if (p.rpm && p.pitch) {
        d.unitsPerSecond = unitsPerSecond(*p.rpm, *p.pitch);
        if (d.unitsPerSecond)
            d.unitsPerMinute = *d.unitsPerSecond * 60.0;
    }
    if (p.distance && p.pitch)
        d.revolutionsPerMove = revolutionsPerMove(*p.distance, *p.pitch);
    if (p.distance && p.pitch && d.pulsesPerRev)
        d.pulsesPerMove = pulsesPerMove(*p.distance, *p.pitch, *d.pulsesPerRev);
    if (p.startHz && p.accelHzPerMs && d.pulseRateHz)
        d.rampMs = rampTimeMs(*p.startHz, *p.accelHzPerMs, *d.pulseRateHz);
    if (d.pulsesPerMove && p.startHz && p.accelHzPerMs && d.pulseRateHz)
        d.moveTimeMs = moveTimeMs(*d.pulsesPerMove, *p.startHz, *p.accelHzPerMs, *d.pulseRateHz);
    return d;
}

} // namespace stepcom::motorderived
