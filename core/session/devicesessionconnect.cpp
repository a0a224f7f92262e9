// DeviceSession, its connection: connecting, reconnecting after a loss, and what each controller
// of the line refuses to read. (The devices of the line are in devicesessionline.cpp.)
#include "session/devicesession.h"

#include "bus/modbuslink.h"
#include "device/devicememory.h"
#include "device/poller.h"
#include "session/buspoller.h"
#include "session/reconnector.h"
#include "session/simulatorstarter.h"

namespace stepcom {

void DeviceSession::onOpened(bool ok, const QString &reason)
{
    const bool retry = m_reconnector->state() == Reconnector::State::Attempting;
    if (!ok && retry) {
        // One attempt of a reconnect: the countdown says it, not an error each time.
        m_reconnector->attemptFinished(false, reason);
        Q_EMIT linkStateChanged();
        return;
    }
    if (ok)
        m_reconnector->linkOpened(m_link->settings());
    // An E-STOP pressed while the link was down goes out before anything else; the jog
    // controller's due stops follow at the same priority from `connected`, then the reads.
    if (ok && std::exchange(m_estopPending, false))
        emergencyStop();
    Q_EMIT connected(ok, reason);
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
    Q_EMIT disconnected(reason);
    Q_EMIT linkLost(reason);
    m_reconnector->linkLost(m_link->settings(), reason);
    if (m_reconnector->isActive())
        say(Severity::Info, tr("Trying to connect again on its own (Cancel stops it)."));
    Q_EMIT linkStateChanged();
}

void DeviceSession::reopen(const LinkSettings &settings)
{
    // A port found again under another name keeps what its controllers refuse to read.
    const QString before = lineKey(m_link->settings());
    if (lineKey(settings) != before && !m_knownLimits.contains(lineKey(settings)))
        m_knownLimits.insert(lineKey(settings), m_knownLimits.value(before));
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

void DeviceSession::connectTo(const LinkSettings &settings)
{
    m_reconnector->stop(); // the user chose: no attempt of the old line interferes
    if (m_usingSim && m_sim) {
        // leaving the built-in simulator: close our side first so its going away is no "loss"
        m_link->close(tr("switching to %1").arg(settings.describe()));
        m_sim->stop();
    }
    m_usingSim = false;
    openLink(settings);
}

void DeviceSession::connectSimulator()
{
    m_reconnector->stop();
    QString error;
    std::optional<LinkSettings> s;
    if (!m_sim)
        error = tr("this program has no built-in simulator");
    else
        s = m_sim->start(map(), &error);
    if (!s) {
        say(Severity::Error, tr("Cannot start the built-in simulator: %1").arg(error));
        Q_EMIT connected(false, error);
        return;
    }
    m_usingSim = true; // before open(): on a pty the verdict arrives inside it
    openLink(*s);
}

QString DeviceSession::lineKey(const LinkSettings &settings)
{
    return settings.transport == LinkSettings::Transport::Tcp
               ? QStringLiteral("%1:%2").arg(settings.host).arg(settings.tcpPort)
               : settings.portName;
}

const ReadLimits &DeviceSession::readLimits() const
{
    return m_client->readLimits();
}

void DeviceSession::learnt(int unit, ReadLimits::Lesson lesson, const QString &key)
{
    m_knownLimits.insert(lineKey(m_link->settings()), m_client->allReadLimits());
    QString text;
    if (lesson == ReadLimits::Lesson::GapsRefused) {
        text = tr("The controller refuses reads that cover reserved registers; from now on only "
                  "its listed registers are read (a few more requests).");
    } else if (lesson == ReadLimits::Lesson::Unsupported) {
        const Parameter *p = m_client->map().find(key);
        text = tr("%1 (register %2) is not supported by this controller: it refuses to read it. "
                  "It is left out from now on.")
                   .arg(key, p ? p->registerName() : QString());
        if (unit == deviceInView())
            m_store->setUnsupported(m_client->readLimits(unit).unsupported());
    }
    if (text.isEmpty())
        return;
    if (deviceIds().size() > 1)
        text = tr("Device id %1: %2").arg(unit).arg(text);
    say(Severity::Warning, text);
    Q_EMIT readLimitsLearned(text);
}

QMap<QString, QString> DeviceSession::knownReadLimits() const
{
    QMap<QString, QString> out;
    for (auto line = m_knownLimits.cbegin(); line != m_knownLimits.cend(); ++line) {
        for (auto id = line->cbegin(); id != line->cend(); ++id) {
            const QString text = id->toText();
            if (!text.isEmpty())
                out.insert(QStringLiteral("%1#%2").arg(line.key()).arg(id.key()), text);
        }
    }
    return out;
}

void DeviceSession::setKnownReadLimits(const QMap<QString, QString> &known)
{
    for (auto it = known.cbegin(); it != known.cend(); ++it) {
        const qsizetype hash = it.key().lastIndexOf(QLatin1Char('#'));
        bool isNumber = false;
        const int id = hash > 0 ? it.key().mid(hash + 1).toInt(&isNumber) : 0;
        if (!isNumber || id < 1 || id > 255)
            continue; // not written by us: nothing to learn from it
        const QString line = it.key().left(hash);
        ReadLimits limits = ReadLimits::fromText(it.value());
        if (limits.isEmpty() || !m_knownLimits.value(line).value(id).isEmpty())
            continue; // what this session learnt itself stands
        m_knownLimits[line].insert(id, limits);
        m_restored.insert(it.key());
    }
}

void DeviceSession::sayKnownLimits(int id)
{
    const QString key = QStringLiteral("%1#%2").arg(lineKey(m_link->settings())).arg(id);
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
    m_client->setAllReadLimits(m_knownLimits.value(lineKey(settings)));
    m_store->setUnsupported(m_client->readLimits(settings.deviceId).unsupported());
    m_readAfterConnect = true;
    m_link->resetStats(); // statistics are per connection
    m_link->open(settings);
}

void DeviceSession::disconnectFrom(const QString &reason)
{
    const QString why = reason.isEmpty() ? tr("disconnected by the user") : reason;
    m_reconnector->stop();
    m_resumeStatus = false;
    m_poller->stop();
    m_bus->stop();
    m_link->close(why);
    m_store->forgetDeviceValues();
    m_memory->forgetDeviceValues();
    Q_EMIT disconnected(why);
}

} // namespace stepcom
