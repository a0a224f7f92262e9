#include "device/devicesession.h"

#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "device/linkhealth.h"
#include "device/motionjudge.h"
#include "device/motionsupervisor.h"
#include "i18n/translators.h"
#include "poll/poller.h"
#include "sim/simdevice.h"
#include "sim/simhost.h"

namespace stepcom {

DeviceSession::DeviceSession(const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_link(new ModbusLink(this))
    , m_client(new DeviceClient(m_link, map, this))
    , m_store(new ParameterStore(map, this))
    , m_poller(new Poller(m_client, m_store, this))
    , m_motion(nullptr)
    , m_health(new LinkHealth(m_link, this))
{
    m_motion = new MotionSupervisor(this); // after the link and the poller it follows
    // The outcome is said when the controller showed it, not when the command went out.
    connect(m_motion, &MotionSupervisor::finished, this, [this](const MotionOutcome &o) {
        say(o.ok() ? Severity::Info : Severity::Warning, m_motion->text(o));
    });
    m_poller->useStatusKeys(); // the full status; positions and running while a motor runs
    m_poller->setIntervalMs(Poller::intervalFromEnvironment(100));
    m_link->traffic()->setMap(&m_client->map());
    connect(m_link, &ModbusLink::opened, this, [this](bool ok, const QString &reason) {
        Q_EMIT connected(ok, reason);
        if (!ok) {
            say(Severity::Error, tr("Cannot connect: %1").arg(reason));
            return;
        }
        say(Severity::Info,
            tr("Opened %1; asking the controller").arg(m_link->settings().describe()));
        if (std::exchange(m_readAfterConnect, false))
            readAll();
        m_poller->start();
    });
    connect(m_link, &ModbusLink::stateChanged, this, &DeviceSession::linkStateChanged);
    connect(m_health, &LinkHealth::stateChanged, this, [this](LinkHealth::State s) {
        if (s == LinkHealth::State::NotAnswering)
            say(Severity::Warning, tr("The port is open, but the controller at %1 does not "
                                      "answer.")
                                       .arg(m_link->settings().describe()));
        else if (s == LinkHealth::State::Answering)
            say(Severity::Info, tr("The controller answers."));
        Q_EMIT linkStateChanged();
    });
    connect(m_link, &ModbusLink::lost, this, [this](const QString &reason) {
        m_poller->stop();
        m_store->forgetDeviceValues();
        say(Severity::Error, tr("Link lost: %1").arg(reason));
        Q_EMIT disconnected(reason);
    });
}

DeviceSession::~DeviceSession()
{
    delete m_link; // before the simulator it may be talking to
    m_link = nullptr;
}

bool DeviceSession::isConnected() const
{
    return m_link->isConnected();
}

LinkSettings DeviceSession::settings() const
{
    return m_link->settings();
}

void DeviceSession::say(Severity severity, const QString &text)
{
    Q_EMIT message(severity, text);
}

void DeviceSession::connectTo(const LinkSettings &settings)
{
    if (m_usingSim && m_sim) {
        // leaving the built-in simulator: close our side first so its going away is no "loss"
        m_link->close(tr("switching to %1").arg(settings.describe()));
        m_sim->stop();
    }
    m_usingSim = false;
    m_readAfterConnect = true;
    m_link->resetStats(); // statistics are per connection
    m_link->open(settings);
}

void DeviceSession::connectSimulator()
{
    if (!m_sim)
        m_sim = new SimHost(this);
    if (!m_sim->isRunning()) {
        SimOptions options;
        options.map = map();
#ifdef Q_OS_UNIX
        options.rtu = true;
#else
        options.tcp = true;
#endif
        QString error;
        if (!m_sim->start(options, &error)) {
            say(Severity::Error, tr("Cannot start the built-in simulator: %1").arg(error));
            Q_EMIT connected(false, error);
            return;
        }
    }
    LinkSettings s;
    if (!m_sim->rtuPath().isEmpty()) {
        s.transport = LinkSettings::Transport::Rtu;
        s.portName = m_sim->rtuPath();
        s.baud = m_sim->device() ? m_sim->device()->baud() : 9600;
        s.deviceId = m_sim->device() ? m_sim->device()->deviceId() : 1;
    } else {
        s.transport = LinkSettings::Transport::Tcp;
        s.host = m_sim->tcpAddress().toString();
        s.tcpPort = m_sim->tcpPort();
    }
    m_readAfterConnect = true;
    m_usingSim = true;    // before open(): on a pty the verdict arrives inside it
    m_link->resetStats(); // statistics are per connection
    m_link->open(s);
}

void DeviceSession::disconnectFrom()
{
    m_poller->stop();
    m_link->close(tr("disconnected by the user"));
    m_store->forgetDeviceValues();
    Q_EMIT disconnected(tr("disconnected by the user"));
}

void DeviceSession::readAll()
{
    m_client->readAll([this](const ReadOutcome &r) {
        m_store->setDeviceValues(r.values);
        if (!r.ok)
            say(Severity::Error, tr("Reading failed: %1").arg(r.errors.join(QLatin1String("; "))));
        else
            say(Severity::Info, tr("Read %1 in %2", "%1: n parameters, %2: n requests")
                                    .arg(tr("%n parameter(s)", nullptr, int(r.values.size())),
                                         tr("%n request(s)", nullptr, r.reads)));
        Q_EMIT readFinished(r.ok);
    });
}

void DeviceSession::writeChanges()
{
    write(m_store->pendingWrites());
}

void DeviceSession::write(const QList<ParameterWrite> &writes,
                          std::function<void(const WriteOutcome &)> done)
{
    if (writes.isEmpty())
        return;
    const LinkSettings before = m_link->settings();
    m_client->write(writes, [this, writes, before, done](const WriteOutcome &outcome) {
        m_store->applyWriteOutcome(writes, outcome);
        readBackUncertain(writes, outcome);
        if (outcome.ok) {
            say(Severity::Info,
                tr("Wrote and verified %n parameter(s)", nullptr, int(outcome.written.size())));
        } else {
            for (const QString &e : outcome.errors)
                say(Severity::Error, e);
        }
        // A write that carried device.id or device.baud (a profile applied with its link
        // settings) moved the link: tell the pages, as changeLink() does.
        const LinkSettings now = m_link->settings();
        if (now.deviceId != before.deviceId || now.baud != before.baud)
            Q_EMIT linkChanged(now);
        if (done)
            done(outcome);
        Q_EMIT writeFinished(outcome);
    });
}

void DeviceSession::readBackUncertain(const QList<ParameterWrite> &writes,
                                      const WriteOutcome &outcome)
{
    QList<const Parameter *> uncertain; // sent, but failed: the store forgot their value
    for (const ParameterWrite &w : writes) {
        const QString &key = w.parameter->key;
        bool mismatched = false;
        for (const WriteMismatch &m : outcome.mismatches)
            mismatched = mismatched || m.key == key;
        if (!outcome.written.contains(key) && !outcome.notWritten.contains(key) && !mismatched)
            uncertain << w.parameter;
    }
    if (uncertain.isEmpty() || !m_link->isConnected())
        return;
    m_client->read(uncertain, Priority::Command,
                   [this](const ReadOutcome &r) { m_store->setDeviceValues(r.values); });
}

void DeviceSession::command(const QString &key)
{
    const Parameter *p = map().find(key);
    if (!p || !p->isCoil()) {
        say(Severity::Error, tr("Unknown command %1").arg(key));
        Q_EMIT commandFinished(key, false);
        return;
    }
    const QString label = p->label.text(Translators::current());
    const bool motion = p->command == CommandClass::Motion;
    m_client->command(*p, [this, key, label, motion](const Result &r) {
        // A moving command is only acknowledged here; MotionSupervisor says how it ended.
        if (r.ok)
            say(Severity::Info, motion ? tr("%1: sent").arg(label) : tr("%1: done").arg(label));
        else
            say(Severity::Error, r.errorText);
        if (r.ok && key == QLatin1String("save_to_flash"))
            m_store->setUnsavedToFlash(false);
        if (r.ok && key == QLatin1String("factory_reset")) {
            m_store->setUnsavedToFlash(true); // factory values are in RAM; flash keeps the old ones
            readAll();                        // show what the controller holds now
        }
        Q_EMIT commandFinished(key, r.ok);
    });
}

void DeviceSession::emergencyStop()
{
    if (!m_link->isConnected()) {
        say(Severity::Warning, tr("E-STOP: not connected, nothing was sent"));
        return;
    }
    // Anything still waiting (polls, reads, queued moves) is stale after an emergency stop.
    m_link->cancelQueued(Priority::Command, tr("emergency stop"));
    say(Severity::Warning, tr("E-STOP sent"));
    command(QStringLiteral("estop"));
}

void DeviceSession::saveToFlash()
{
    command(QStringLiteral("save_to_flash"));
}

void DeviceSession::factoryReset()
{
    command(QStringLiteral("factory_reset"));
}

void DeviceSession::changeLink(int deviceId, int baud)
{
    const LinkSettings previous = m_link->settings();
    QList<ParameterWrite> writes;
    const Parameter *id = map().find(QStringLiteral("device.id"));
    const Parameter *rate = map().find(QStringLiteral("device.baud"));
    if (id && deviceId != previous.deviceId)
        writes.append({id, deviceId});
    if (rate && previous.transport == LinkSettings::Transport::Rtu && baud != previous.baud)
        writes.append({rate, baud});
    if (writes.isEmpty())
        return;
    m_client->write(writes, [this, writes, previous](const WriteOutcome &outcome) {
        m_store->applyWriteOutcome(writes, outcome);
        if (outcome.ok) {
            say(Severity::Info,
                tr("The controller answers at %1").arg(m_link->settings().describe()));
            Q_EMIT linkChanged(m_link->settings());
            return;
        }
        const QString reason = outcome.errors.join(QLatin1String("; "));
        say(Severity::Error,
            tr("The controller does not answer with the new settings: %1").arg(reason));
        Q_EMIT linkChangeFailed(previous, reason);
    });
}

} // namespace stepcom
