#pragma once

#include "motion/rampmover.h"
#include "sim/model/axissettings.h"

#include <QtGlobal>

namespace stepcom {

// One motor of the simulated controller with the carriage it drives: the controller's pulse
// counter (open loop: it counts what it sent) and the carriage's real place on a travel with
// a switch at each end and hard stops a little beyond them.
class SimAxis
{
public:
    enum class Activity { Idle, Move, Jog, Home, Path };
    // Who started the motion: a command (coil) or a special mode reacting to inputs.
    enum class Owner { Command, Mode };

    // Parameters for the next ticks; the ramp follows a new speed at once.
    void configure(const AxisSettings &settings);
    const AxisSettings &settings() const { return m_settings; }

    void setTravel(double travel, double overtravel);
    double travel() const { return m_travel; }

    // Absolute target in steps of the counter.
    void startMove(double targetSteps, Owner owner = Owner::Command);
    void startJog(int direction, Owner owner = Owner::Command);
    void startHome();
    // Interpolation drives the counter directly through setPathSteps().
    void startPath();
    void stop();

    // One millisecond; returns the steps moved (signed).
    double tick();
    void setPathSteps(double steps);

    Activity activity() const { return m_activity; }
    Owner owner() const { return m_owner; }
    bool isRunning() const { return m_activity != Activity::Idle; }
    // +1 / -1 while moving, 0 when idle.
    int motionDirection() const;

    double exactSteps() const { return m_mover.position(); }
    qint64 steps() const;
    // The position register: counter in distance units × 100.
    qint64 positionRaw() const;
    void zero();

    // Where the carriage really is (distance units from the negative switch).
    double machinePosition() const { return m_machine; }
    void setMachinePosition(double units);
    bool negativeSwitch() const { return m_machine <= 0; }
    bool positiveSwitch() const { return m_machine >= m_travel; }

private:
    void applyMachineDelta(double steps);
    void applyRates();

    AxisSettings m_settings;
    RampMover m_mover;
    Activity m_activity = Activity::Idle;
    Owner m_owner = Owner::Command;
    int m_pathDirection = 0;
    double m_machine = 50.0;
    double m_travel = 200.0;
    double m_overtravel = 5.0;
};

} // namespace stepcom
