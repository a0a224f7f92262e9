#include "benchrunner.h"

#include "windowprobe.h"

#include "bus/modbuslink.h"
#include "device/poller.h"
#include "device/readplanner.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h" // the link itself is what is measured
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

namespace stepcom::bench {

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point from, Clock::time_point to)
{
    return std::chrono::duration<double, std::milli>(to - from).count();
}

// Every request on a link: how many went out, and how long each poll took on the wire.
struct LinkWatch
{
    QHash<quint64, Clock::time_point> pollStarted;
    double longestPollMs = 0;
    int dispatched = 0;
    int pollsThisCycle = 0;
    int mostPollsInACycle = 0;
    QObject context; // the connections end with the watch

    explicit LinkWatch(DeviceSession &session)
    {
        ModbusLink *link = SessionInternals::link(session);
        QObject::connect(link, &ModbusLink::dispatched, &context,
                         [this](quint64 id, const Request &r) {
                             ++dispatched;
                             if (r.priority != Priority::Poll)
                                 return;
                             ++pollsThisCycle;
                             pollStarted.insert(id, Clock::now());
                         });
        QObject::connect(link, &ModbusLink::finished, &context,
                         [this](quint64 id, const Request &, const Result &result) {
                             const auto it = pollStarted.constFind(id);
                             if (it == pollStarted.cend())
                                 return;
                             if (result.ok)
                                 longestPollMs =
                                     std::max(longestPollMs, msBetween(*it, Clock::now()));
                             pollStarted.erase(it);
                         });
        QObject::connect(session.status(), &SessionStatus::statusCycleFinished, &context, [this] {
            mostPollsInACycle = std::max(mostPollsInACycle, pollsThisCycle);
            pollsThisCycle = 0;
        });
    }
};

QList<const Parameter *> parameters(const RegisterMap &map, const QStringList &keys)
{
    QList<const Parameter *> out;
    for (const QString &key : keys)
        out << map.find(key);
    return out;
}

void pause(int ms)
{
    waitUntil([] { return false; }, ms);
}

void measureStatus(DeviceSession &session, LinkWatch &watch, const BenchConfig &config,
                   BaudResult &r)
{
    waitUntil([&session] { return session.status()->stats().cycles >= 2; }, 5000); // warm up
    session.status()->resetStats();
    watch.mostPollsInACycle = 0;
    if (!waitUntil([&] { return session.status()->stats().cycles >= config.cycles; },
                   config.cycles * 2000 + 5000)) {
        r.error = QStringLiteral("(a): only %1 cycles").arg(session.status()->stats().cycles);
        return;
    }
    const PollStats &s = session.status()->stats();
    r.cycleMs.count = s.cycles;
    r.cycleMs.mean = s.meanMs();
    r.cycleMs.min = double(s.minMs);
    r.cycleMs.max = double(s.maxMs);
    r.fastCycles = s.fastCycles;
    r.readsPerCycle = watch.mostPollsInACycle;
    if (s.failed > 0)
        r.error = QStringLiteral("(a): %1 cycles failed: %2")
                      .arg(s.failed)
                      .arg(session.status()->error());
}

void measureReadAll(DeviceSession &session, LinkWatch &watch, const BenchConfig &config,
                    BaudResult &r)
{
    ModbusLink *link = SessionInternals::link(session);
    session.status()->stop(); // read-all alone on the line, as at connect
    waitUntil([link] { return !link->isBusy() && link->queuedCount() == 0; }, 5000);
    for (int i = 0; i < config.readAlls; ++i) {
        struct State
        {
            bool done = false;
            ReadOutcome outcome;
            double ms = 0;
            QElapsedTimer clock;
        };
        auto state = std::make_shared<State>();
        const int before = watch.dispatched;
        state->clock.start();
        session.parameters()->readAll([state](const ReadOutcome &o) {
            state->ms = double(state->clock.nsecsElapsed()) / 1e6;
            state->outcome = o;
            state->done = true;
        });
        if (!waitUntil([state] { return state->done; }, 10000) || !state->outcome.ok) {
            r.error = QStringLiteral("(b): read-all failed: %1")
                          .arg(state->outcome.errors.join(QLatin1String("; ")));
            break;
        }
        r.readAllMs.add(state->ms);
        r.readAllReads = std::max(r.readAllReads, watch.dispatched - before);
    }
    session.status()->start();
}

