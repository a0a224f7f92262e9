#pragma once

#include "motion/pathsetup.h"
#include "sim/model/interpolator.h"
#include "sim/model/machinesettings.h"
#include "sim/model/simaxis.h"
#include "sim/model/specialmodes.h"

#include <QList>

namespace stepcom {

class Parameter;
class SimRegisters;

// The motion side of the simulated controller: the axes with their carriages and switches, the
// inputs and outputs, the commands of the coils, homing, interpolation and the special modes,
// advanced in 1 ms ticks. Not thread-safe: SimDevice serialises every call.
class SimMachine
{
public:
    enum class InputForce { Off, On, Pulse };
    static constexpr int kPulseMs = 50; // how long a "triggered" input stays on

    explicit SimMachine(SimRegisters &registers);

    int motorCount() const { return int(m_axes.size()); }
    int inputCount() const { return int(m_inputs.size()); }
    int outputCount() const { return int(m_outputs.size()); }
    qint64 now() const { return m_now; }
    void advance(qint64 ms);

    // Re-read the motor parameters after a register write (speed changes act while running).
    void parametersChanged();
    // Register 40300 was written: the old mode's motion stops and its state is forgotten.
    void systemModeChanged();

    // The coils; motors are 1-based. A motion command to a moving axis is ignored.
    void singleMove(int motor);
    void jog(int motor, int direction);
    void home(int motor);
    void stop(int motor);
    void emergencyStop();
    void zeroCoordinates();
    void returnToZero();
    void homeAll();
    void setOutput(int n, bool on);
    void setAllOutputs(bool on);
    bool startArc();
    void stopArc();
    bool startLine();
    void stopLine();

    // The 24 V supply: off stops everything at once and the machine ignores its inputs; on
    // starts as the firmware does (nothing running, nothing homed, outputs off, positions 0).
    // The caller restores the saved registers before powerUp().
    void powerDown();
    void powerUp();
    bool powered() const { return m_powered; }

    // Inputs by hand (1-based); switches of the machine are OR-ed in.
    void forceInput(int n, InputForce force);
    bool input(int n) const;
    bool forcedInput(int n) const;
    bool output(int n) const;

    const SimAxis &axis(int motor) const { return m_axes.at(motor - 1); }
    void setMachinePosition(int motor, double units);
    void setTravel(int motor, double travel, double overtravel);
    // The mechanics of every axis; a start_mm puts that carriage there now.
    void setMachine(const MachineSettings &machine);
    const MachineSettings &machine() const { return m_machine; }
    bool homingSequenceActive() const { return !m_homingQueue.isEmpty(); }
    bool homed(int motor) const { return m_homed.value(motor - 1); }
    const Interpolator &interpolator() const { return m_interpolator; }
    const SpecialModes &specialModes() const { return m_modes; }
    int systemMode() const;

    // Status registers from the state (positions, running, inputs, outputs).
    void publish();

private:
    class ModeAxis;
    struct AxisParams
    {
        const Parameter *stepAngle = nullptr;
        const Parameter *microsteps = nullptr;
        const Parameter *startHz = nullptr;
        const Parameter *accel = nullptr;
        const Parameter *direction = nullptr;
        const Parameter *speed = nullptr;
        const Parameter *pitch = nullptr;
        const Parameter *distance = nullptr;
        const Parameter *limitPositive = nullptr;
        const Parameter *limitNegative = nullptr;
        const Parameter *homeInput = nullptr;
        const Parameter *position = nullptr;
        const Parameter *running = nullptr;
    };

    bool needsTicks() const;
    void tick();
    void endPulses(); // hand pulses whose time is up
    void stopEverything();
    void settle(); // inputs, modes, home and limit checks, sequences
    AxisSettings settingsFor(int index) const;
    int limitInput(int index, int direction) const;
    int homeWire(int index) const;
    bool limitActive(int index, int direction) const;
    bool inputOn(int n) const { return n > 0 && n <= m_inputs.size() && m_inputs.at(n - 1); }
    void updateInputs();
    void checkHomeAndLimits();
    void advanceHomingSequence();
    // Interpolation needs motors 1 and 2, both idle, and the enable register on.
    bool canStartPath(bool enabled) const;
    interpolation::RawValue rawValue() const;
    SimAxis &ax(int motor) { return m_axes[motor - 1]; }
    bool validMotor(int motor) const { return motor >= 1 && motor <= m_axes.size(); }

    SimRegisters &m_regs;
    QList<AxisParams> m_params;
    QList<SimAxis> m_axes;
    QList<bool> m_homed;
    QList<bool> m_forced;
    QList<qint64> m_pulseUntil; // 0: no pulse pending
    QList<bool> m_inputs;
    QList<bool> m_outputs;
    QList<int> m_homingQueue; // motors still to home, the first is homing now
    MachineSettings m_machine = MachineSettings::ideal();
    Interpolator m_interpolator;
    SpecialModes m_modes;
    qint64 m_now = 0;
    bool m_powered = true;
};

} // namespace stepcom
