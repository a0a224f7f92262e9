#include "sim/model/simdevice.h"

#include "sim/model/simprotocol.h"
#include "sim/model/simstate.h"

#include <QCoreApplication>
#include <QFile>
#include <QMutexLocker>
#include <QRegularExpression>

#include <algorithm>

namespace stepcom {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::SimDevice", text);
}

} // namespace

SimDevice::SimDevice(const RegisterMap &map)
    : m_regs(map)
    , m_machine(m_regs)
{
    m_flash = m_regs.writableValues();
}

void SimDevice::sync() const
{
    qint64 ms = 0;
    if (m_clock) {
        const qint64 t = m_clock();
        if (t > m_clockSeen) {
            ms = t - m_clockSeen;
            m_clockSeen = t;
        }
    }
    run(ms);
}

void SimDevice::run(qint64 ms) const
{
    if (m_poweredOff) {
        const qint64 dark = std::clamp(m_powerOnAt - m_machine.now(), qint64(0), ms);
        if (dark > 0)
            m_machine.advance(dark);
        ms -= dark;
        if (m_machine.now() < m_powerOnAt)
            return;
        powerUp();
    }
    if (ms > 0)
        m_machine.advance(ms);
}

void SimDevice::powerUp() const
{
    const qint64 id = m_regs.raw(QStringLiteral("device.id"), 1);
    const qint64 baud = m_regs.raw(QStringLiteral("device.baud"), 9600);
    m_poweredOff = false;
    // Flash holds only values the map allowed when they were saved: nothing to report.
    m_regs.applyValues(m_flash);
    m_machine.powerUp();
    const bool linkChanged = id != m_regs.raw(QStringLiteral("device.id"), 1) ||
                             baud != m_regs.raw(QStringLiteral("device.baud"), 9600);
    if (linkChanged && m_linkObserver)
        m_linkObserver();
}

void SimDevice::powerCycle(qint64 offMs)
{
    QMutexLocker lock(&m_mutex);
    sync();
    m_poweredOff = true;
    m_powerOnAt = m_machine.now() + std::max(qint64(0), offMs);
    m_machine.powerDown();
}

bool SimDevice::isPoweredOff() const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return m_poweredOff;
}

QString SimDevice::offError() const
{
    return tr("the controller is switched off");
}

void SimDevice::setClock(Clock clock)
{
    QMutexLocker lock(&m_mutex);
    m_clock = std::move(clock);
    m_clockSeen = m_clock ? m_clock() : 0;
}

void SimDevice::advance(qint64 ms)
{
    QMutexLocker lock(&m_mutex);
    sync();
    run(ms);
}

qint64 SimDevice::now() const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return m_machine.now();
}

SimAnswer SimDevice::handle(const QModbusRequest &request)
{
    QMutexLocker lock(&m_mutex);
    sync();
    if (m_poweredOff)
        return {}; // no power, no answer
    m_linkChanged = false;
    SimProtocol protocol(m_regs,
                         {[this](const QList<SimProtocol::Write> &w) { applyWrites(w); },
                          [this](const Parameter &coil) { return executeCoil(coil); }},
                         m_strictReads, m_lacking);
    SimAnswer answer;
    answer.response = protocol.process(request);
    answer.linkChanged = m_linkChanged;
    return answer;
}

void SimDevice::applyWrites(const QList<std::pair<const Parameter *, qint64>> &writes)
{
    bool modeChanged = false;
    for (const auto &[param, raw] : writes) {
        const qint64 old = m_regs.raw(param);
        m_regs.setRaw(param, raw);
        if (param->key == QLatin1String("device.id") || param->key == QLatin1String("device.baud"))
            m_linkChanged = m_linkChanged || old != raw;
        if (param->key == QLatin1String("mode.system") && old != raw)
            modeChanged = true;
    }
    m_machine.parametersChanged();
    if (modeChanged)
        m_machine.systemModeChanged();
    if (m_linkChanged && m_linkObserver)
        m_linkObserver();
}

void SimDevice::setStrictReads(bool strict)
{
    QMutexLocker lock(&m_mutex);
    m_strictReads = strict;
}

void SimDevice::setLacking(const QSet<QString> &keys)
{
    QMutexLocker lock(&m_mutex);
    m_lacking = keys;
}

void SimDevice::setLinkObserver(std::function<void()> observer)
{
    QMutexLocker lock(&m_mutex);
    m_linkObserver = std::move(observer);
}

