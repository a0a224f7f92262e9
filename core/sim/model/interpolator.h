#pragma once

#include "motion/interpolationpath.h"
#include "motion/rampmover.h"

namespace stepcom {

class SimAxis;

// Runs an arc or line interpolation on motors 1 and 2: first each axis moves on its own to the
// start point (as the manual says), then both follow the path together at the interpolation
// speed, which is latched at the start (the manual: not adjustable during the move).
class Interpolator
{
public:
    enum class Phase { Idle, Approach, Path };
    enum class Kind { Arc, Line };

    // `speedRpm` is the path speed as motor 1 revolutions per minute along the path.
    void start(Kind kind, const InterpolationPath &path, double speedRpm, SimAxis &x, SimAxis &y);
    // Stops both axes at once.
    void stop(SimAxis &x, SimAxis &y);
    // After the axes' own tick; advances the approach or the path by one millisecond.
    void tick(SimAxis &x, SimAxis &y);

    Phase phase() const { return m_phase; }
    Kind kind() const { return m_kind; }
    bool isActive() const { return m_phase != Phase::Idle; }
    const InterpolationPath &path() const { return m_path; }

private:
    void beginPath(SimAxis &x, SimAxis &y);

    Phase m_phase = Phase::Idle;
    Kind m_kind = Kind::Line;
    InterpolationPath m_path;
    RampMover m_mover; // arc length along the path, distance units
    double m_speedRpm = 60;
    double m_startX = 0; // approach targets in steps
    double m_startY = 0;
    // The path point of the last tick before rounding to pulses: each axis's pulse rate.
    InterpolationPath::Point m_last{};
};

} // namespace stepcom
