#pragma once

#include <QtGlobal>

#include <optional>

namespace stepcom {

// One motor's parameters in engineering units (degrees, Hz, Hz gained per ms, rpm, distance
// units); nullopt while a value is not known.
struct MotorParameters
{
    std::optional<double> stepAngle;
    std::optional<double> microsteps;
    std::optional<double> startHz;
    std::optional<double> accelHzPerMs;
    std::optional<double> rpm;
    std::optional<double> pitch;
    std::optional<double> distance;
};

// What a technician works out by hand from a motor's parameters. Each value is nullopt when
// an input it needs is unknown or zero (the page shows "—" then).
struct MotorDerived
{
    std::optional<double> pulsesPerRev;
    std::optional<double> pulseRateHz;
    std::optional<double> unitsPerSecond;
    std::optional<double> unitsPerMinute;
    std::optional<double> revolutionsPerMove;
    std::optional<qint64> pulsesPerMove;
    std::optional<double> rampMs; // start frequency up to the set speed, one way
    std::optional<double> moveTimeMs;
};

// Pure functions of the motion model the simulator runs (docs/simulator.md, "The motion model").
namespace motorderived {

// 360 / step angle × microsteps (1.8°, 8 → 1600).
std::optional<double> pulsesPerRevolution(double stepAngle, double microsteps);
// rpm × pulses per revolution / 60 (300 rpm at 1600 → 8000 Hz).
std::optional<double> pulseRateHz(double rpm, double pulsesPerRev);
// rpm × pitch / 60 (300 rpm on a 5 mm pitch → 25 mm/s).
std::optional<double> unitsPerSecond(double rpm, double pitch);
// pulses per revolution / pitch (1600 on a 5 mm pitch → 320 pulses per mm).
std::optional<double> pulsesPerUnit(double pulsesPerRev, double pitch);
// The controller sends whole pulses: the pulse count nearest to `units` (10.01 mm at 320 → 3203).
double wholePulses(double units, double pulsesPerUnit);
// The position register (distance units × 100) for a pulse count (3203 at 320 → 1001).
qint64 positionCounts(double pulses, double pulsesPerUnit);
// distance / pitch (10 mm on 5 mm → 2).
std::optional<double> revolutionsPerMove(double distance, double pitch);
// The whole pulses a single move sends, as the controller rounds them (10 mm / 5 mm × 1600 → 3200).
std::optional<qint64> pulsesPerMove(double distance, double pitch, double pulsesPerRev);
// Ramp from the start frequency to the top rate at accel Hz per ms; 0 when the start
// frequency is at or above the top rate (no ramp).
std::optional<double> rampTimeMs(double startHz, double accelHzPerMs, double topHz);
// Milliseconds a single move of `pulses` takes: trapezoid in 1 ms ticks exactly as the
// simulator runs it (start at the start rate, accel Hz gained per ms, brake to the start rate).
std::optional<double> moveTimeMs(qint64 pulses, double startHz, double accelHzPerMs, double topHz);

MotorDerived derive(const MotorParameters &parameters);

} // namespace motorderived

} // namespace stepcom
