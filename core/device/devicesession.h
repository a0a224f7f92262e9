#pragma once

#include "bus/linksettings.h"
#include "device/deviceclient.h"
#include "device/parameterstore.h"

#include <QObject>

namespace stepcom {

class LinkHealth;
class ModbusLink;
class MotionSupervisor;
class Poller;
class SimHost;

// One controller connection and everything known about it: owns the link, the typed client,
// the parameter store and (for the built-in simulator) the simulated controller. The window's
// pages and actions talk to this; none of them touch the link directly.
class DeviceSession : public QObject
{
    Q_OBJECT
public:
    enum class Severity { Info, Warning, Error };
    Q_ENUM(Severity)

    explicit DeviceSession(const RegisterMap &map = RegisterMap::builtin(),
                           QObject *parent = nullptr);
    ~DeviceSession() override;

    const RegisterMap &map() const { return m_store->map(); }
    ModbusLink *link() const { return m_link; }
    DeviceClient *client() const { return m_client; }
    ParameterStore *store() const { return m_store; }
    SimHost *simulator() const { return m_sim; }
    // Keeps the status values (positions, inputs, outputs, running) fresh while connected.
    Poller *statusPoller() const { return m_poller; }
    // Follows motion commands to their judged outcome and keeps each axis' reference state.
    MotionSupervisor *motion() const { return m_motion; }
    // Port closed / open but not answering / answering: "connected" means answering.
    LinkHealth *health() const { return m_health; }
    bool isConnected() const;
    bool isSimulator() const { return m_usingSim; }
    LinkSettings settings() const;

    // Connect, then read everything (reading never writes). `connected(ok, reason)` follows.
    void connectTo(const LinkSettings &settings);
    // Start the built-in simulated controller in this process and connect to it.
    void connectSimulator();
    void disconnectFrom();

    void readAll();
    // Write every edit held in the store, verify, and update the store.
    void writeChanges();
    // `done` (optional) hears this write's outcome, after the store has taken it.
    void write(const QList<ParameterWrite> &writes,
               std::function<void(const WriteOutcome &)> done = {});
    // Pulse a command coil by key; emergency ones jump the queue.
    void command(const QString &key);
    // Always goes out at once, ahead of everything queued; never asks.
    void emergencyStop();
    void saveToFlash();
    void factoryReset(); // the caller confirmed what will be lost
    // Write a new device id and/or baud, follow the controller and verify it answers there.
    // On failure `linkChangeFailed` offers the settings that worked before.
    void changeLink(int deviceId, int baud);

Q_SIGNALS:
    void connected(bool ok, const QString &reason);
    void disconnected(const QString &reason);
    void linkStateChanged();
    void message(stepcom::DeviceSession::Severity severity, const QString &text);
    void readFinished(bool ok);
    void writeFinished(const stepcom::WriteOutcome &outcome);
    void commandFinished(const QString &key, bool ok);
    void linkChanged(const stepcom::LinkSettings &settings);
    void linkChangeFailed(const stepcom::LinkSettings &previous, const QString &reason);

private:
    void say(Severity severity, const QString &text);
    // After a failed write, read back what the controller holds for the keys whose request went
    // out without a good answer.
    void readBackUncertain(const QList<ParameterWrite> &writes, const WriteOutcome &outcome);

    ModbusLink *m_link;
    DeviceClient *m_client;
    ParameterStore *m_store;
    Poller *m_poller;
    MotionSupervisor *m_motion;
    LinkHealth *m_health;
    SimHost *m_sim = nullptr;
    bool m_usingSim = false;
    bool m_readAfterConnect = false;
};

} // namespace stepcom
