#pragma once

#include "motion/motionoutcome.h"

namespace stepcom {

class RegisterMap;

// Follows one acknowledged motion command through status samples until every axis it moves is
// idle, and remembers what may have cut it short (a stop or E-STOP that went out, a lost link).
// A sample may hold the running flags from before the command took effect, so the first
// `skipSamples` samples never end it, and the end needs two idle samples in a row (a homing
// sequence may pause between two motors).
class MotionWatch
{
public:
    MotionWatch(const RegisterMap &map, MotionStart start, int skipSamples = 1);

    const MotionStart &start() const { return m_start; }
    // Keeps the strongest cause seen: link loss and E-STOP outrank a stop.
    void interrupt(MotionCause cause);
    MotionCause cause() const { return m_cause; }
    // A status sample read after the command was acknowledged (values merge into the last
    // ones). Returns true once the motion is over.
    bool sample(const StatusValues &values);
    bool isOver() const { return m_over; }
    // Motors of this motion the last sample saw running.
    QList<int> running() const;
    const StatusValues &last() const { return m_last; }

private:
    QList<QString> m_runningKeys; // per moved motor
    MotionStart m_start;
    MotionCause m_cause = MotionCause::None;
    StatusValues m_last;
    int m_skip;
    int m_idle = 0;
    bool m_over = false;
};

} // namespace stepcom
