#pragma once

#include <limits>
#include <optional>

namespace stepcom {

// The mechanics of one simulated axis that no register shows: the motor's torque limits (motor
// units, independent of microstepping), the play in the drive, where the switches and hard stops
// are and which input each switch is wired to. Distances in mm of the carriage's frame: 0 is the
// nominal place of the negative (home) switch. The member defaults are a machine file's defaults.
struct AxisPhysics
{
    static constexpr double kNoLimit = std::numeric_limits<double>::infinity();

    // Which input (1-4, 0 none) each switch drives; the home switch sits at the negative switch.
    struct Wiring
    {
        int negative = 0;
        int positive = 0;
        int home = 0;
    };

    double pullOutRpm = kNoLimit;        // above this rotor speed it loses sync
    double pullInRpm = kNoLimit;         // highest speed it can start at, and relock at
    double accelLimitRpmPerS = kNoLimit; // a faster change of speed loses sync
    double backlashMm = 0;               // dead band between the rotor and the carriage
    std::optional<double> travelMm;      // unset: SimOptions::travel
    std::optional<double> startMm;       // carriage at power-up; unset: where it stands
    double negativeSwitchMm = 0;
    std::optional<double> positiveSwitchMm; // unset: the travel
    double switchJitterMm = 0.002;          // trip point spread, uniform ± half of it
    double switchHysteresisMm = 0;          // released this far past the trip point
    double hardStopMm = 5;                  // past each switch
    std::optional<Wiring> wiring;           // unset: the inputs the registers name

    // The machine without a machine file: exact switches, nothing stalls, no play.
    static AxisPhysics ideal()
    {
        AxisPhysics p;
        p.switchJitterMm = 0;
        return p;
    }
};

} // namespace stepcom
