#pragma once

#include "motion/motorderived.h"

namespace stepcom {

// One motor's parameters as the motion model uses them, read from the registers every tick
// (the speed may change while running). Distances are in the pitch's distance units.
struct AxisSettings
{
    double stepAngle = 1.8;   // degrees
    double microsteps = 8;    // driver DIP setting
    double startHz = 400;     // pulse rate a move starts (and ends) at
    double accelHzPerMs = 80; // pulse rate gained per millisecond of ramp
    int direction = 0;        // single-move direction: 0 forward, 1 reverse
    double rpm = 300;         // top speed
    double pitch = 5.0;       // distance units per revolution
    double distance = 10.0;   // single-move distance
    int limitPositive = 0;    // input 1-4 or 0
    int limitNegative = 0;
    int homeInput = 0;

    // The motion model's values, with a fallback where a register holds nonsense (a step angle of
    // 0 counts as one pulse per revolution, a pitch of 0 as one unit per revolution).
    double pulsesPerRev() const
    {
        return motorderived::pulsesPerRevolution(stepAngle, microsteps).value_or(1);
    }
    double stepsPerUnit() const
    {
        return motorderived::pulsesPerUnit(pulsesPerRev(), pitch).value_or(pulsesPerRev());
    }
    // Pulse rate (Hz) for a speed in revolutions per minute.
    double hzForRpm(double revsPerMinute) const
    {
        return motorderived::pulseRateHz(revsPerMinute, pulsesPerRev()).value_or(0);
    }
};

} // namespace stepcom
