#pragma once

#include "motion/ramprates.h"

#include <QtGlobal>

namespace stepcom {

// One-dimensional trapezoidal motion in 1 ms ticks: starts at the start rate at once (a stepper
// can), gains `accel` per ms up to the top rate, and brakes so it arrives at a target at the
// start rate. Units are the caller's (steps for an axis, distance units for an interpolation).
class RampMover
{
public:
    enum class Mode { Idle, Run, Target };

    // Values are taken live every tick so the speed can be changed while running.
    void setRates(const RampRates &rates);

    // Run without end in direction +1 or -1.
    void run(int direction);
    // Go to `target`, braking in time.
    void moveTo(double target);
    // Immediate stop (no ramp), as the controller's stop command and limits do.
    void stop();

    // One tick of `dt` ms; returns the distance moved (signed).
    double tick(double dt = 1.0);

    Mode mode() const { return m_mode; }
    bool isMoving() const { return m_mode != Mode::Idle; }
    double position() const { return m_pos; }
    void setPosition(double pos) { m_pos = pos; }
    double rate() const { return m_rate; }
    int direction() const { return m_dir; }
    double target() const { return m_target; }

private:
    double effectiveStart() const;

    Mode m_mode = Mode::Idle;
    double m_pos = 0;
    double m_rate = 0; // current speed, >= 0
    int m_dir = 1;
    double m_target = 0;
    double m_startRate = 0.4;
    double m_maxRate = 8.0;
    double m_accel = 0.08;
};

} // namespace stepcom
