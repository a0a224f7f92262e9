#include "sim/model/simaxis.h"

#include <algorithm>
#include <cmath>

namespace stepcom {

void SimAxis::configure(const AxisSettings &settings)
{
    m_settings = settings;
    applyRates();
}

void SimAxis::applyRates()
{
    // The mover works in steps and milliseconds.
    m_mover.setRates(RampRates::fromHz(m_settings.startHz, m_settings.hzForRpm(m_settings.rpm),
                                       m_settings.accelHzPerMs));
}

void SimAxis::setTravel(double travel, double overtravel)
{
    m_travel = travel;
    m_overtravel = overtravel;
}

void SimAxis::startMove(double targetSteps, Owner owner)
{
    m_owner = owner;
    m_mover.moveTo(targetSteps);
    m_activity = m_mover.isMoving() ? Activity::Move : Activity::Idle;
}

void SimAxis::startJog(int direction, Owner owner)
{
    m_owner = owner;
    m_mover.run(direction);
    m_activity = Activity::Jog;
}

void SimAxis::startHome()
{
    m_owner = Owner::Command;
    m_mover.run(-1);
    m_activity = Activity::Home;
}

void SimAxis::startPath()
{
    m_mover.stop();
    m_owner = Owner::Command;
    m_activity = Activity::Path;
    m_pathDirection = 0;
}

void SimAxis::stop()
{
    m_mover.stop();
    m_activity = Activity::Idle;
    m_pathDirection = 0;
}

double SimAxis::tick()
{
    if (m_activity == Activity::Idle || m_activity == Activity::Path)
        return 0;
    const double moved = m_mover.tick();
    applyMachineDelta(moved);
    if (!m_mover.isMoving())
        m_activity = Activity::Idle;
    return moved;
}

void SimAxis::setPathSteps(double steps)
{
    const double moved = steps - m_mover.position();
    m_pathDirection = moved > 1e-12 ? 1 : (moved < -1e-12 ? -1 : m_pathDirection);
    m_mover.setPosition(steps);
    applyMachineDelta(moved);
}

int SimAxis::motionDirection() const
{
    switch (m_activity) {
    case Activity::Idle:
        return 0;
    case Activity::Path:
        return m_pathDirection;
    default:
        return m_mover.direction();
    }
}

qint64 SimAxis::steps() const
{
    return qint64(std::llround(m_mover.position()));
}

qint64 SimAxis::positionRaw() const
{
    return motorderived::positionCounts(m_mover.position(), m_settings.stepsPerUnit());
}

void SimAxis::zero()
{
    // A move in progress keeps its end point on the machine: shift its target with the counter.
    const double shift = m_mover.position();
    m_mover.setPosition(0);
    if (m_mover.mode() == RampMover::Mode::Target)
        m_mover.moveTo(m_mover.target() - shift);
}

void SimAxis::setMachinePosition(double units)
{
    m_machine = std::clamp(units, -m_overtravel, m_travel + m_overtravel);
}

void SimAxis::applyMachineDelta(double steps)
{
    // Past the hard stops the motor stalls: the counter goes on, the carriage does not.
    setMachinePosition(m_machine + steps / m_settings.stepsPerUnit());
}

} // namespace stepcom
