// DeviceSession, the line's side of the id assistant: probes at any id, the line's baud, and
// pausing the polls while ids move (split from devicesession.cpp along that seam).
#include "device/devicesession.h"

#include "bus/modbuslink.h"
#include "device/buspoller.h"
#include "device/poller.h"

#include <QTimer>

#include <memory>
#include <utility>

namespace stepcom {

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