bool SimDevice::executeCoil(const Parameter &coil)
{
    if (coil.block == QLatin1String("motor")) {
        const int n = coil.instance;
        const QString &k = coil.localKey;
        if (k == QLatin1String("move"))
            m_machine.singleMove(n);
        else if (k == QLatin1String("forward"))
            m_machine.jog(n, 1);
        else if (k == QLatin1String("reverse"))
            m_machine.jog(n, -1);
        else if (k == QLatin1String("home"))
            m_machine.home(n);
        else if (k == QLatin1String("stop"))
            m_machine.stop(n);
        return true;
    }
    const QString &k = coil.key;
    static const QRegularExpression output(QStringLiteral("^output(\\d+)_(on|off)$"));
    if (k == QLatin1String("estop")) {
        m_machine.emergencyStop();
    } else if (k == QLatin1String("zero_coordinates")) {
        m_machine.zeroCoordinates();
    } else if (k == QLatin1String("return_to_zero")) {
        m_machine.returnToZero();
    } else if (k == QLatin1String("home_all")) {
        m_machine.homeAll();
    } else if (const auto m = output.match(k); m.hasMatch()) {
        m_machine.setOutput(m.captured(1).toInt(), m.captured(2) == QLatin1String("on"));
    } else if (k == QLatin1String("outputs_all_on")) {
        m_machine.setAllOutputs(true);
    } else if (k == QLatin1String("outputs_all_off")) {
        m_machine.setAllOutputs(false);
    } else if (k == QLatin1String("factory_reset")) {
        m_regs.resetToFactory();
        m_machine.parametersChanged();
        m_machine.systemModeChanged();
    } else if (k == QLatin1String("save_to_flash")) {
        return saveLocked(nullptr);
    } else if (k == QLatin1String("arc.start")) {
        m_machine.startArc();
    } else if (k == QLatin1String("arc.stop")) {
        m_machine.stopArc();
    } else if (k == QLatin1String("line.start")) {
        m_machine.startLine();
    } else if (k == QLatin1String("line.stop")) {
        m_machine.stopLine();
    }
    return true; // unknown coils of another map are accepted and do nothing
}

std::optional<qint64> SimDevice::value(const QString &key) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    const Parameter *p = m_regs.map().find(key);
    if (!p || !p->isHolding())
        return std::nullopt;
    return m_regs.raw(p);
}

const Parameter *SimDevice::writeLocked(const QString &key, qint64 raw, QString *error)
{
    const Parameter *p = m_regs.map().find(key);
    QString why;
    if (!p || !p->writable())
        why = tr("%1: not a writable parameter").arg(key);
    else
        why = p->checkRaw(raw);
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return nullptr;
    }
    m_linkChanged = false;
    applyWrites({{p, raw}});
    return p;
}

bool SimDevice::setValue(const QString &key, qint64 raw, QString *error)
{
    QMutexLocker lock(&m_mutex);
    sync();
    if (m_poweredOff) {
        if (error)
            *error = offError();
        return false;
    }
    return writeLocked(key, raw, error) != nullptr;
}

bool SimDevice::setSavedValue(const QString &key, qint64 raw, QString *error)
{
    QMutexLocker lock(&m_mutex);
    sync();
    const Parameter *p = writeLocked(key, raw, error);
    if (p)
        m_flash.insert(p->key, raw);
    return p != nullptr;
}

bool SimDevice::command(const QString &coilKey, QString *error)
{
    QMutexLocker lock(&m_mutex);
    sync();
    if (m_poweredOff) {
        if (error)
            *error = offError();
        return false;
    }
    const Parameter *p = m_regs.map().find(coilKey);
    if (!p || !p->isCoil()) {
        if (error)
            *error = tr("%1: not a command of the map").arg(coilKey);
        return false;
    }
    const bool ok = executeCoil(*p);
    if (!ok && error)
        *error = tr("%1: the device failed").arg(coilKey);
    return ok;
}

int SimDevice::deviceId() const
{
    QMutexLocker lock(&m_mutex);
    sync(); // a power-up may have restored the saved id
    return int(m_regs.raw(QStringLiteral("device.id"), 1));
}

int SimDevice::baud() const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return int(m_regs.raw(QStringLiteral("device.baud"), 9600));
}

int SimDevice::motorCount() const
{
    QMutexLocker lock(&m_mutex);
    return m_machine.motorCount();
}

int SimDevice::inputCount() const
{
    QMutexLocker lock(&m_mutex);
    return m_machine.inputCount();
}

int SimDevice::outputCount() const
{
    QMutexLocker lock(&m_mutex);
    return m_machine.outputCount();
}

void SimDevice::setInput(int n, InputForce force)
{
    QMutexLocker lock(&m_mutex);
    sync();
    m_machine.forceInput(n, force);
}

bool SimDevice::input(int n) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return m_machine.input(n);
}

bool SimDevice::output(int n) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return m_machine.output(n);
}

bool SimDevice::running(int motor) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return motor >= 1 && motor <= m_machine.motorCount() && m_machine.axis(motor).isRunning();
}

