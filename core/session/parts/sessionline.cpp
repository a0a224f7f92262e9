// The devices of the session's line: which one is in view, showing another, what is known of
// each (docs/architecture.md, "The line and its devices"), reading and writing one that may not
// be in view; and the line's side of the id assistant: probes at any id, the line's baud, a new
// id or baud written to the controller in view.
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/devicememory.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "map/registermap.h"
#include "session/buspoller.h"
#include "session/devicesession.h"
#include "session/idlist.h"
#include "session/stepmove.h"

#include <QTimer>
#include <memory>
#include <utility>

namespace stepcom {

namespace {

// A client for one id, alive until its one operation has reported.
DeviceClient *clientFor(ModbusLink *link, const RegisterMap &map, int id, QObject *parent)
{
    auto *client = new DeviceClient(link, map, parent);
    client->setUnitId(id);
    return client;
}

} // namespace

SessionLine::SessionLine(DeviceSession *session)
    : QObject(session)
    , m_session(session)
{}

void SessionLine::setDeviceIds(const QList<int> &ids)
{
    const bool changed = m_session->m_deviceIds != ids;
    m_session->m_deviceIds = ids;
    m_session->updateBackground();
    if (changed)
        Q_EMIT deviceIdsChanged(ids);
}

QList<int> SessionLine::deviceIds() const
{
    if (m_session->m_deviceIds.isEmpty())
        return {deviceInView()};
    return m_session->m_deviceIds;
}

int SessionLine::deviceInView() const
{
    return m_session->m_link->settings().deviceId;
}

bool SessionLine::showDevice(int id)
{
    if (!deviceIds().contains(id)) {
        m_session->say(DeviceSession::Severity::Error,
                       DeviceSession::tr("Device id %1 is not on this line (%2)")
                           .arg(id)
                           .arg(IdList::format(deviceIds())));
        return false;
    }
    if (id == deviceInView())
        return true;
    if (m_session->m_step->isBusy()) {
        // Its end restores the move settings it changed, on the device in view.
        m_session->say(
            DeviceSession::Severity::Error,
            DeviceSession::tr("A step move still runs on device %1: wait for its end or stop "
                              "it, then show device %2")
                .arg(deviceInView())
                .arg(id));
        return false;
    }
    m_session->stopJogging(
        DeviceSession::JogStop::PageLeft); // its stops are addressed to the device they run on
    const bool polling = m_session->m_poller->isActive();
    m_session->m_poller->stop();
    m_session->m_bus->stop();
    // Reads queued for the device that was in view would land in the new one's store.
    m_session->m_link->cancelQueued(Priority::Read, DeviceSession::tr("showing device %1").arg(id));
    m_session->m_memory->putAside(deviceInView(), *m_session->m_store);
    m_session->m_link->setDeviceId(id);
    m_session->m_memory->bringBack(id, *m_session->m_store, m_session->m_bus->status(id).values);
    m_session->m_store->setUnsupported(m_session->m_client->readLimits(id).unsupported());
    m_session->sayKnownLimits(id);
    m_session->updateBackground();
    Q_EMIT deviceInViewChanged(id);
    if (m_session->m_link->isConnected() && m_session->m_live) {
        m_session->m_parameters->readAll();
        if (polling)
            m_session->m_poller->start();
        m_session->m_bus->start();
    }
    return true;
}

void SessionLine::setBackgroundIntervalMs(int ms)
{
    m_session->m_bus->setIntervalMs(ms);
}

int SessionLine::backgroundIntervalMs() const
{
    return m_session->m_bus->intervalMs();
}

BusDeviceStatus SessionLine::deviceStatus(int id) const
{
    return m_session->m_bus->status(id);
}

QHash<QString, qint64> SessionLine::knownValues(int id) const
{
    if (id != deviceInView())
        return m_session->m_memory->values(id, m_session->m_bus->status(id).values);
    QHash<QString, qint64> values;
    for (const Parameter *p : m_session->map().holdings()) {
        if (const auto raw = m_session->m_store->deviceValue(p->key))
            values.insert(p->key, *raw);
    }
    return values;
}

void SessionLine::readAt(int id, const QList<const Parameter *> &params,
                         std::function<void(const ReadOutcome &)> done)
{
    // A client of its own: the session's follows the device in view.
    auto *client = new DeviceClient(m_session->m_link, m_session->map(), this);
    client->setUnitId(id);
    client->read(params, Priority::Command, [client, done = std::move(done)](const ReadOutcome &r) {
        client->deleteLater();
        done(r);
    });
}

void SessionLine::setLineBaud(int baud, std::function<void(bool ok, const QString &reason)> done)
{
    LinkSettings s = m_session->m_link->settings();
    if (s.transport != LinkSettings::Transport::Rtu || s.baud == baud ||
        !m_session->m_link->isConnected()) {
        const bool ok = m_session->m_link->isConnected();
        const QString why = ok ? QString() : DeviceSession::tr("the port is not open");
        QTimer::singleShot(0, this, [done = std::move(done), ok, why] { done(ok, why); });
        return;
    }
    s.baud = baud;
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection = connect(m_session->m_link, &ModbusLink::opened, this,
                          [connection, done = std::move(done)](bool ok, const QString &reason) {
                              QObject::disconnect(*connection);
                              done(ok, reason);
                          });
    m_session->m_link->open(s);
}

void SessionLine::readDevice(int id, const QList<const Parameter *> &params,
                             std::function<void(const ReadOutcome &)> done)
{
    if (id == deviceInView()) {
        m_session->m_parameters->read(params, std::move(done));
        return;
    }
    DeviceClient *client = clientFor(m_session->m_link, m_session->map(), id, this);
    client->read(params, Priority::Read, [client, done](const ReadOutcome &r) {
        client->deleteLater();
        done(r);
    });
}

void SessionLine::writeDevice(int id, const QList<ParameterWrite> &writes,
                              std::function<void(const WriteOutcome &)> done)
{
    if (id == deviceInView()) {
        m_session->m_parameters->write(writes, std::move(done));
        return;
    }
    for (const ParameterWrite &w : writes) {
        const QString &key = w.parameter->key;
        if (key == QLatin1String("device.id") || key == QLatin1String("device.baud")) {
            WriteOutcome refused;
            for (const ParameterWrite &n : writes)
                refused.notWritten << n.parameter->key;
            refused.errors << DeviceSession::tr(
                                  "%1 of id %2 is written only while it is the device in view")
                                  .arg(key)
                                  .arg(id);
            done(refused);
            return;
        }
    }
    DeviceClient *client = clientFor(m_session->m_link, m_session->map(), id, this);
    client->write(writes, [this, id, writes, client, done](const WriteOutcome &w) {
        client->deleteLater();
        // What it acknowledged (and read back) is what it holds: known for a restart's check.
        QHash<QString, qint64> held;
        for (const ParameterWrite &pw : writes) {
            if (w.written.contains(pw.parameter->key))
                held.insert(pw.parameter->key, pw.raw);
        }
        m_session->m_memory->setDeviceValues(id, held);
        done(w);
    });
}

QString SessionLine::describeDevice(int id) const
{
    LinkSettings s = m_session->m_link->settings();
    s.deviceId = id;
    return s.describe();
}

void SessionLine::changeLink(int deviceId, int baud)
{
    const LinkSettings previous = m_session->m_link->settings();
    QList<ParameterWrite> writes;
    const Parameter *id = m_session->map().find(QStringLiteral("device.id"));
    const Parameter *rate = m_session->map().find(QStringLiteral("device.baud"));
    if (id && deviceId != previous.deviceId)
        writes.append({id, deviceId});
    if (rate && previous.transport == LinkSettings::Transport::Rtu && baud != previous.baud)
        writes.append({rate, baud});
    if (writes.isEmpty())
        return;
    const DeviceSession::Risk risk =
        writes.first().parameter == id ? DeviceSession::Risk::DeviceId : DeviceSession::Risk::Baud;
    m_session->m_risks->guard(risk, [this, writes, previous](const QString &refusal) {
        if (refusal.isEmpty()) {
            writeLink(writes, previous);
            return;
        }
        m_session->say(DeviceSession::Severity::Error, refusal);
        Q_EMIT linkChangeFailed(previous, refusal);
    });
}

void SessionLine::writeLink(const QList<ParameterWrite> &writes, const LinkSettings &previous)
{
    m_session->m_client->write(writes, [this, writes, previous](const WriteOutcome &outcome) {
        m_session->m_store->applyWriteOutcome(writes, outcome);
        if (outcome.ok) {
            m_session->say(DeviceSession::Severity::Info,
                           DeviceSession::tr("The controller answers at %1")
                               .arg(m_session->m_link->settings().describe()));
            Q_EMIT linkChanged(m_session->m_link->settings());
            return;
        }
        const QString reason = outcome.errors.join(QLatin1String("; "));
        m_session->say(DeviceSession::Severity::Error,
                       DeviceSession::tr("The controller does not answer with the new settings: %1")
                           .arg(reason));
        Q_EMIT linkChangeFailed(previous, reason);
    });
}

} // namespace stepcom
