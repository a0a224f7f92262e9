#include "session/devicesession.h"
#include "device/readlimits.h"

#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/devicememory.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "i18n/translators.h"
#include "map/factoryvalues.h"
#include "motion/motionjudge.h"
#include "session/buspoller.h"
#include "session/idlist.h"
#include "session/jogcontroller.h"
#include "session/linkhealth.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/reconnector.h"
#include "session/sessionlog.h"
#include "session/simulatorstarter.h"
#include "session/stepmove.h"

#include <algorithm>
#include <memory>

namespace stepcom {

DeviceSession::DeviceSession(const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_link(new ModbusLink(this))
    , m_connection(new SessionConnection(this))
    , m_line(new SessionLine(this))
    , m_client(new DeviceClient(m_link, map, this))
    , m_store(new ParameterStore(map, this))
    , m_parameters(new SessionParameters(this, m_store))
    , m_poller(new Poller(m_client, m_store, this))
    , m_status(new SessionStatus(m_poller, m_store, this))
    , m_motion(new MotionSupervisor(this, m_link)) // before the jog controller, which follows it
    , m_health(new LinkHealth(m_link, this))
    , m_jog(new JogController(this, this))
    , m_step(new StepMove(this))
    , m_risks(new SessionRisks(m_line, this))
    , m_bus(new BusPoller(m_link, map, this))
    , m_memory(new DeviceMemory)
{
    // The outcome is said when the controller showed it, not when the command went out.
    connect(m_motion, &MotionSupervisor::deviceFinished, this,
            [this](int id, const MotionOutcome &o) {
                const QString text = m_motion->text(o);
                say(o.ok() ? Severity::Info : Severity::Warning,
                    m_line->deviceIds().size() > 1 ? tr("Device %1: %2").arg(id).arg(text) : text);
            });
    m_poller->useStatusKeys(); // the full status; positions and running while a motor runs
    m_poller->setIntervalMs(Poller::intervalFromEnvironment(100));
    m_bus->setKeys(m_poller->keys());
    watchRestarts(); // sees each status before the motion supervisor judges a motion from it
    connect(m_bus, &BusPoller::statusChanged, m_line, &SessionLine::deviceStatusChanged);
    m_link->traffic()->setMap(&m_client->map());
    connect(m_link, &ModbusLink::opened, this, &DeviceSession::onOpened);
    connect(m_link, &ModbusLink::stateChanged, m_connection, &SessionConnection::linkStateChanged);
    connect(m_link, &ModbusLink::statsChanged, m_connection, &SessionConnection::linkStatsChanged);
    connect(m_link, &ModbusLink::echoDetected, m_connection, &SessionConnection::echoSuspected);
    connect(m_health, &LinkHealth::stateChanged, this, [this](LinkHealth::State s) {
        if (s == LinkHealth::State::NotAnswering)
            say(Severity::Warning, tr("The port is open, but the controller at %1 does not "
                                      "answer.")
                                       .arg(m_link->settings().describe()));
        else if (s == LinkHealth::State::Answering)
            say(Severity::Info, tr("The controller answers."));
        Q_EMIT m_connection->linkStateChanged();
    });
    connect(m_link, &ModbusLink::lost, this, &DeviceSession::onLost);
    connect(m_poller, &Poller::cycleFinished, this, [this](bool ok, qint64 ms) {
        Q_EMIT m_status->statusCycleFinished(ok, ms);
        if (std::exchange(m_readAllAfterStatus, false))
            m_parameters->readAll();
    });
    const auto learn = [this](int unit, ReadLimits::Lesson lesson, const QString &key) {
        learnt(unit, int(lesson), key);
    };
    connect(m_client, &DeviceClient::readLimitsLearned, this, learn);
    // The background poll plans with, and learns into, the same per-id limits.
    m_client->shareReadLimits(m_bus->client());
    connect(m_bus->client(), &DeviceClient::readLimitsLearned, this, learn);
    connect(m_poller, &Poller::cycleFinished, this, [this](bool ok) {
        m_bus->noteLiveCycle(m_line->deviceInView(), ok, *m_store, m_poller->lastError());
    });
    m_reconnector = new Reconnector(this);
    connect(m_reconnector, &Reconnector::reopen, this, &DeviceSession::reopen);
    connect(m_reconnector, &Reconnector::restored, this,
            [this](const LinkSettings &s, int attempts) {
                say(Severity::Info, tr("The link is back at %1 (attempt %2): reading the status, "
                                       "then everything")
                                        .arg(s.describe())
                                        .arg(attempts));
            });
    connect(m_reconnector, &Reconnector::cancelled, this, [this] {
        say(Severity::Info, tr("Reconnecting cancelled: Connect tries again."));
        Q_EMIT m_connection->linkStateChanged();
    });
}

DeviceSession::~DeviceSession()
{
    delete m_jog; // a jog still held sends its stop while the link is there
    m_jog = nullptr;
    delete m_link; // before the simulator it may be talking to
    m_link = nullptr;
    delete m_memory;
}

const RegisterMap &DeviceSession::map() const
{
    return m_store->map();
}

void DeviceSession::setSimulator(std::unique_ptr<SimulatorStarter> simulator)
{
    if (m_sim && m_sim->isRunning()) {
        if (m_usingSim)
            m_link->close(tr("the built-in simulator was replaced"));
        m_sim->stop();
    }
    m_usingSim = false;
    m_sim = std::move(simulator);
}

void DeviceSession::say(Severity severity, const QString &text)
{
    Q_EMIT message(severity, text);
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
    const int id =
        m_line->deviceInView(); // the pulse goes to this one, whatever is shown by the answer
    command(*p, [this, key, label, motion, id](const Result &r) {
        // A moving command is only acknowledged here; MotionSupervisor says how it ended.
        if (r.ok && r.roundTripMs >= kSlowAnswerMs)
            say(Severity::Info, tr("%1: done; the controller answered after %2 s")
                                    .arg(label)
                                    .arg(double(r.roundTripMs) / 1000.0, 0, 'f', 1));
        else if (r.ok)
            say(Severity::Info, motion ? tr("%1: sent").arg(label) : tr("%1: done").arg(label));
        else
            say(Severity::Error, r.errorText);
        if (r.ok && key == QLatin1String("save_to_flash"))
            m_store->setUnsavedToFlash(false);
        if (r.ok && key == QLatin1String("factory_reset")) {
            m_store->setUnsavedToFlash(true); // factory values are in RAM; flash keeps the old ones
            m_parameters->readAll([this](const ReadOutcome &all) { factoryResetReadBack(all); });
        }
        if (r.ok)
            m_motion->commandAcknowledged(id, key);
        Q_EMIT commandFinished(key, r.ok);
    });
}

void DeviceSession::command(const Parameter &coil, std::function<void(const Result &)> done)
{
    m_client->command(coil, std::move(done));
}

void DeviceSession::emergencyStop()
{
    Q_EMIT emergencyStopRequested();
    if (!m_link->isConnected()) {
        if (m_reconnector->isActive()) {
            m_estopPending = true;
            say(Severity::Error, tr("E-STOP: the link is down, the controller did NOT get it; "
                                    "it is sent first when the link is back"));
            return;
        }
        say(Severity::Warning, tr("E-STOP: not connected, nothing was sent"));
        return;
    }
    // Anything still waiting (polls, reads, queued moves) is stale after an emergency stop.
    m_link->cancelQueued(Priority::Command, tr("emergency stop"));
    const QList<int> ids = m_line->deviceIds();
    if (ids.size() > 1) {
        emergencyStopAll(ids);
        return;
    }
    say(Severity::Warning, tr("E-STOP sent"));
    command(QStringLiteral("estop"));
}

void DeviceSession::setTravelLimits(const TravelLimits &limits)
{
    if (limits == m_limits)
        return;
    m_limits = limits;
    Q_EMIT travelLimitsChanged();
}

SessionLog *DeviceSession::log()
{
    if (!m_log)
        m_log = new SessionLog(this, this);
    return m_log;
}

void DeviceSession::guardedCommand(Risk risk, const QString &key)
{
    m_risks->guard(risk, [this, key](const QString &refusal) {
        if (refusal.isEmpty()) {
            command(key);
            return;
        }
        say(Severity::Error, refusal);
        Q_EMIT commandFinished(key, false);
    });
}

void DeviceSession::emergencyStopAll(const QList<int> &ids)
{
    const Parameter *estop = map().find(QStringLiteral("estop"));
    if (!estop || !estop->isCoil()) {
        say(Severity::Error, tr("Unknown command %1").arg(QStringLiteral("estop")));
        return;
    }
    say(Severity::Warning, tr("E-STOP sent to %n controller(s): id %1", nullptr, int(ids.size()))
                               .arg(IdList::format(ids)));
    struct Tally
    {
        QList<int> acknowledged;
        QList<int> notAcknowledged;
        QStringList errors;
        int pending = 0;
    };
    auto tally = std::make_shared<Tally>();
    tally->pending = int(ids.size());
    // All at emergency priority, in the order of the list: each is next on the wire.
    for (int id : ids) {
        Request req = Request::coil(estop->address, true, Priority::Emergency);
        req.what = estop->key;
        req.unitId = id;
        m_link->submit(
            req,
            [this, id, ids, tally](const Result &r) {
                (r.ok ? tally->acknowledged : tally->notAcknowledged).append(id);
                if (!r.ok)
                    tally->errors << r.errorText;
                if (id == m_line->deviceInView() && r.ok)
                    Q_EMIT commandFinished(QStringLiteral("estop"), true);
                if (--tally->pending > 0)
                    return;
                auto inOrder = [&ids](QList<int> list) {
                    std::sort(list.begin(), list.end(),
                              [&ids](int a, int b) { return ids.indexOf(a) < ids.indexOf(b); });
                    return list;
                };
                const QList<int> ack = inOrder(tally->acknowledged);
                const QList<int> nack = inOrder(tally->notAcknowledged);
                if (nack.isEmpty())
                    say(Severity::Warning, tr("E-STOP acknowledged by every controller: id %1")
                                               .arg(IdList::format(ack)));
                else
                    say(Severity::Error,
                        tr("E-STOP NOT acknowledged by id %1 (%2); acknowledged by: %3")
                            .arg(IdList::format(nack), tally->errors.join(QLatin1String("; ")),
                                 ack.isEmpty() ? tr("none") : IdList::format(ack)));
                Q_EMIT emergencyStopFinished(ack, nack);
            },
            this);
    }
}

void DeviceSession::saveToFlash()
{
    guardedCommand(Risk::SaveToFlash, QStringLiteral("save_to_flash"));
}

void DeviceSession::factoryReset()
{
    guardedCommand(Risk::FactoryReset, QStringLiteral("factory_reset"));
}

void DeviceSession::factoryResetReadBack(const ReadOutcome &r)
{
    // What the controller holds now is shown, whatever it is; then compared with the factory.
    m_store->setDeviceValues(r.values);
    Q_EMIT m_parameters->readFinished(r.ok);
    if (!r.ok) {
        say(Severity::Error, tr("Factory reset: reading it back failed: %1")
                                 .arg(r.errors.join(QLatin1String("; "))));
        return;
    }
    const QString locale = Translators::current();
    const QHash<QString, qint64> factory = FactoryValues::writable(map());
    QStringList differ;
    for (const Parameter *p : map().holdings()) {
        const auto is = r.values.constFind(p->key);
        if (!factory.contains(p->key) || is == r.values.cend() || *is == factory.value(p->key))
            continue;
        differ << QStringLiteral("%1 %2 (factory %3)")
                      .arg(p->key, p->displayRaw(*is, locale),
                           p->displayRaw(factory.value(p->key), locale));
    }
    if (differ.isEmpty())
        say(Severity::Info, tr("Factory reset: read back, every value is the factory value."));
    else
        say(Severity::Warning, tr("Factory reset: read back; %n value(s) differ from the factory "
                                  "values StepCom knows (another firmware's defaults?): %1",
                                  nullptr, int(differ.size()))
                                   .arg(differ.join(QLatin1String(", "))));
}

void DeviceSession::updateBackground()
{
    QList<int> others = m_line->deviceIds();
    others.removeAll(m_line->deviceInView());
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
    m_parameters->readAll();
    m_poller->start();
    updateBackground();
    m_bus->start();
}

int DeviceSession::stopJogging(JogStop why)
{
    switch (why) {
    case JogStop::PageLeft:
        return m_jog->stopAll(tr("the page was left"), true);
    case JogStop::FocusLost:
        return m_jog->stopAll(tr("the window lost focus"), true);
    case JogStop::WindowClosing:
        return m_jog->stopAll(tr("the window closes"));
    }
    return 0;
}

} // namespace stepcom
