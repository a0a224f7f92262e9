#pragma once

#include "motion/rampmover.h"
#include "sim/model/axisphysics.h"
#include "sim/model/axissettings.h"
#include "sim/model/simrotor.h"
#include "sim/model/simswitch.h"

#include <QtGlobal>

namespace stepcom {

// One motor of the simulated controller with the carriage it drives. Open loop: the controller's
// pulse counter is what it sent; a rotor follows the pulses while in sync (SimRotor) and drives
// the carriage through the play of the drive (backlash) on a travel with a switch near each end
// and hard stops beyond them. Frames: the count and the rotor in pulses from the count's zero;
// the carriage in mm from the nominal negative switch (machinePosition()).
class SimAxis
{
public:
    enum class Activity { Idle, Move, Jog, Home, Path };
    // Who started the motion: a command (coil) or a special mode reacting to inputs.
    enum class Owner { Command, Mode };

    SimAxis();

    // Parameters for the next ticks; the ramp follows a new speed at once.
    void configure(const AxisSettings &settings);
    const AxisSettings &settings() const { return m_settings; }

    // The positive switch at `travel` (unless the physics places it), hard stops `overtravel`
    // past both switches.
    void setTravel(double travel, double overtravel);
    double travel() const { return m_travel; }
    // The mechanics (travel, start and wiring are the caller's); `seed` seeds the switches.
    void setPhysics(const AxisPhysics &physics, quint32 seed);
    const AxisPhysics &physics() const { return m_physics; }

    // Absolute target in steps of the counter.
    void startMove(double targetSteps, Owner owner = Owner::Command);
    void startJog(int direction, Owner owner = Owner::Command);
    void startHome();
    // Interpolation drives the counter directly through setPathSteps().
    void startPath();
    void stop();

    // One millisecond; returns the steps moved (signed).
    double tick();
    // The counter set by interpolation at `rateHz` pulses per second (signed, 0 at the end).
    void setPathSteps(double steps, double rateHz = 0);

    Activity activity() const { return m_activity; }
    Owner owner() const { return m_owner; }
    bool isRunning() const { return m_activity != Activity::Idle; }
    // +1 / -1 while moving, 0 when idle.
    int motionDirection() const;

    double exactSteps() const { return m_mover.position(); }
    qint64 steps() const;
    // The position register: counter in distance units × 100.
    qint64 positionRaw() const;
    // Counter (and rotor with it) to 0; the carriage stays where it is.
    void zero();
    // The supply came back: the count restarts at 0 with the rotor in sync where it stands.
    void powerUp();

    // Where the carriage really is (mm from the nominal negative switch).
    double machinePosition() const { return m_machine; }
    // Puts the carriage (and the rotor, play taken up) there, within the hard stops.
    void setMachinePosition(double units);
    bool negativeSwitch() const { return m_negative.isOn(); }
    bool positiveSwitch() const { return m_positive.isOn(); }
    const SimSwitch &negativeSwitchState() const { return m_negative; }
    const SimSwitch &positiveSwitchState() const { return m_positive; }

    // The rotor in pulses of the count's frame, and whether it is out of sync now.
    double rotorSteps() const { return m_rotor.position(); }
    bool stalled() const { return m_rotor.stalled(); }
    // The rotor in the carriage's frame (mm); carriage − rotorMachine is the play taken.
    double rotorMachinePosition() const { return m_rotorMm; }

private:
    // The count moved by `moved` pulses at `rateHz`: the rotor follows, stalls or relocks.
    void drive(double moved, double rateHz, double startHz);
    // Rotor to `pulses` as far as the hard stops let it; false when a stop blocked it.
    bool placeRotor(double pulses);
    void relock();
    SimRotor::Limits limits() const;
    double lowStop() const;
    double highStop() const;
    void configureSwitches();
    void applyRates();

    AxisSettings m_settings;
    AxisPhysics m_physics = AxisPhysics::ideal();
    quint32 m_seed = 1;
    RampMover m_mover;
    SimRotor m_rotor;
    SimSwitch m_negative{-1};
    SimSwitch m_positive{1};
    Activity m_activity = Activity::Idle;
    Owner m_owner = Owner::Command;
    int m_pathDirection = 0;
    int m_blockedSide = 0; // the hard stop the rotor pushes against (-1/+1), 0 none
    double m_machine = 50.0;
    double m_rotorMm = 50.0;
    double m_travel = 200.0;
    double m_overtravel = 5.0;
};

} // namespace stepcom