qint64 SimDevice::position(int motor) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return motor >= 1 && motor <= m_machine.motorCount() ? m_machine.axis(motor).positionRaw() : 0;
}

qint64 SimDevice::steps(int motor) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return motor >= 1 && motor <= m_machine.motorCount() ? m_machine.axis(motor).steps() : 0;
}

double SimDevice::machinePosition(int motor) const
{
    QMutexLocker lock(&m_mutex);
    sync();
    return motor >= 1 && motor <= m_machine.motorCount() ? m_machine.axis(motor).machinePosition()
                                                         : 0.0;
}

void SimDevice::setMachinePosition(int motor, double units)
{
    QMutexLocker lock(&m_mutex);
    sync();
    m_machine.setMachinePosition(motor, units);
}

void SimDevice::setTravel(int motor, double travel, double overtravel)
{
    QMutexLocker lock(&m_mutex);
    sync();
    m_machine.setTravel(motor, travel, overtravel);
}

void SimDevice::setMachine(const MachineSettings &machine)
{
    QMutexLocker lock(&m_mutex);
    sync();
    m_machine.setMachine(machine);
}

MachineSettings SimDevice::machine() const
{
    QMutexLocker lock(&m_mutex);
    return m_machine.machine();
}

SimTruth SimDevice::truth() const
{
    QMutexLocker lock(&m_mutex);
    sync();
    SimTruth t;
    t.timeMs = m_machine.now();
    for (int n = 1; n <= m_machine.motorCount(); ++n)
        t.axes.append(SimTruth::Axis::of(n, m_machine.axis(n)));
    return t;
}

QJsonObject SimDevice::truthJson() const
{
    return truth().toJson();
}

void SimDevice::setStatePath(const QString &path)
{
    QMutexLocker lock(&m_mutex);
    m_statePath = path;
}

QString SimDevice::statePath() const
{
    QMutexLocker lock(&m_mutex);
    return m_statePath;
}

bool SimDevice::loadState(QString *error)
{
    QMutexLocker lock(&m_mutex);
    if (m_statePath.isEmpty() || !QFile::exists(m_statePath))
        return true;
    const auto values = SimState::load(m_statePath, error);
    if (!values)
        return false;
    const QStringList problems = m_regs.applyValues(*values);
    m_flash = m_regs.writableValues();
    m_machine.parametersChanged();
    m_machine.systemModeChanged();
    if (!problems.isEmpty() && error)
        *error = problems.join(QLatin1Char('\n'));
    return true;
}

bool SimDevice::save(QString *error)
{
    QMutexLocker lock(&m_mutex);
    return saveLocked(error);
}

bool SimDevice::saveLocked(QString *error)
{
    m_flash = m_regs.writableValues();
    if (m_statePath.isEmpty())
        return true;
    return SimState::save(m_statePath, m_regs.map().identity(), m_flash, error);
}

void SimDevice::factoryReset()
{
    QMutexLocker lock(&m_mutex);
    sync();
    m_regs.resetToFactory();
    m_machine.parametersChanged();
    m_machine.systemModeChanged();
}

QString SimDevice::statusText() const
{
    QMutexLocker lock(&m_mutex);
    sync();
    QStringList lines;
    lines << tr("time %1 ms, mode %2, id %3, %4 baud")
                 .arg(m_machine.now())
                 .arg(m_machine.systemMode())
                 .arg(m_regs.raw(QStringLiteral("device.id"), 1))
                 .arg(m_regs.raw(QStringLiteral("device.baud"), 9600));
    if (m_poweredOff)
        lines << tr("24 V off: power returns in %1 ms").arg(m_powerOnAt - m_machine.now());
    for (int n = 1; n <= m_machine.motorCount(); ++n) {
        const SimAxis &a = m_machine.axis(n);
        lines << tr("motor %1: position %2, %3, carriage at %4 of %5")
                     .arg(n)
                     .arg(QString::number(double(a.positionRaw()) / 100.0, 'f', 2),
                          a.isRunning() ? tr("running") : tr("idle"),
                          QString::number(a.machinePosition(), 'f', 2),
                          QString::number(a.travel(), 'f', 2));
    }
    QString in;
    for (int n = 1; n <= m_machine.inputCount(); ++n)
        in += QStringLiteral(" IN%1=%2").arg(n).arg(m_machine.input(n) ? 1 : 0);
    QString out;
    for (int n = 1; n <= m_machine.outputCount(); ++n)
        out += QStringLiteral(" OUT%1=%2").arg(n).arg(m_machine.output(n) ? 1 : 0);
    lines << tr("inputs:%1").arg(in) << tr("outputs:%1").arg(out);
    return lines.join(QLatin1Char('\n'));
}

} // namespace stepcom
