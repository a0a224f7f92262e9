#pragma once

#include "motion/ramprates.h"

namespace stepcom {

// The continuous trapezoid of a ramped move over `distance` (RampMover without its 1 ms ticks):
// up from the start rate, cruise at the top rate, down to the start rate on arrival; a triangle
// when the distance is too short to reach the top rate. Times in ms, rates as RampRates.
class Trapezoid
{
public:
    Trapezoid(double distance, const RampRates &rates);

    double rampMs() const { return m_rampMs; } // one way
    double cruiseMs() const { return m_cruiseMs; }
    double peakRate() const { return m_peak; }
    bool reachesTop() const { return m_reachesTop; }
    double durationMs() const { return 2 * m_rampMs + m_cruiseMs; }
    // How far the move has gone after `ms`, for 0 <= ms <= durationMs().
    double travelledAt(double ms) const;

private:
    double m_distance;
    double m_start;
    double m_accel;
    double m_peak;
    double m_rampMs;
    double m_cruiseMs = 0;
    bool m_reachesTop;
};

} // namespace stepcom
