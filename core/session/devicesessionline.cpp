// DeviceSession, the devices of the line: which one is in view, showing another, what is
// known of each (docs/architecture.md, "The line and its devices"); and the line's side of the
// id assistant: probes at any id, the line's baud, pausing the polls while ids move.
#include "session/devicesession.h"

#include "bus/modbuslink.h"
#include "device/devicememory.h"
#include "device/poller.h"
#include "session/buspoller.h"
#include "session/idlist.h"
#include "session/stepmove.h"

#include <QTimer>
#include <memory>
#include <utility>

namespace stepcom {

void DeviceSession::setDeviceIds(const QList<int> &ids)
{
    const bool changed = m_deviceIds != ids;
    m_deviceIds = ids;
    updateBackground();
    if (changed)
        Q_EMIT deviceIdsChanged(ids);
}

QList<int> DeviceSession::deviceIds() const
{
    if (m_deviceIds.isEmpty())
        return {deviceInView()};
    return m_deviceIds;
}

int DeviceSession::deviceInView() const
{
    return m_link->settings().deviceId;
}

bool DeviceSession::showDevice(int id)
{
    if (!deviceIds().contains(id)) {
        say(Severity::Error,
            tr("Device id %1 is not on this line (%2)").arg(id).arg(IdList::format(deviceIds())));
        return false;
    }
    if (id == deviceInView())
        return true;
    if (m_step->isBusy()) {
        // Its end restores the move settings it changed, on the device in view.
        say(Severity::Error, tr("A step move still runs on device %1: wait for its end or stop "
                                "it, then show device %2")
                                 .arg(deviceInView())
                                 .arg(id));
        return false;
    }
    stopJogging(JogStop::PageLeft); // its stops are addressed to the device they run on
    const bool polling = m_poller->isActive();
    m_poller->stop();
    m_bus->stop();
    // Reads queued for the device that was in view would land in the new one's store.
    m_link->cancelQueued(Priority::Read, tr("showing device %1").arg(id));
    m_memory->putAside(deviceInView(), *m_store);
    m_link->setDeviceId(id);
    m_memory->bringBack(id, *m_store, m_bus->status(id).values);
    m_store->setUnsupported(m_client->readLimits(id).unsupported());
    sayKnownLimits(id);
    updateBackground();
    Q_EMIT deviceInViewChanged(id);
    if (m_link->isConnected() && m_live) {
        readAll();
        if (polling)
            m_poller->start();
        m_bus->start();
    }
    return true;
}

void DeviceSession::setBackgroundIntervalMs(int ms)
{
    m_bus->setIntervalMs(ms);
}

int DeviceSession::backgroundIntervalMs() const
{
    return m_bus->intervalMs();
}

BusDeviceStatus DeviceSession::deviceStatus(int id) const
{
    return m_bus->status(id);
}

QHash<QString, qint64> DeviceSession::knownValues(int id) const
{
    if (id != deviceInView())
        return m_memory->values(id, m_bus->status(id).values);
    QHash<QString, qint64> values;
    for (const Parameter *p : map().holdings()) {
        if (const auto raw = m_store->deviceValue(p->key))
            values.insert(p->key, *raw);
    }
    return values;
}

void DeviceSession::updateBackground()
{
    QList<int> others = deviceIds();
    others.removeAll(deviceInView());
    m_bus->setDevices(others);
}

void DeviceSession::setLive(bool live)
{
    if (std::exchange(m_live, live) == live)
        return;
    if (!live) {
        m_poller->stop();
        m_bus->stop();
        return;
    }
    if (!m_link->isConnected())
        return;
    readAll();
    m_poller->start();
    updateBackground();
    m_bus->start();
}

void DeviceSession::readAt(int id, const QList<const Parameter *> &params,
                           std::function<void(const ReadOutcome &)> done)
{
    // A client of its own: the session's follows the device in view.
    auto *client = new DeviceClient(m_link, map(), this);
    client->setUnitId(id);
    client->read(params, Priority::Command, [client, done = std::move(done)](const ReadOutcome &r) {
        client->deleteLater();
        done(r);
    });
}

void DeviceSession::setLineBaud(int baud, std::function<void(bool ok, const QString &reason)> done)
{
    LinkSettings s = m_link->settings();
    if (s.transport != LinkSettings::Transport::Rtu || s.baud == baud || !m_link->isConnected()) {
        const bool ok = m_link->isConnected();
        const QString why = ok ? QString() : tr("the port is not open");
        QTimer::singleShot(0, this, [done = std::move(done), ok, why] { done(ok, why); });
        return;
    }
    s.baud = baud;
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection = connect(m_link, &ModbusLink::opened, this,
                          [connection, done = std::move(done)](bool ok, const QString &reason) {
                              QObject::disconnect(*connection);
                              done(ok, reason);
                          });
    m_link->open(s);
}

} // namespace stepcom
