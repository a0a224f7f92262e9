#include "busprobe.h"

#include "benchrunner.h"

#include "bus/modbuslink.h"
#include "device/poller.h"
#include "device/readplanner.h"
#include "session/buspoller.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h" // the link itself is what is measured
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QHash>

#include <atomic>
#include <chrono>
#include <memory>
#include <numeric>
#include <thread>

namespace stepcom::bench {

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point from, Clock::time_point to)
{
    return std::chrono::duration<double, std::milli>(to - from).count();
}

void pause(int ms)
{
    waitUntil([] { return false; }, ms);
}

QList<int> firstIds(int n)
{
    QList<int> ids(n);
    std::iota(ids.begin(), ids.end(), 1);
    return ids;
}

// A simulator serving `ids` on one pseudo-terminal with the wire-time model, and a session on it.
struct Line
{
    SimHost host;
    std::unique_ptr<DeviceSession> session;
    QString error;

    Line(int baud, const QList<int> &ids, bool live)
    {
        SimOptions options;
        options.rtu = true;
        options.wireBaud = baud;
        options.ids = ids;
        if (!host.start(options, &error))
            return;
        for (SimDevice *d : host.devices())
            d->setValue(QStringLiteral("device.baud"), baud);
        session = std::make_unique<DeviceSession>();
        session->setLive(live);
        session->line()->setDeviceIds(ids);
        session->status()->setIntervalMs(0); // full rate
        LinkSettings settings;
        settings.portName = host.rtuPath();
        settings.baud = baud;
        settings.deviceId = ids.first();
        bool opened = false;
        QObject::connect(
            session->connection(), &SessionConnection::connected, session.get(),
            [&opened] { opened = true; }, Qt::SingleShotConnection);
        session->connection()->connectTo(settings);
        if (!waitUntil([&opened] { return opened; }, 10000) ||
            !session->connection()->isConnected())
            error = QStringLiteral("cannot connect to the simulator at %1 baud").arg(baud);
    }
};

void measureRounds(int baud, const BenchConfig &config, BusResult &r)
{
    const QList<int> ids = firstIds(r.devices);
    Line line(baud, ids, false); // nothing polled but what is measured
    if (!line.error.isEmpty()) {
        r.error = line.error;
        return;
    }
    ModbusLink *link = SessionInternals::link(*line.session);
    BusPoller bus(link, line.session->map());
    bus.setKeys(line.session->status()->keys());
    bus.setDevices(ids);
    bus.setIntervalMs(0); // each turn armed as the last one ends
    int reads = 0;
    QObject context;
    QObject::connect(link, &ModbusLink::dispatched, &context, [&reads] { ++reads; });
    int rounds = 0;
    Clock::time_point roundStart;
    QObject::connect(&bus, &BusPoller::statusChanged, &context, [&](int id) {
        if (id != ids.last())
            return;
        const Clock::time_point now = Clock::now();
        if (rounds++ > 0) { // the first round is the warm-up
            r.roundMs.add(msBetween(roundStart, now));
            r.readsPerRound = std::max(r.readsPerRound, reads);
        }
        reads = 0;
        roundStart = now;
    });
    bus.start();
    if (!waitUntil([&] { return rounds > config.busRounds; }, config.busRounds * 5000 + 5000))
        r.error = QStringLiteral("(f): only %1 rounds").arg(rounds);
    bus.stop();
    for (int id : ids)
        if (bus.status(id).errors > 0)
            r.error = QStringLiteral("(f): device %1: %2").arg(id).arg(bus.status(id).lastError);
}

