#include "sim/model/simmachine.h"

#include "sim/model/simregisters.h"

#include <cmath>

namespace stepcom {

// Motor 1 as the special modes see it.
class SimMachine::ModeAxis : public SpecialModes::Axis
{
public:
    explicit ModeAxis(SimMachine &m)
        : m_m(m)
    {}
    void run(int direction) override
    {
        if (m_m.m_interpolator.isActive())
            m_m.m_interpolator.stop(m_m.m_axes[0], m_m.m_axes[1]);
        m_m.ax(1).startJog(direction, SimAxis::Owner::Mode);
    }
    void moveBy(int direction) override
    {
        SimAxis &a = m_m.ax(1);
        const double steps =
            motorderived::wholePulses(a.settings().distance, a.settings().stepsPerUnit());
        a.startMove(a.exactSteps() + direction * steps, SimAxis::Owner::Mode);
    }
    void stop() override { m_m.stop(1); }
    bool isRunning() const override { return m_m.axis(1).isRunning(); }
    int runDirection() const override { return m_m.axis(1).motionDirection(); }
    bool startedByMode() const override { return m_m.axis(1).owner() == SimAxis::Owner::Mode; }
    bool limitActive(int direction) const override { return m_m.limitActive(0, direction); }

private:
    SimMachine &m_m;
};

SimMachine::SimMachine(SimRegisters &registers)
    : m_regs(registers)
{
    const RegisterMap &map = m_regs.map();
    const QString motor = QStringLiteral("motor");
    for (int n = 1; n <= m_regs.motorCount(); ++n) {
        auto p = [&](const char *key) { return map.blockParameter(motor, n, QLatin1String(key)); };
        AxisParams a;
        a.stepAngle = p("step_angle");
        a.microsteps = p("microsteps");
        a.startHz = p("start_frequency");
        a.accel = p("accel_frequency");
        a.direction = p("direction");
        a.speed = p("speed");
        a.pitch = p("pitch");
        a.distance = p("move_distance");
        a.limitPositive = p("limit_positive");
        a.limitNegative = p("limit_negative");
        a.homeInput = p("home_input");
        a.position = p("position");
        a.running = p("running");
        m_params.append(a);
        m_axes.append(SimAxis());
        m_axes.last().setPhysics(m_machine.axis(n), m_machine.seed * 1000003u + quint32(n));
        m_homed.append(false);
    }
    for (int i = 0; i < m_regs.inputCount(); ++i) {
        m_forced.append(false);
        m_pulseUntil.append(0);
        m_inputs.append(false);
    }
    for (int i = 0; i < m_regs.outputCount(); ++i)
        m_outputs.append(false);
    parametersChanged();
}

AxisSettings SimMachine::settingsFor(int index) const
{
    const AxisParams &p = m_params.at(index);
    AxisSettings s;
    auto get = [&](const Parameter *param, double fallback) {
        return param ? double(m_regs.raw(param)) / param->scale : fallback;
    };
    s.stepAngle = get(p.stepAngle, s.stepAngle);
    s.microsteps = std::max(1.0, get(p.microsteps, s.microsteps));
    s.startHz = std::max(1.0, get(p.startHz, s.startHz));
    s.accelHzPerMs = std::max(1.0, get(p.accel, s.accelHzPerMs));
    s.direction = int(get(p.direction, s.direction));
    s.rpm = std::max(0.01, get(p.speed, s.rpm));
    s.pitch = get(p.pitch, s.pitch);
    if (s.pitch <= 0)
        s.pitch = 0.01;
    s.distance = get(p.distance, s.distance);
    s.limitPositive = int(get(p.limitPositive, 0));
    s.limitNegative = int(get(p.limitNegative, 0));
    s.homeInput = int(get(p.homeInput, 0));
    return s;
}

void SimMachine::parametersChanged()
{
    for (int i = 0; i < m_axes.size(); ++i)
        m_axes[i].configure(settingsFor(i));
    // A new pitch changes the position register, new wiring the inputs: show it at once.
    settle();
    publish();
}

int SimMachine::systemMode() const
{
    return int(m_regs.raw(QStringLiteral("mode.system"), 0));
}

void SimMachine::systemModeChanged()
{
    m_modes.reset();
    for (SimAxis &a : m_axes) {
        if (a.owner() == SimAxis::Owner::Mode)
            a.stop();
    }
    settle();
    publish();
}

int SimMachine::limitInput(int index, int direction) const
{
    // Modes 1-5 fix motor 1's limits to inputs and ignore the limit registers.
    switch (systemMode()) {
    case 0:
        return direction > 0 ? axis(index + 1).settings().limitPositive
                             : axis(index + 1).settings().limitNegative;
    case 1:
        return index == 0 ? (direction > 0 ? 1 : 2) : 0;
    case 3:
    case 4:
    case 5:
        return index == 0 ? (direction > 0 ? 3 : 4) : 0;
    default:
        return 0;
    }
}

int SimMachine::homeWire(int index) const
{
    return systemMode() == 0 ? axis(index + 1).settings().homeInput : 0;
}

bool SimMachine::limitActive(int index, int direction) const
{
    return inputOn(limitInput(index, direction));
}

bool SimMachine::needsTicks() const
{
    if (!m_homingQueue.isEmpty() || m_interpolator.isActive())
        return true;
    for (const SimAxis &a : m_axes) {
        if (a.isRunning())
            return true;
    }
    for (qint64 until : m_pulseUntil) {
        if (until > 0)
            return true;
    }
    return false;
}

void SimMachine::advance(qint64 ms)
{
    if (!m_powered) {
        m_now += ms; // without power nothing moves or looks at the inputs
        endPulses();
        return;
    }
    for (qint64 i = 0; i < ms; ++i) {
        if (!needsTicks()) {
            m_now += ms - i; // nothing moves: time passes in one go
            break;
        }
        tick();
    }
    publish();
}

void SimMachine::tick()
{
    ++m_now;
    endPulses();
    for (SimAxis &a : m_axes)
        a.tick();
    if (m_axes.size() >= 2)
        m_interpolator.tick(m_axes[0], m_axes[1]);
    settle();
}

void SimMachine::endPulses()
{
    for (int i = 0; i < m_pulseUntil.size(); ++i) {
        if (m_pulseUntil.at(i) > 0 && m_now >= m_pulseUntil.at(i)) {
            m_pulseUntil[i] = 0;
            m_forced[i] = false;
        }
    }
}

void SimMachine::settle()
{
    if (!m_powered)
        return; // no firmware runs: inputs change nothing
    updateInputs();
    if (!m_axes.isEmpty()) {
        // Also in mode 0, so a mode entered later sees only edges that happen after it.
        ModeAxis modeAxis(*this);
        m_modes.evaluate(systemMode(), m_inputs,
                         int(m_regs.raw(QStringLiteral("mode.round_trips"), 0)), modeAxis);
    }
    checkHomeAndLimits();
    advanceHomingSequence();
}

void SimMachine::updateInputs()
{
    for (int i = 0; i < m_inputs.size(); ++i) {
        const int n = i + 1;
        bool on = m_forced.at(i);
        for (int a = 0; a < m_axes.size() && !on; ++a) {
            const SimAxis &axis = m_axes.at(a);
            // A wired switch drives its input whatever the registers name, as on a machine.
            if (const auto &w = axis.physics().wiring) {
                on = (axis.positiveSwitch() && w->positive == n) ||
                     (axis.negativeSwitch() && (w->negative == n || w->home == n));
                continue;
            }
            if (axis.positiveSwitch() && limitInput(a, 1) == n)
                on = true;
            if (axis.negativeSwitch() && (limitInput(a, -1) == n || homeWire(a) == n))
                on = true;
        }
        m_inputs[i] = on;
    }
}

void SimMachine::checkHomeAndLimits()
{
    for (int i = 0; i < m_axes.size(); ++i) {
        SimAxis &a = m_axes[i];
        if (a.activity() == SimAxis::Activity::Home && inputOn(homeWire(i))) {
            a.stop(); // on the home switch: stop and (unless the machine says not) zero
            if (m_machine.homingZeroesCount)
                a.zero();
            m_homed[i] = true;
            continue;
        }
        const int dir = a.motionDirection();
        if (dir != 0 && limitActive(i, dir))
            a.stop();
    }
}

void SimMachine::advanceHomingSequence()
{
    while (!m_homingQueue.isEmpty()) {
        const int motor = m_homingQueue.first();
        if (axis(motor).isRunning())
            return;
        if (!m_homed.at(motor - 1)) {
            m_homingQueue.clear(); // stopped before reaching home: the sequence ends
            return;
        }
        m_homingQueue.removeFirst();
        if (!m_homingQueue.isEmpty())
            home(m_homingQueue.first());
    }
}

void SimMachine::singleMove(int motor)
{
    if (!validMotor(motor) || axis(motor).isRunning())
        return;
    SimAxis &a = ax(motor);
    const int dir = a.settings().direction ? -1 : 1;
    if (limitActive(motor - 1, dir))
        return;
    const double steps =
        motorderived::wholePulses(a.settings().distance, a.settings().stepsPerUnit());
    a.startMove(a.exactSteps() + dir * steps);
    publish();
}

void SimMachine::jog(int motor, int direction)
{
    if (!validMotor(motor) || axis(motor).isRunning() || limitActive(motor - 1, direction))
        return;
    ax(motor).startJog(direction);
    publish();
}

void SimMachine::home(int motor)
{
    if (!validMotor(motor) || axis(motor).isRunning())
        return;
    m_homed[motor - 1] = false;
    ax(motor).startHome();
    settle(); // already on the home switch: homed at once
    publish();
}

void SimMachine::stop(int motor)
{
    if (!validMotor(motor))
        return;
    if (m_interpolator.isActive() && motor <= 2)
        m_interpolator.stop(m_axes[0], m_axes[1]);
    if (!m_homingQueue.isEmpty() && m_homingQueue.first() == motor)
        m_homingQueue.clear();
    ax(motor).stop();
    publish();
}

void SimMachine::stopEverything()
{
    if (m_axes.size() >= 2)
        m_interpolator.stop(m_axes[0], m_axes[1]);
    m_homingQueue.clear();
    for (SimAxis &a : m_axes)
        a.stop();
    m_modes.reset();
}

void SimMachine::emergencyStop()
{
    stopEverything();
    setAllOutputs(false);
}

void SimMachine::powerDown()
{
    stopEverything();
    m_powered = false;
    setAllOutputs(false);
}

void SimMachine::powerUp()
{
    stopEverything();
    m_powered = true;
    m_homed.fill(false);
    // The counters start at 0 wherever the carriages stand (they do not move by themselves).
    for (SimAxis &a : m_axes)
        a.powerUp();
    for (bool &o : m_outputs)
        o = false;
    parametersChanged(); // the restored registers, inputs read afresh, status published
}

void SimMachine::zeroCoordinates()
{
    for (SimAxis &a : m_axes)
        a.zero();
    publish();
}

void SimMachine::returnToZero()
{
    for (SimAxis &a : m_axes) {
        if (!a.isRunning())
            a.startMove(0);
    }
    publish();
}

void SimMachine::homeAll()
{
    for (const SimAxis &a : m_axes) {
        if (a.isRunning())
            return;
    }
    m_homingQueue.clear();
    for (const char *key : {"homing.first", "homing.second"}) {
        const int motor = int(m_regs.raw(QLatin1String(key), 0));
        if (validMotor(motor) && !m_homingQueue.contains(motor))
            m_homingQueue.append(motor);
    }
    if (!m_homingQueue.isEmpty())
        home(m_homingQueue.first());
}

void SimMachine::setOutput(int n, bool on)
{
    if (n >= 1 && n <= m_outputs.size())
        m_outputs[n - 1] = on;
    publish();
}

void SimMachine::setAllOutputs(bool on)
{
    for (bool &o : m_outputs)
        o = on;
    publish();
}

bool SimMachine::canStartPath(bool enabled) const
{
    return m_axes.size() >= 2 && !m_axes[0].isRunning() && !m_axes[1].isRunning() && enabled;
}

interpolation::RawValue SimMachine::rawValue() const
{
    return [this](const QString &key) -> std::optional<qint64> { return m_regs.raw(key, 0); };
}

bool SimMachine::startArc()
{
    const interpolation::ArcSetup arc = interpolation::arcSetup(m_regs.map(), rawValue());
    if (!canStartPath(arc.enabled))
        return false;
    const interpolation::ArcPath path = interpolation::arcPath(arc);
    if (!path.path)
        return false;
    m_interpolator.start(Interpolator::Kind::Arc, *path.path, std::max(0.01, arc.speedRpm),
                         m_axes[0], m_axes[1]);
    publish();
    return true;
}

bool SimMachine::startLine()
{
    const interpolation::LineSetup line = interpolation::lineSetup(m_regs.map(), rawValue());
    if (!canStartPath(line.enabled))
        return false;
    m_interpolator.start(Interpolator::Kind::Line, interpolation::linePath(line),
                         std::max(0.01, line.speedRpm), m_axes[0], m_axes[1]);
    publish();
    return true;
}

void SimMachine::stopArc()
{
    if (m_interpolator.isActive() && m_interpolator.kind() == Interpolator::Kind::Arc)
        m_interpolator.stop(m_axes[0], m_axes[1]);
    publish();
}

void SimMachine::stopLine()
{
    if (m_interpolator.isActive() && m_interpolator.kind() == Interpolator::Kind::Line)
        m_interpolator.stop(m_axes[0], m_axes[1]);
    publish();
}

void SimMachine::forceInput(int n, InputForce force)
{
    if (n < 1 || n > m_forced.size())
        return;
    m_forced[n - 1] = force != InputForce::Off;
    m_pulseUntil[n - 1] = force == InputForce::Pulse ? m_now + kPulseMs : 0;
    settle();
    publish();
}

bool SimMachine::input(int n) const
{
    return inputOn(n);
}

bool SimMachine::forcedInput(int n) const
{
    return n >= 1 && n <= m_forced.size() && m_forced.at(n - 1);
}

bool SimMachine::output(int n) const
{
    return n >= 1 && n <= m_outputs.size() && m_outputs.at(n - 1);
}

void SimMachine::setMachinePosition(int motor, double units)
{
    if (!validMotor(motor))
        return;
    ax(motor).setMachinePosition(units);
    settle();
    publish();
}

void SimMachine::setTravel(int motor, double travel, double overtravel)
{
    if (!validMotor(motor))
        return;
    ax(motor).setTravel(travel, overtravel);
    settle();
    publish();
}

void SimMachine::setMachine(const MachineSettings &machine)
{
    m_machine = machine;
    for (int i = 0; i < m_axes.size(); ++i) {
        const AxisPhysics physics = machine.axis(i + 1);
        m_axes[i].setPhysics(physics, machine.seed * 1000003u + quint32(i + 1));
        if (physics.startMm)
            m_axes[i].setMachinePosition(*physics.startMm);
    }
    settle();
    publish();
}

void SimMachine::publish()
{
    const RegisterMap &map = m_regs.map();
    for (int i = 0; i < m_axes.size(); ++i) {
        m_regs.setRaw(m_params.at(i).position, m_axes.at(i).positionRaw());
        m_regs.setRaw(m_params.at(i).running, m_axes.at(i).isRunning() ? 1 : 0);
    }
    for (int i = 0; i < m_inputs.size(); ++i)
        m_regs.setRaw(map.find(QStringLiteral("io.in%1").arg(i + 1)), m_inputs.at(i) ? 1 : 0);
    for (int i = 0; i < m_outputs.size(); ++i)
        m_regs.setRaw(map.find(QStringLiteral("io.out%1").arg(i + 1)), m_outputs.at(i) ? 1 : 0);
}

} // namespace stepcom
