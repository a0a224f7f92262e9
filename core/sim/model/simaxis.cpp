#include "sim/model/simaxis.h"

#include <algorithm>
#include <cmath>

namespace stepcom {

SimAxis::SimAxis()
{
    configureSwitches();
    setMachinePosition(m_machine);
}

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
    configureSwitches();
    setMachinePosition(m_machine);
}

void SimAxis::setPhysics(const AxisPhysics &physics, quint32 seed)
{
    m_physics = physics;
    m_seed = seed;
    if (physics.travelMm)
        m_travel = *physics.travelMm;
    m_overtravel = physics.hardStopMm;
    configureSwitches();
    setMachinePosition(m_machine);
}

void SimAxis::configureSwitches()
{
    // Each switch its own dice, so one axis's moves do not change another's trip points.
    m_negative.configure(m_physics.negativeSwitchMm, m_physics.switchJitterMm,
                         m_physics.switchHysteresisMm, m_seed * 2654435761u + 1);
    m_positive.configure(m_physics.positiveSwitchMm.value_or(m_travel), m_physics.switchJitterMm,
                         m_physics.switchHysteresisMm, m_seed * 2654435761u + 2);
}

double SimAxis::lowStop() const
{
    return m_negative.nominal() - m_overtravel;
}

double SimAxis::highStop() const
{
    return m_positive.nominal() + m_overtravel;
}

SimRotor::Limits SimAxis::limits() const
{
    // Motor units (rotor speed) to this axis's pulse rates.
    const double hzPerRpm = m_settings.pulsesPerRev() / 60.0;
    return {m_physics.pullOutRpm * hzPerRpm, m_physics.pullInRpm * hzPerRpm,
            m_physics.accelLimitRpmPerS * hzPerRpm / 1000.0};
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
    drive(0, 0, 0); // the motion ends: a stalled rotor locks in again
}

double SimAxis::tick()
{
    if (m_activity == Activity::Idle || m_activity == Activity::Path)
        return 0;
    const double moved = m_mover.tick();
    // The rate the mover reached this tick; a motion from rest starts at the start rate.
    const double rateHz = m_mover.isMoving() ? m_mover.direction() * m_mover.rate() * 1000.0 : 0;
    const double startHz = std::min(m_settings.startHz, m_settings.hzForRpm(m_settings.rpm));
    drive(moved, rateHz, startHz);
    if (!m_mover.isMoving())
        m_activity = Activity::Idle;
    return moved;
}

void SimAxis::setPathSteps(double steps, double rateHz)
{
    const double moved = steps - m_mover.position();
    m_pathDirection = moved > 1e-12 ? 1 : (moved < -1e-12 ? -1 : m_pathDirection);
    m_mover.setPosition(steps);
    drive(moved, rateHz, rateHz);
}

void SimAxis::drive(double moved, double rateHz, double startHz)
{
    const SimRotor::Limits lim = limits();
    m_rotor.observe(rateHz, startHz, lim);
    if (!m_rotor.stalled() && !placeRotor(m_rotor.position() + moved))
        m_rotor.setStalled(true); // pushing into a hard stop
    const int direction = rateHz > 0 ? 1 : (rateHz < 0 ? -1 : 0);
    // Against a hard stop it stays out of sync while the pulses push on into it.
    const bool pushing = m_blockedSide != 0 && direction == m_blockedSide;
    if (m_rotor.stalled() && !pushing && SimRotor::canRelock(rateHz, lim))
        relock();
}

bool SimAxis::placeRotor(double pulses)
{
    const double spu = m_settings.stepsPerUnit();
    const double half = m_physics.backlashMm / 2;
    double rotor = m_rotorMm + (pulses - m_rotor.position()) / spu;
    // The carriage moves only once the rotor has taken up the play in the new direction.
    double carriage = std::clamp(m_machine, rotor - half, rotor + half);
    m_blockedSide = 0;
    if (carriage > highStop()) {
        carriage = highStop();
        rotor = std::min(rotor, carriage + half);
        m_blockedSide = 1;
    } else if (carriage < lowStop()) {
        carriage = lowStop();
        rotor = std::max(rotor, carriage - half);
        m_blockedSide = -1;
    }
    // Unblocked the rotor takes the pulses exactly, so in sync it never drifts from the count.
    m_rotor.setPosition(m_blockedSide == 0 ? pulses
                                           : m_rotor.position() + (rotor - m_rotorMm) * spu);
    m_rotorMm = rotor;
    m_machine = carriage;
    m_negative.update(m_machine);
    m_positive.update(m_machine);
    return m_blockedSide == 0;
}

void SimAxis::relock()
{
    // A 2-phase hybrid relocks at the same phase of its windings: whole electrical cycles of
    // 4 full steps, never past a hard stop.
    const double chunk = 4.0 * m_settings.microsteps;
    const double spu = m_settings.stepsPerUnit();
    const double half = m_physics.backlashMm / 2;
    double target = m_rotor.relockTarget(m_mover.position(), chunk);
    const double rotorAtTarget = m_rotorMm + (target - m_rotor.position()) / spu;
    const double chunkMm = chunk / spu;
    if (rotorAtTarget > highStop() + half + 1e-9)
        target -= chunk * std::ceil((rotorAtTarget - highStop() - half - 1e-9) / chunkMm);
    else if (rotorAtTarget < lowStop() - half - 1e-9)
        target += chunk * std::ceil((lowStop() - half - rotorAtTarget - 1e-9) / chunkMm);
    placeRotor(target);
    m_blockedSide = 0;
    m_rotor.setStalled(false);
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
    m_rotor.setPosition(m_rotor.position() - shift); // what was lost stays lost
    if (m_mover.mode() == RampMover::Mode::Target)
        m_mover.moveTo(m_mover.target() - shift);
}

void SimAxis::powerUp()
{
    zero();
    m_rotor.reset(0);
    m_blockedSide = 0;
}

void SimAxis::setMachinePosition(double units)
{
    m_machine = std::clamp(units, lowStop(), highStop());
    m_rotorMm = m_machine;
    m_blockedSide = 0;
    m_negative.update(m_machine);
    m_positive.update(m_machine);
}

} // namespace stepcom
