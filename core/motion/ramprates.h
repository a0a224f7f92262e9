#pragma once

#include <algorithm>

namespace stepcom {

// The rates of a ramped move in units per millisecond (pulses for a motor, distance units along
// an interpolation path): the motor starts at `start` at once (a stepper can), gains `accel`
// each millisecond up to `top`, and brakes to arrive at `start` again.
struct RampRates
{
    double start = 0;
    double top = 0;
    double accel = 0; // units per ms gained each ms

    // From the registers' units: pulses per second and pulses per second gained each ms.
    static RampRates fromHz(double startHz, double topHz, double accelHzPerMs)
    {
        return {startHz / 1000.0, topHz / 1000.0, accelHzPerMs / 1000.0};
    }
    // The same move in other units (pulses to distance units: × units per pulse).
    RampRates scaled(double factor) const { return {start * factor, top * factor, accel * factor}; }
    // A start rate above the top rate means no ramp at all: the move starts at the top rate.
    double effectiveStart() const { return std::min(start, top); }
};

} // namespace stepcom
