#include "sim/model/specialmodes.h"

namespace stepcom {

void SpecialModes::reset()
{
    m_trip = Trip::Idle;
    m_trips = 0;
    m_lastDirection = 1;
    m_nextDirection = 1;
}

bool SpecialModes::rose(int input) const
{
    const int i = input - 1;
    return i < m_current.size() && m_current.at(i) && !(i < m_previous.size() && m_previous.at(i));
}

bool SpecialModes::level(int input) const
{
    const int i = input - 1;
    return i < m_current.size() && m_current.at(i);
}

void SpecialModes::evaluate(int mode, const QList<bool> &inputs, int roundTrips, Axis &axis)
{
    m_current = inputs;
    switch (mode) {
    case 1:
        roundTrip(roundTrips, axis);
        break;
    case 2:
        singleTrigger(axis);
        break;
    case 3:
        forwardReverseTrigger(axis);
        break;
    case 4:
        holdToJog(axis);
        break;
    case 5:
        fixedDistance(axis);
        break;
    default:
        break;
    }
    m_previous = m_current;
}

void SpecialModes::roundTrip(int roundTrips, Axis &axis)
{
    // IN1 positive limit, IN2 negative limit, IN3 emergency stop, IN4 start.
    if (rose(3)) {
        axis.stop();
        m_trip = Trip::Idle;
        return;
    }
    if (m_trip != Trip::Idle && !(axis.isRunning() && axis.startedByMode()))
        m_trip = Trip::Idle; // stopped by a command
    if (rose(4) && m_trip == Trip::Idle) {
        m_trips = 0;
        m_trip = Trip::Forward;
        axis.run(1);
    }
    if (m_trip == Trip::Forward && level(1)) {
        m_trip = Trip::Reverse;
        axis.run(-1);
    } else if (m_trip == Trip::Reverse && level(2)) {
        ++m_trips; // forward to the positive limit and back is one round trip
        if (roundTrips > 0 && m_trips >= roundTrips) {
            axis.stop();
            m_trip = Trip::Idle;
        } else {
            m_trip = Trip::Forward;
            axis.run(1);
        }
    }
}

void SpecialModes::singleTrigger(Axis &axis)
{
    // IN1 start; IN2/IN3/IN4 stop and choose the next start's direction.
    if (rose(2)) {
        axis.stop();
        m_nextDirection = m_lastDirection;
    }
    if (rose(3)) {
        axis.stop();
        m_nextDirection = -m_lastDirection;
    }
    if (rose(4)) {
        axis.stop();
        m_nextDirection = 1;
    }
    if (rose(1) && !axis.isRunning()) {
        m_lastDirection = m_nextDirection;
        axis.run(m_nextDirection);
    }
}

void SpecialModes::forwardReverseTrigger(Axis &axis)
{
    // IN1 forward, IN2 reverse; IN3/IN4 limits (the machine stops a run into them).
    if (rose(1) && !axis.limitActive(1))
        axis.run(1);
    else if (rose(2) && !axis.limitActive(-1))
        axis.run(-1);
}

void SpecialModes::holdToJog(Axis &axis)
{
    const bool forward = level(1) && !level(2);
    const bool reverse = level(2) && !level(1);
    const int wanted = forward ? 1 : (reverse ? -1 : 0);
    if (wanted == 0) {
        if (axis.isRunning() && axis.startedByMode())
            axis.stop(); // released
        return;
    }
    if (axis.limitActive(wanted)) {
        if (axis.isRunning() && axis.startedByMode() && axis.runDirection() == wanted)
            axis.stop();
        return;
    }
    if (!(axis.isRunning() && axis.startedByMode() && axis.runDirection() == wanted))
        axis.run(wanted);
}

void SpecialModes::fixedDistance(Axis &axis)
{
    if (axis.isRunning())
        return; // a trigger during a move is ignored
    if (rose(1) && !axis.limitActive(1))
        axis.moveBy(1);
    else if (rose(2) && !axis.limitActive(-1))
        axis.moveBy(-1);
}

} // namespace stepcom
