#pragma once

#include "map/registermap.h"
#include "sim/model/simanswer.h"
#include "sim/model/simmachine.h"
#include "sim/model/simregisters.h"
#include "sim/model/simtruth.h"

#include <QHash>
#include <QModbusPdu>
#include <QMutex>
#include <QSet>

#include <functional>
#include <optional>

namespace stepcom {

// The simulated controller without any transport: registers by the register map, the motion
// model, the virtual machine and the protocol rules. Time is injected (a clock and/or
// advance()), so tests are deterministic. Every public method is thread-safe.
class SimDevice
{
public:
    using Clock = std::function<qint64()>; // monotonic milliseconds
    using InputForce = SimMachine::InputForce;

    explicit SimDevice(const RegisterMap &map = RegisterMap::builtin());

    const RegisterMap &map() const { return m_regs.map(); }

    // With a clock the model catches up with it on every call; without one only advance()
    // moves time.
    void setClock(Clock clock);
    void advance(qint64 ms);
    qint64 now() const;

    // One request PDU, answered as the controller would (no delays here; see SimResponder).
    SimAnswer handle(const QModbusRequest &request);

    // Raw register value of a holding parameter (status ones included).
    std::optional<qint64> value(const QString &key) const;
    // A write as a client would make it: read-write parameters, range-checked.
    bool setValue(const QString &key, qint64 raw, QString *error = nullptr);
    // A value as written and saved to flash, without writing the state file: what the
    // controller comes back with after a power cycle (the command line's --id).
    bool setSavedValue(const QString &key, qint64 raw, QString *error = nullptr);
    // A coil switched ON by key ("motor1.move", "estop").
    bool command(const QString &coilKey, QString *error = nullptr);
    int deviceId() const;
    int baud() const;
    // Called (under the device's lock: only queue work from it) whenever the device id or baud
    // changed, by a request or by hand, so a server can follow once its answer is out.
    void setLinkObserver(std::function<void()> observer);

    int motorCount() const;
    int inputCount() const;
    int outputCount() const;
    // Drive input n (1-based) by hand; a pulse stays on for SimMachine::kPulseMs.
    void setInput(int n, InputForce force);
    bool input(int n) const;
    bool output(int n) const;
    bool running(int motor) const;
    qint64 position(int motor) const; // the position register: distance units × 100
    qint64 steps(int motor) const;    // the pulse counter
    double machinePosition(int motor) const;
    void setMachinePosition(int motor, double units);
    void setTravel(int motor, double travel, double overtravel = 5.0);
    // The machine's mechanics (MachineFile); without a call the ideal machine of old. A start_mm
    // puts that carriage there now.
    void setMachine(const MachineSettings &machine);
    MachineSettings machine() const;
    // What really happened: count, rotor, carriage, lost pulses, switches (see SimTruth).
    SimTruth truth() const;
    QJsonObject truthJson() const;

    // The 24 V supply switched off for `offMs` of the device's time (manual clock: advance()).
    // Meanwhile it answers nothing and refuses setValue() and command(); the motors stop at
    // once. The first call after that powers it up: writable registers as last saved (unsaved
    // writes are lost, id and baud included), positions 0, outputs off, nothing running or
    // homed. Switching it off while off restarts the off time.
    void powerCycle(qint64 offMs);
    bool isPoweredOff() const;

    // Where coil 00096 saves; empty keeps the saved values in memory only.
    void setStatePath(const QString &path);
    QString statePath() const;
    // Loads the state file if it exists (a missing file means factory values).
    bool loadState(QString *error);
    bool save(QString *error);
    void factoryReset();

    // Strict reads: every address read must belong to a parameter (default: gaps read as 0).
    void setStrictReads(bool strict);
    // A firmware variant without these listed parameters: reads and writes of them get
    // exception 02.
    void setLacking(const QSet<QString> &keys);

    // A few lines for people: mode, motors, inputs, outputs.
    QString statusText() const;

private:
    void sync() const;
    // Time passes for the machine; power returns on the way when its off time runs out.
    void run(qint64 ms) const;
    void powerUp() const;
    QString offError() const;
    // A write by hand, checked as a client's would be; the parameter, or null and why not.
    const Parameter *writeLocked(const QString &key, qint64 raw, QString *error);
    void applyWrites(const QList<std::pair<const Parameter *, qint64>> &writes);
    bool executeCoil(const Parameter &coil);
    bool saveLocked(QString *error);

    mutable QMutex m_mutex;
    mutable SimRegisters m_regs;
    mutable SimMachine m_machine;
    Clock m_clock;
    mutable qint64 m_clockSeen = 0;
    QString m_statePath;
    QHash<QString, qint64> m_flash; // saved values when there is no state file
    bool m_linkChanged = false;
    mutable bool m_poweredOff = false;
    qint64 m_powerOnAt = 0; // device time the supply comes back, while m_poweredOff
    bool m_strictReads = false;
    QSet<QString> m_lacking;
    std::function<void()> m_linkObserver;
};

} // namespace stepcom
