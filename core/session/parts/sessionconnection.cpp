// The session's link to its line. What the session does when the link opens or drops (reading,
// polling, the E-STOP held while it was down) stays in devicesessionconnect.cpp.
#include "session/parts/sessionconnection.h"

#include "bus/modbuslink.h"
#include "bus/wiretap.h"
#include "device/deviceclient.h"
#include "device/devicememory.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "session/buspoller.h"
#include "session/devicesession.h"
#include "session/reconnector.h"
#include "session/simulatorstarter.h"

namespace stepcom {

SessionConnection::SessionConnection(DeviceSession *session)
    : QObject(session)
    , m_session(session)
{}

void SessionConnection::connectTo(const LinkSettings &settings)
{
    DeviceSession &s = *m_session;
    s.m_reconnector->stop(); // the user chose: no attempt of the old line interferes
    if (s.m_usingSim && s.m_sim) {
        // leaving the built-in simulator: close our side first so its going away is no "loss"
        s.m_link->close(DeviceSession::tr("switching to %1").arg(settings.describe()));
        s.m_sim->stop();
    }
    s.m_usingSim = false;
    s.openLink(settings);
}

void SessionConnection::connectSimulator()
{
    DeviceSession &s = *m_session;
    s.m_reconnector->stop();
    QString error;
    std::optional<LinkSettings> opened;
    if (!s.m_sim)
        error = DeviceSession::tr("this program has no built-in simulator");
    else
        opened = s.m_sim->start(s.map(), &error);
    if (!opened) {
        s.say(DeviceSession::Severity::Error,
              DeviceSession::tr("Cannot start the built-in simulator: %1").arg(error));
        Q_EMIT connected(false, error);
        return;
    }
    s.m_usingSim = true; // before open(): on a pty the verdict arrives inside it
    s.openLink(*opened);
}

void SessionConnection::disconnectFrom(const QString &reason)
{
    DeviceSession &s = *m_session;
    const QString why = reason.isEmpty() ? DeviceSession::tr("disconnected by the user") : reason;
    s.m_reconnector->stop();
    s.m_resumeStatus = false;
    s.m_poller->stop();
    s.m_bus->stop();
    s.m_link->close(why);
    s.m_store->forgetDeviceValues();
    s.m_memory->forgetDeviceValues();
    Q_EMIT disconnected(why);
}

SessionConnection::LinkState SessionConnection::linkState() const
{
    switch (m_session->m_link->state()) {
    case ModbusLink::State::Connected:
        return LinkState::Connected;
    case ModbusLink::State::Connecting:
        return LinkState::Connecting;
    case ModbusLink::State::Disconnected:
        break;
    }
    return LinkState::Disconnected;
}

bool SessionConnection::isConnected() const
{
    return m_session->m_link->isConnected();
}

bool SessionConnection::isSimulator() const
{
    // connected(true) can arrive from inside connectSimulator(): recognise the simulator's port.
    const DeviceSession &s = *m_session;
    return s.m_usingSim ||
           (s.m_sim && s.m_sim->isRunning() && s.m_sim->serves(s.m_link->settings()));
}

LinkSettings SessionConnection::settings() const
{
    return m_session->m_link->settings();
}

LinkHealth *SessionConnection::health() const
{
    return m_session->m_health;
}

Reconnector *SessionConnection::reconnector() const
{
    return m_session->m_reconnector;
}

TrafficLog *SessionConnection::traffic() const
{
    return m_session->m_link->traffic();
}

const LinkStats &SessionConnection::linkStats() const
{
    return m_session->m_link->stats();
}

void SessionConnection::resetLinkStats()
{
    m_session->m_link->resetStats();
}

void SessionConnection::setLinkDiagnosticsShown(bool shown)
{
    WireTap::setPassThrough(shown);
}

const ReadLimits &SessionConnection::readLimits() const
{
    return m_session->m_client->readLimits();
}

QString SessionConnection::lineKey(const LinkSettings &settings)
{
    return settings.transport == LinkSettings::Transport::Tcp
               ? QStringLiteral("%1:%2").arg(settings.host).arg(settings.tcpPort)
               : settings.portName;
}

QMap<QString, QString> SessionConnection::knownReadLimits() const
{
    QMap<QString, QString> out;
    const auto &known = m_session->m_knownLimits;
    for (auto line = known.cbegin(); line != known.cend(); ++line) {
        for (auto id = line->cbegin(); id != line->cend(); ++id) {
            const QString text = id->toText();
            if (!text.isEmpty())
                out.insert(QStringLiteral("%1#%2").arg(line.key()).arg(id.key()), text);
        }
    }
    return out;
}

void SessionConnection::setKnownReadLimits(const QMap<QString, QString> &known)
{
    DeviceSession &s = *m_session;
    for (auto it = known.cbegin(); it != known.cend(); ++it) {
        const qsizetype hash = it.key().lastIndexOf(QLatin1Char('#'));
        bool isNumber = false;
        const int id = hash > 0 ? it.key().mid(hash + 1).toInt(&isNumber) : 0;
        if (!isNumber || id < 1 || id > 255)
            continue; // not written by us: nothing to learn from it
        const QString line = it.key().left(hash);
        ReadLimits limits = ReadLimits::fromText(it.value());
        if (limits.isEmpty() || !s.m_knownLimits.value(line).value(id).isEmpty())
            continue; // what this session learnt itself stands
        s.m_knownLimits[line].insert(id, limits);
        s.m_restored.insert(it.key());
    }
}

} // namespace stepcom