void measureEmergencyStop(DeviceSession &session, SimDevice *device, const BenchConfig &config,
                          BaudResult &r)
{
    const Parameter *estop = session.map().find(QStringLiteral("estop"));
    for (int round = 0; round < config.estopRounds; ++round) {
        device->setMachinePosition(1, 50.0);
        device->command(QStringLiteral("motor1.forward"));
        if (!waitUntil([&session] { return session.status()->isFast(); }, 3000)) {
            r.error = QStringLiteral("(c): the poller never saw the motor run");
            return;
        }
        pause(20 + (round * 37) % 120); // land at different points of a cycle
        if (!device->running(1)) {
            r.error = QStringLiteral("(c): the motor stopped on its own");
            return;
        }
        std::atomic<bool> watching{true};
        std::atomic<Clock::rep> stoppedAt{0};
        std::thread watcher([&] {
            while (watching) {
                if (!device->running(1)) {
                    stoppedAt = Clock::now().time_since_epoch().count();
                    return;
                }
                std::this_thread::sleep_for(std::chrono::microseconds(100));
            }
        });
        bool seen = false;
        bool next = false;
        Clock::time_point dispatchedAt;
        QObject context;
        QObject::connect(SessionInternals::link(session), &ModbusLink::dispatched, &context,
                         [&](quint64, const Request &req) {
                             if (std::exchange(seen, true))
                                 return;
                             dispatchedAt = Clock::now();
                             next = req.type == Request::Type::WriteCoil &&
                                    req.address == estop->address;
                         });
        const Clock::time_point requestedAt = Clock::now();
        session.emergencyStop();
        const bool ok = waitUntil([&] { return seen && stoppedAt != 0; }, 3000);
        watching = false;
        watcher.join();
        if (!ok) {
            r.error = QStringLiteral("(c): the emergency stop did not stop the simulator");
            return;
        }
        r.estopDispatchMs.add(msBetween(requestedAt, dispatchedAt));
        r.estopStoppedMs.add(
            msBetween(requestedAt, Clock::time_point(Clock::duration(stoppedAt.load()))));
        r.estopAlwaysNext = r.estopAlwaysNext && next;
        pause(50);
    }
}

} // namespace

