#pragma once

#include "bus/linksettings.h"        // LinkSettings, in signals
#include "session/busdevicestatus.h" // BusDeviceStatus

#include <QHash>
#include <QList>
#include <QObject>

#include <functional>

namespace stepcom {

class DeviceSession;
struct Parameter;
struct ParameterWrite;
struct ReadOutcome;
struct WriteOutcome;

// The devices of the session's line. Several controllers on one line (RS-485: one pair of
// wires, one id each): the link's device id is the device in view; the others' status is read
// at the background rate, and the session's emergencyStop() reaches every one. Empty or one id:
// a single controller. Owned by the DeviceSession that hands it out (line()).
class SessionLine : public QObject
{
    Q_OBJECT
public:
    explicit SessionLine(DeviceSession *session);

    void setDeviceIds(const QList<int> &ids);
    QList<int> deviceIds() const;
    int deviceInView() const;
    // Show another device of the list without reconnecting: a jog still held is stopped on the
    // device it runs on, what the store holds is put aside for the device that was in view and
    // `id`'s is put back at once (then read again), and the live poll moves to `id`. Motion
    // supervision and references stay per device (MotionSupervisor). False (and a message) when
    // `id` is not on the list or a step move still runs.
    bool showDevice(int id);
    // How often each device not in view has its status read.
    void setBackgroundIntervalMs(int ms);
    int backgroundIntervalMs() const;
    // What the status polls saw of a device, in view or not (Unknown before its first read).
    BusDeviceStatus deviceStatus(int id) const;
    // The device values known of any device of the line: the store's for the device in view,
    // else what was read while it was in view with the background poll's newer status on top.
    QHash<QString, qint64> knownValues(int id) const;
    // Read these parameters from the controller at `id`, whoever is in view; the store, the
    // view and the device list are left alone (probes while ids are given).
    void readAt(int id, const QList<const Parameter *> &params,
                std::function<void(const ReadOutcome &)> done);
    // Reopen the line at another baud without writing to any controller (serial lines only;
    // elsewhere `done(true)` at once): while ids are given, new controllers arrive at 9600 and
    // the ones already done listen at the common baud. `done` hears whether the port opened.
    void setLineBaud(int baud, std::function<void(bool ok, const QString &reason)> done);
    // Read or write a device of the line whether it is in view or not: the device in view goes
    // through the session's read()/write() (its store follows); another one through a client
    // addressed to its id, leaving the store alone. Link settings (device.id, device.baud) are
    // refused for a device not in view: the link cannot follow it there.
    void readDevice(int id, const QList<const Parameter *> &params,
                    std::function<void(const ReadOutcome &)> done);
    void writeDevice(int id, const QList<ParameterWrite> &writes,
                     std::function<void(const WriteOutcome &)> done);
    // The link as it reaches device `id` ("/dev/ttyUSB0 · 9600 8N1 · id 2").
    QString describeDevice(int id) const;
    // Write a new device id and/or baud to the device in view, follow the controller and verify
    // it answers there. On failure `linkChangeFailed` offers the settings that worked before.
    void changeLink(int deviceId, int baud);

Q_SIGNALS:
    void deviceInViewChanged(int id);
    void deviceStatusChanged(int id);
    // setDeviceIds() named other devices or another order.
    void deviceIdsChanged(const QList<int> &ids);
    void linkChanged(const stepcom::LinkSettings &settings);
    void linkChangeFailed(const stepcom::LinkSettings &previous, const QString &reason);

private:
    void writeLink(const QList<ParameterWrite> &writes, const LinkSettings &previous);

    DeviceSession *m_session;
};

} // namespace stepcom
