#pragma once

#include "session/busdevicestatus.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace stepcom {

class DeviceClient;
class ModbusLink;
class ParameterStore;
class RegisterMap;

// The slow status poll of the controllers on the line that are not in view: one device's
// status per turn, round robin, each refreshed once per interval; the next turn is armed only
// when the last one ended. Its reads queue at poll priority on the shared link, so they take
// turns with the device in view's live poll and never delay a command or an E-STOP.
class BusPoller : public QObject
{
    Q_OBJECT
public:
    BusPoller(ModbusLink *link, const RegisterMap &map, QObject *parent = nullptr);

    void setKeys(const QStringList &keys) { m_keys = keys; }
    // The devices to poll, in the order of the list (the device in view is not among them).
    void setDevices(const QList<int> &ids);
    QList<int> devices() const { return m_ids; }
    // How often each background device's status is read (at least every 50 ms; 0: as fast as
    // the link allows, each turn armed as the last one ends).
    void setIntervalMs(int ms);
    int intervalMs() const { return m_intervalMs; }

    void start();
    void stop();
    bool isActive() const { return m_active; }

    BusDeviceStatus status(int id) const;
    DeviceClient *client() const { return m_client; }
    // Keeps what is known of a device that leaves or joins the background poll.
    void setStatus(const BusDeviceStatus &status) { m_status.insert(status.id, status); }
    // The device in view is polled live, not here: its cycles are counted with the others'
    // (state, failed reads, the status values the store holds after it).
    void noteLiveCycle(int id, bool ok, const ParameterStore &store, const QString &error);

Q_SIGNALS:
    void statusChanged(int id);

private:
    void turn();
    void arm();

    DeviceClient *m_client;
    QStringList m_keys;
    QList<int> m_ids;
    QHash<int, BusDeviceStatus> m_status;
    QTimer m_timer;
    int m_intervalMs = 1000;
    int m_next = 0;
    bool m_active = false;
    bool m_busy = false;
    quint64 m_generation = 0; // a turn's answer after stop()/setDevices() is dropped
};

} // namespace stepcom
