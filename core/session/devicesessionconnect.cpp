// DeviceSession, its connection: what it does when the link opens, drops or comes back, and
// what each controller of the line refuses to read (its part: parts/sessionconnection.cpp; the
// devices of the line: parts/sessionline.cpp).
#include "device/readlimits.h"
#include "session/devicesession.h"

#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/devicememory.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "session/buspoller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/reconnector.h"
#include "session/simulatorstarter.h"

namespace stepcom {

void DeviceSession::onOpened(bool ok, const QString &reason)
{
    const bool retry = m_reconnector->state() == Reconnector::State::Attempting;
    if (!ok && retry) {
        // One attempt of a reconnect: the countdown says it, not an error each time.
        m_reconnector->attemptFinished(false, reason);
        Q_EMIT m_connection->linkStateChanged();
        return;
    }
    if (ok)
        m_reconnector->linkOpened(m_link->settings());
    // An E-STOP pressed while the link was down goes out before anything else; the jog
    // controller's due stops follow at the same priority from `connected`, then the reads.
    if (ok && std::exchange(m_estopPending, false))
        emergencyStop();
    Q_EMIT m_connection->connected(ok, reason);
    if (!ok) {
        say(Severity::Error, tr("Cannot connect: %1").arg(reason));
        return;
    }
    say(Severity::Info, tr("Opened %1; asking the controller").arg(m_link->settings().describe()));
    sayKnownLimits(m_link->settings().deviceId);
    // Live values first: one status cycle (positions, inputs), then everything else.
    m_readAllAfterStatus = std::exchange(m_readAfterConnect, false) && m_live;
    if (m_live || std::exchange(m_resumeStatus, false)) {
        m_poller->start();
        if (m_live) {
            updateBackground();
            m_bus->start();
        }
    }
    if (retry)
        m_reconnector->attemptFinished(true, QString());
}

void DeviceSession::onLost(const QString &reason)
{
    m_resumeStatus = m_poller->isActive();
    m_poller->stop();
    m_bus->stop();
    m_store->forgetDeviceValues();
    m_memory->forgetDeviceValues();
    say(Severity::Error, tr("Link lost: %1").arg(reason));
    Q_EMIT m_connection->disconnected(reason);
    Q_EMIT m_connection->linkLost(reason);
    m_reconnector->linkLost(m_link->settings(), reason);
    if (m_reconnector->isActive())
        say(Severity::Info, tr("Trying to connect again on its own (Cancel stops it)."));
    Q_EMIT m_connection->linkStateChanged();
}

void DeviceSession::reopen(const LinkSettings &settings)
{
    // A port found again under another name keeps what its controllers refuse to read.
    const QString before = SessionConnection::lineKey(m_link->settings());
    if (SessionConnection::lineKey(settings) != before &&
        !m_knownLimits.contains(SessionConnection::lineKey(settings)))
        m_knownLimits.insert(SessionConnection::lineKey(settings), m_knownLimits.value(before));
    if (m_usingSim && m_sim) {
        QString error;
        const std::optional<LinkSettings> s = m_sim->start(map(), &error);
        if (!s) {
            m_reconnector->attemptFinished(false, error);
            return;
        }
        LinkSettings again = *s;
        again.deviceId = settings.deviceId;
        openLink(again);
        return;
    }
    openLink(settings);
}

void DeviceSession::learnt(int unit, int lesson, const QString &key)
{
    m_knownLimits.insert(SessionConnection::lineKey(m_link->settings()), m_client->allReadLimits());
    QString text;
    if (ReadLimits::Lesson(lesson) == ReadLimits::Lesson::GapsRefused) {
        text = tr("The controller refuses reads that cover reserved registers; from now on only "
                  "its listed registers are read (a few more requests).");
    } else if (ReadLimits::Lesson(lesson) == ReadLimits::Lesson::Unsupported) {
        const Parameter *p = m_client->map().find(key);
        text = tr("%1 (register %2) is not supported by this controller: it refuses to read it. "
                  "It is left out from now on.")
                   .arg(key, p ? p->registerName() : QString());
        if (unit == m_line->deviceInView())
            m_store->setUnsupported(m_client->readLimits(unit).unsupported());
    }
    if (text.isEmpty())
        return;
    if (m_line->deviceIds().size() > 1)
        text = tr("Device id %1: %2").arg(unit).arg(text);
    say(Severity::Warning, text);
    Q_EMIT m_connection->readLimitsLearned(text);
}

void DeviceSession::sayKnownLimits(int id)
{
    const QString key =
        QStringLiteral("%1#%2").arg(SessionConnection::lineKey(m_link->settings())).arg(id);
    if (!m_restored.remove(key))
        return;
    const ReadLimits &limits = m_client->readLimits(id);
    QStringList what;
    if (limits.gapFree())
        what << tr("it refuses reads that cover reserved registers, so only its listed "
                   "registers are read");
    if (!limits.unsupported().isEmpty()) {
        QStringList keys(limits.unsupported().cbegin(), limits.unsupported().cend());
        keys.sort();
        what << tr("it does not support %1").arg(keys.join(QLatin1String(", ")));
    }
    if (!what.isEmpty())
        say(Severity::Info, tr("Known from an earlier connection to this controller: %1.")
                                .arg(what.join(QLatin1String("; "))));
}

void DeviceSession::openLink(const LinkSettings &settings)
{
    m_client->setAllReadLimits(m_knownLimits.value(SessionConnection::lineKey(settings)));
    m_store->setUnsupported(m_client->readLimits(settings.deviceId).unsupported());
    m_readAfterConnect = true;
    m_link->resetStats(); // statistics are per connection
    m_link->open(settings);
}

} // namespace stepcom