EstopAllResult measureEstopAll(int baud, int devices, const BenchConfig &config, QString *error)
{
    EstopAllResult e;
    e.devices = devices;
    const QList<int> ids = firstIds(devices);
    Line line(baud, ids, true); // the window's polling: live at full rate, the others behind
    if (!line.error.isEmpty()) {
        *error = line.error;
        return e;
    }
    DeviceSession &session = *line.session;
    session.line()->setBackgroundIntervalMs(500);
    ModbusLink *link = SessionInternals::link(session);
    const Parameter *estop = session.map().find(QStringLiteral("estop"));
    QHash<quint64, std::pair<Clock::time_point, bool>> started; // request id -> (when, E-STOP)
    QObject context;
    QObject::connect(link, &ModbusLink::dispatched, &context, [&](quint64 id, const Request &req) {
        const bool stop = req.type == Request::Type::WriteCoil && req.address == estop->address;
        if (stop || req.priority == Priority::Poll)
            started.insert(id, {Clock::now(), stop});
    });
    QObject::connect(link, &ModbusLink::finished, &context,
                     [&](quint64 id, const Request &, const Result &result) {
                         const auto it = started.constFind(id);
                         if (it == started.cend())
                             return;
                         const double ms = msBetween(it->first, Clock::now());
                         if (result.ok) {
                             double &longest = it->second ? e.longestEstopMs : e.longestPollMs;
                             longest = std::max(longest, ms);
                         }
                         started.erase(it);
                     });
    for (int round = 0; round < config.estopRounds; ++round) {
        for (SimDevice *d : line.host.devices()) {
            d->setMachinePosition(1, 50.0);
            d->command(QStringLiteral("motor1.forward"));
        }
        if (!waitUntil([&session] { return session.status()->isFast(); }, 3000)) {
            *error = QStringLiteral("(g): the poller never saw the motor run");
            return e;
        }
        pause(20 + (round * 37) % 120); // land at different points of a poll
        std::atomic<bool> watching{true};
        std::atomic<Clock::rep> stoppedAt{0};
        const QList<SimDevice *> sims = line.host.devices();
        std::thread watcher([&] {
            while (watching) {
                if (std::none_of(sims.cbegin(), sims.cend(),
                                 [](SimDevice *d) { return d->running(1); })) {
                    stoppedAt = Clock::now().time_since_epoch().count();
                    return;
                }
                std::this_thread::sleep_for(std::chrono::microseconds(100));
            }
        });
        QList<int> order; // the first requests after the call, by unit id
        Clock::time_point lastAt;
        QObject roundContext;
        QObject::connect(link, &ModbusLink::dispatched, &roundContext,
                         [&](quint64, const Request &req) {
                             if (order.size() >= devices)
                                 return;
                             const bool stop = req.type == Request::Type::WriteCoil &&
                                               req.address == estop->address;
                             order << (stop ? req.unitId : -1);
                             lastAt = Clock::now();
                         });
        bool finished = false;
        QObject::connect(&session, &DeviceSession::emergencyStopFinished, &roundContext,
                         [&](const QList<int> &, const QList<int> &nack) {
                             finished = true;
                             e.allAcknowledged = e.allAcknowledged && nack.isEmpty();
                         });
        const Clock::time_point requestedAt = Clock::now();
        session.emergencyStop();
        const bool ok = waitUntil([&] { return finished && stoppedAt != 0; }, 5000);
        watching = false;
        watcher.join();
        if (!ok) {
            *error = QStringLiteral("(g): the E-STOP did not stop every simulated controller");
            return e;
        }
        e.lastDispatchMs.add(msBetween(requestedAt, lastAt));
        e.allStoppedMs.add(
            msBetween(requestedAt, Clock::time_point(Clock::duration(stoppedAt.load()))));
        e.inOrderNext = e.inOrderNext && order == ids;
        pause(100);
    }
    return e;
}

} // namespace

BusResult measureBus(int baud, const BenchConfig &config)
{
    BusResult r;
    r.baud = baud;
    r.devices = 3;
    const RegisterMap &map = RegisterMap::builtin();
    const ReadCostModel model = ReadCostModel::forBaud(baud, map.answerDelayMs());
    QList<const Parameter *> status;
    for (const QString &key : Poller::statusKeys(map))
        status << map.find(key);
    const QList<ReadBlock> plan = ReadPlanner::plan(status, map.maxRegistersPerRequest(), model);
    r.cycleOptimumMs = r.devices * ReadPlanner::costMs(plan, model);
    r.cycleOptimumReads = r.devices * int(plan.size());
    measureRounds(baud, config, r);
    if (!r.error.isEmpty())
        return r;
    for (int devices : {2, 3, 8}) {
        QString error;
        EstopAllResult e = measureEstopAll(baud, devices, config, &error);
        if (!error.isEmpty()) {
            r.error = QStringLiteral("%1 controllers: %2").arg(devices).arg(error);
            return r;
        }
        // A write-coil request and its echo (8 characters each), the silence and the answer delay.
        e.modelEstopMs = (8 + 8 + 7) * model.charMs + model.answerDelayMs;
        e.frameMs = (8 + 3.5) * model.charMs;
        r.estops << e;
    }
    return r;
}

} // namespace stepcom::bench
