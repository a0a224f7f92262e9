#pragma once

#include "session/busdevicestatus.h"

#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <functional>

namespace stepcom {

class DeviceClient;
class ModbusLink;
class ParameterStore;
class RegisterMap;
struct Parameter;
struct ReadOutcome;

// The slow status poll of the controllers on the line that are not in view: one device's
// status per turn, round robin, each refreshed once per interval; the next turn is armed only
// when the last one ended. Its reads queue at poll priority on the shared link, so they take
// turns with the device in view's live poll and never delay a command or an E-STOP.
// stepcomctl's monitor of several devices takes its turns from here too, reading through its
// session (a Reader) and in rounds.
class BusPoller : public QObject
{
    Q_OBJECT
public:
    // How one turn reads device `id`'s status; `done` hears the outcome.
    using Reader = std::function<void(int id, const QList<const Parameter *> &params,
                                      std::function<void(const ReadOutcome &)> done)>;
    // When the turns come. Spread: one device every interval / devices, so each comes round
    // once per interval (the window's background). Rounds: the first turn at once, each next
    // device as the last one answered, the next round no sooner than the interval after the
    // last one began (a command line's sample of every device).
    enum class Pacing { Spread, Rounds };

    // Reads through a client of its own, addressed to each turn's device.
    BusPoller(ModbusLink *link, const RegisterMap &map, QObject *parent = nullptr);
    // Reads through `read` (client() is null); `map` must outlive the poller.
    BusPoller(const RegisterMap &map, Reader read, QObject *parent = nullptr);

    void setKeys(const QStringList &keys) { m_keys = keys; }
    // The devices to poll, in the order of the list (the window leaves the device in view out).
    void setDevices(const QList<int> &ids);
    QList<int> devices() const { return m_ids; }
    // How often each background device's status is read (spread: at least every 50 ms; 0: as
    // fast as the link allows, each turn armed as the last one ends).
    void setIntervalMs(int ms);
    int intervalMs() const;
    void setPacing(Pacing pacing) { m_pacing = pacing; }

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

    DeviceClient *m_client = nullptr;
    const RegisterMap *m_map;
    Reader m_read;
    QStringList m_keys;
    QList<int> m_ids;
    QHash<int, BusDeviceStatus> m_status;
    QTimer m_timer;
    QElapsedTimer m_round; // since the current round began (Pacing::Rounds)
    Pacing m_pacing = Pacing::Spread;
    int m_intervalMs = 1000;
    int m_next = 0;
    bool m_active = false;
    bool m_busy = false;
    quint64 m_generation = 0; // a turn's answer after stop()/setDevices() is dropped
};

} // namespace stepcom