bool waitUntil(const std::function<bool()> &done, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    QTimer tick; // something to wake up for even when nothing else happens
    tick.start(2);
    while (!done()) {
        if (clock.elapsed() >= timeoutMs)
            return false;
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    return true;
}

BaudResult measureBaud(int baud, const BenchConfig &config, int answerDelayMs, bool cyclesOnly)
{
    BaudResult r;
    r.baud = baud;
    const RegisterMap &map = RegisterMap::builtin();
    r.answerDelayMs = answerDelayMs >= 0 ? answerDelayMs : map.answerDelayMs();
    // The optimum for this controller's answer time: a faster one lowers it.
    const ReadCostModel model = ReadCostModel::forBaud(baud, r.answerDelayMs);
    const QList<ReadBlock> statusPlan = ReadPlanner::plan(parameters(map, Poller::statusKeys(map)),
                                                          map.maxRegistersPerRequest(), model);
    r.statusOptimumMs = ReadPlanner::costMs(statusPlan, model);
    r.statusOptimumReads = int(statusPlan.size());
    const QList<ReadBlock> allPlan =
        ReadPlanner::plan(map.holdings(), map.maxRegistersPerRequest(), model);
    r.readAllOptimumMs = ReadPlanner::costMs(allPlan, model);
    r.readAllOptimumReads = int(allPlan.size());
    r.estopFrameMs = (8 + 3.5) * model.charMs;

    SimHost host;
    SimOptions options;
    options.map = map;
    options.rtu = true;
    options.wireBaud = baud; // the simulator takes the bytes' time on a line at this baud
    options.answerDelayMs = r.answerDelayMs;
    QString error;
    if (!host.start(options, &error)) {
        r.error = error;
        return r;
    }
    host.device()->setValue(QStringLiteral("device.baud"), baud);

    DeviceSession session(map);
    session.status()->setIntervalMs(0); // full rate
    LinkWatch watch(session);
    bool read = false;
    QObject::connect(session.parameters(), &SessionParameters::readFinished, &session,
                     [&read] { read = true; });
    LinkSettings settings;
    settings.portName = host.rtuPath();
    settings.baud = baud;
    session.connection()->connectTo(settings);
    if (!waitUntil([&read] { return read; }, 10000) || !session.connection()->isConnected()) {
        r.error = QStringLiteral("cannot connect to the simulator at %1 baud").arg(baud);
        return r;
    }
    measureStatus(session, watch, config, r);
    if (r.error.isEmpty())
        measureReadAll(session, watch, config, r);
    if (cyclesOnly)
        return r;
    if (r.error.isEmpty())
        measureEmergencyStop(session, host.device(), config, r);
    r.longestPollMs = watch.longestPollMs;
    session.connection()->disconnectFrom(); // the window takes the line now
    if (r.error.isEmpty() && !config.stepcomPath.isEmpty()) {
        host.device()->command(QStringLiteral("estop"));
        r.window = measureWindow(config, &host, baud);
    }
    return r;
}

GapResult measureGapRefusing(int baud, const BenchConfig &config)
{
    GapResult g;
    BaudResult &r = g.r;
    r.baud = baud;
    const RegisterMap &map = RegisterMap::builtin();
    SimHost host;
    SimOptions options;
    options.map = map;
    options.rtu = true;
    options.wireBaud = baud;
    options.strictReads = true; // exception 02 to any read covering an unlisted register
    QString error;
    if (!host.start(options, &error)) {
        r.error = error;
        return g;
    }
    host.device()->setValue(QStringLiteral("device.baud"), baud);

    DeviceSession session(map);
    session.status()->setIntervalMs(0); // full rate
    LinkWatch watch(session);
    bool read = false;
    bool readOk = false;
    QObject::connect(session.parameters(), &SessionParameters::readFinished, &session,
                     [&](bool ok) {
                         read = true;
                         readOk = ok;
                     });
    LinkSettings settings;
    settings.portName = host.rtuPath();
    settings.baud = baud;
    session.connection()->connectTo(settings);
    // The warm-up: the first status cycle is refused, the gaps are learnt, read-all follows.
    if (!waitUntil([&read] { return read; }, 10000) || !session.connection()->isConnected() ||
        !readOk) {
        r.error = QStringLiteral("(i): the first read-all on a gap-refusing controller failed");
        return g;
    }
    g.learnt = session.connection()->readLimits().gapFree();
    if (!g.learnt) {
        r.error = QStringLiteral("(i): the session did not learn that gaps are refused");
        return g;
    }
    // The plans the client makes now, costed by the wire-time model as (a) and (b) are.
    const DeviceClient *client = SessionInternals::client(session);
    const ReadCostModel model = ReadCostModel::forBaud(baud, map.answerDelayMs());
    const QList<ReadBlock> statusPlan = client->planRead(parameters(map, Poller::statusKeys(map)));
    r.statusOptimumMs = ReadPlanner::costMs(statusPlan, model);
    r.statusOptimumReads = int(statusPlan.size());
    const QList<ReadBlock> allPlan = client->planRead(map.holdings());
    r.readAllOptimumMs = ReadPlanner::costMs(allPlan, model);
    r.readAllOptimumReads = int(allPlan.size());
    measureStatus(session, watch, config, r);
    if (r.error.isEmpty())
        measureReadAll(session, watch, config, r);
    session.connection()->disconnectFrom();
    return g;
}

} // namespace stepcom::bench
