// DeviceSession: reading and writing a device of the line that may not be the one in view.
#include "session/devicesession.h"

#include "bus/modbuslink.h"
#include "device/devicememory.h"
#include "map/registermap.h"

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

void DeviceSession::readDevice(int id, const QList<const Parameter *> &params,
                               std::function<void(const ReadOutcome &)> done)
{
    if (id == deviceInView()) {
        read(params, std::move(done));
        return;
    }
    DeviceClient *client = clientFor(m_link, map(), id, this);
    client->read(params, Priority::Read, [client, done](const ReadOutcome &r) {
        client->deleteLater();
        done(r);
    });
}

void DeviceSession::writeDevice(int id, const QList<ParameterWrite> &writes,
                                std::function<void(const WriteOutcome &)> done)
{
    if (id == deviceInView()) {
        write(writes, std::move(done));
        return;
    }
    for (const ParameterWrite &w : writes) {
        const QString &key = w.parameter->key;
        if (key == QLatin1String("device.id") || key == QLatin1String("device.baud")) {
            WriteOutcome refused;
            for (const ParameterWrite &n : writes)
                refused.notWritten << n.parameter->key;
            refused.errors << tr("%1 of id %2 is written only while it is the device in view")
                                  .arg(key)
                                  .arg(id);
            done(refused);
            return;
        }
    }
    DeviceClient *client = clientFor(m_link, map(), id, this);
    client->write(writes, [this, id, writes, client, done](const WriteOutcome &w) {
        client->deleteLater();
        // What it acknowledged (and read back) is what it holds: known for a restart's check.
        QHash<QString, qint64> held;
        for (const ParameterWrite &pw : writes) {
            if (w.written.contains(pw.parameter->key))
                held.insert(pw.parameter->key, pw.raw);
        }
        m_memory->setDeviceValues(id, held);
        done(w);
    });
}

QString DeviceSession::describeDevice(int id) const
{
    LinkSettings s = m_link->settings();
    s.deviceId = id;
    return s.describe();
}

} // namespace stepcom
