#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "scripteddevice.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <cstdlib>

using namespace stepcom;
using namespace stepcom::test;

namespace {

// Every poll request of a run: which block, and how many poll requests were out at once
// (queued or on the wire; a retry is the same request again).
struct PollWatch
{
    QList<std::pair<int, int>> blocks; // address, count, in dispatch order (a retry once)
    QList<Request> dispatched;         // every request, polls or not
    int maxOutstanding = 0;
    QSet<quint64> onWire;
    QSet<quint64> seen; // a request that timed out goes again under its own id
    QObject context;    // the connections end with the watch

    void attach(ModbusLink *link)
    {
        QObject::connect(
            link, &ModbusLink::dispatched, &context, [this, link](quint64 id, const Request &r) {
                dispatched << r;
                if (r.priority != Priority::Poll)
                    return;
                if (!seen.contains(id))
                    blocks << std::make_pair(int(r.address), int(r.count));
                seen.insert(id);
                onWire.insert(id);
                maxOutstanding = std::max(maxOutstanding, int(onWire.size()) + link->queuedCount());
            });
        QObject::connect(
            link, &ModbusLink::finished, &context,
            [this](quint64 id, const Request &, const Result &) { onWire.remove(id); });
    }
};

const std::pair<int, int> kPositions{107, 4};   // 40108-40111
const std::pair<int, int> kRunning{167, 2};     // 40168-40169
const std::pair<int, int> kStatusLow{107, 20};  // 40108-40127: positions .. inputs
const std::pair<int, int> kStatusHigh{147, 22}; // 40148-40169: outputs .. running

} // namespace

class TestPoller : public QObject
{
    Q_OBJECT

    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return test::simHost(*session)->device(); }

    // A session on the built-in simulator, polling as fast as the link allows.
    void connectFullRate()
    {
        session = std::make_unique<DeviceSession>();
        session->status()->setIntervalMs(0);
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        test::useBuiltinSimulator(*session);
        session->connection()->connectSimulator();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QTRY_VERIFY(session->status()->stats().cycles >= 2);
    }

private Q_SLOTS:
    void cleanup() { session.reset(); }

    void sessionPollsTheStatusAndMovesFastWithTheMotors()
    {
        const DeviceSession idle;
        const Poller *poller = SessionInternals::poller(idle);
        QCOMPARE(poller->keys().size(), 11);
        QCOMPARE(poller->fastKeys(), (QStringList{"motor1.position", "motor2.position",
                                                  "motor1.running", "motor2.running"}));
    }

    void intervalFromTheEnvironment()
    {
        qputenv("STEPCOM_POLL_INTERVAL_MS", "0");
        QCOMPARE(Poller::intervalFromEnvironment(100), 0);
        QCOMPARE(DeviceSession().status()->intervalMs(), 0);
        qputenv("STEPCOM_POLL_INTERVAL_MS", "fast");
        QCOMPARE(Poller::intervalFromEnvironment(100), 100);
        qputenv("STEPCOM_POLL_INTERVAL_MS", "-5");
        QCOMPARE(Poller::intervalFromEnvironment(100), 100);
        qunsetenv("STEPCOM_POLL_INTERVAL_MS");
        QCOMPARE(DeviceSession().status()->intervalMs(), 100);
    }

    // A silent device: each cycle waits for its timeouts, and no poll piles up behind them --
    // not even when the poller is stopped and started again while a request is out.
    void silentDeviceNeverBuildsAQueue_data()
    {
        QTest::addColumn<bool>("simulator");
        QTest::newRow("no answer at all") << false;
        QTest::newRow("simulator drops every answer") << true;
    }
    void silentDeviceNeverBuildsAQueue()
    {
        QFETCH(bool, simulator);
        ScriptedDevice scripted;
        SimHost host;
        LinkSettings s;
        QString error;
        if (simulator) {
            SimOptions options;
            options.rtu = true;
            options.faults.drop = 1.0;
            QVERIFY2(host.start(options, &error), qPrintable(error));
            s.portName = host.rtuPath();
        } else {
            QVERIFY2(scripted.open(&error), qPrintable(error));
            s.portName = scripted.clientPath();
        }
        s.timeoutMs = 100;
        s.retries = 1;
        ModbusLink link;
        link.setQuietTimeMs(20);
        DeviceClient client(&link, RegisterMap::builtin());
        ParameterStore store(RegisterMap::builtin());
        Poller poller(&client, &store);
        poller.useStatusKeys();
        poller.setIntervalMs(0);
        PollWatch watch;
        watch.attach(&link);
        QSignalSpy cycles(&poller, &Poller::cycleFinished);
        link.open(s);
        QTRY_VERIFY(link.isConnected());
        poller.start();
        QVERIFY(QTest::qWaitFor([&watch] { return !watch.onWire.isEmpty(); }, 5000));
        poller.stop(); // with a request out: the restart must wait for it
        poller.start();
        QTRY_VERIFY_WITH_TIMEOUT(cycles.size() >= 2, 5000);
        for (const QList<QVariant> &c : std::as_const(cycles))
            QVERIFY(!c.at(0).toBool());
        QVERIFY(!poller.lastError().isEmpty());
        QCOMPARE(watch.maxOutstanding, 1);
        // Each request waited for its timeout: two blocks, two attempts each per cycle.
        QVERIFY2(watch.blocks.size() <= 4 * (cycles.size() + 1),
                 qPrintable(QString::number(watch.blocks.size())));
        QVERIFY(store.deviceValue(QStringLiteral("motor1.position")) == std::nullopt);
    }

    void neverOverlapsAtFullRate()
    {
        connectFullRate();
        if (QTest::currentTestFailed())
            return;
        PollWatch watch;
        watch.attach(SessionInternals::link(*session));
        Poller *poller = SessionInternals::poller(*session);
        poller->resetStats();
        QTRY_VERIFY_WITH_TIMEOUT(poller->stats().cycles >= 6, 5000);
        QCOMPARE(watch.maxOutstanding, 1);
        QCOMPARE(poller->stats().failed, 0);
        QVERIFY(poller->rate() > 0.0);
        // Idle motors: every cycle is the full status, in its two planned reads.
        for (const auto &b : std::as_const(watch.blocks))
            QVERIFY(b == kStatusLow || b == kStatusHigh);
    }

    void intervalLimitsTheRate()
    {
        connectFullRate();
        if (QTest::currentTestFailed())
            return;
        Poller *poller = SessionInternals::poller(*session);
        QSignalSpy underWay(poller, &Poller::cycleFinished);
        poller->setIntervalMs(300);
        QVERIFY(underWay.wait(10000)); // the cycle under way ends: the next one waits
        // Cycles start no closer than the interval (a busy machine only spreads them further;
        // a coarse timer may fire 5 % early).
        QElapsedTimer clock;
        clock.start();
        QList<qint64> startedAt; // a cycle's end less its length
        connect(poller, &Poller::cycleFinished, this,
                [&startedAt, &clock](bool, qint64 ms) { startedAt << clock.elapsed() - ms; });
        QTRY_VERIFY_WITH_TIMEOUT(startedAt.size() >= 4, 10000);
        for (qsizetype i = 1; i < startedAt.size(); ++i)
            QVERIFY2(startedAt.at(i) - startedAt.at(i - 1) >= 270,
                     qPrintable(
                         QStringLiteral("%1 ms apart").arg(startedAt.at(i) - startedAt.at(i - 1))));
        disconnect(poller, &Poller::cycleFinished, this, nullptr);
    }

    void fastKeysWhileAMotorRuns()
    {
        connectFullRate();
        if (QTest::currentTestFailed())
            return;
        Poller *poller = SessionInternals::poller(*session);
        QVERIFY(!poller->isFast());
        PollWatch watch;
        watch.attach(SessionInternals::link(*session));
        QVERIFY(sim()->command(QStringLiteral("motor1.forward")));
        QTRY_VERIFY_WITH_TIMEOUT(poller->isFast(), 2000);
        watch.blocks.clear();
        poller->resetStats();
        QTRY_VERIFY_WITH_TIMEOUT(poller->stats().cycles >= 9, 5000);
        QVERIFY(sim()->running(1));
        // Fast cycles read positions and running flags only; every 4th is the full status.
        const int fast = int(watch.blocks.count(kPositions));
        const int full = int(watch.blocks.count(kStatusLow));
        const int running = int(watch.blocks.count(kRunning));
        const int high = int(watch.blocks.count(kStatusHigh));
        // The cycle under way when counting began may have had its first block read already
        // (its second is counted alone), the one under way when counting ends its first only.
        QVERIFY2(std::abs(fast - running) <= 1,
                 qPrintable(QStringLiteral("%1 positions, %2 running").arg(fast).arg(running)));
        QVERIFY2(std::abs(full - high) <= 1,
                 qPrintable(QStringLiteral("%1 low, %2 high").arg(full).arg(high)));
        QCOMPARE(fast + full + running + high, int(watch.blocks.size())); // nothing else read
        QVERIFY2(full >= 1 && fast >= 2 * full,
                 qPrintable(QStringLiteral("%1 fast, %2 full").arg(fast).arg(full)));
        QVERIFY(poller->stats().fastCycles >= 6);
        QCOMPARE(watch.maxOutstanding, 1);
        const qint64 before = session->parameters()
                                  ->store()
                                  ->deviceValue(QStringLiteral("motor1.position"))
                                  .value_or(0);
        QTRY_VERIFY(session->parameters()
                        ->store()
                        ->deviceValue(QStringLiteral("motor1.position"))
                        .value_or(0) > before);

        QVERIFY(sim()->command(QStringLiteral("motor1.stop")));
        QTRY_VERIFY_WITH_TIMEOUT(!poller->isFast(), 2000);
        watch.blocks.clear();
        poller->resetStats();
        QTRY_VERIFY_WITH_TIMEOUT(poller->stats().cycles >= 3, 5000);
        QCOMPARE(poller->stats().fastCycles, 0);
        QVERIFY(!watch.blocks.contains(kPositions));
    }

    void motionCommandSwitchesToFastAtOnce()
    {
        connectFullRate();
        if (QTest::currentTestFailed())
            return;
        Poller *poller = SessionInternals::poller(*session);
        QSignalSpy fast(poller, &Poller::fastChanged);
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        session->command(QStringLiteral("motor1.forward"));
        QTRY_COMPARE(done.size(), 1);
        const int cyclesAtAck = poller->stats().cycles;
        QTRY_VERIFY_WITH_TIMEOUT(!fast.isEmpty(), 2000);
        // at most the cycle under way when the answer came, then the fast one
        QVERIFY(poller->stats().cycles <= cyclesAtAck + 1);
        QCOMPARE(fast.first().at(0).toBool(), true);
        session->command(QStringLiteral("motor1.stop"));
        QTRY_VERIFY(!sim()->running(1));
    }

    // The emergency stop is the very next request on the wire after the poll in flight.
    void emergencyStopGoesNextWhilePollingAtFullRate()
    {
        connectFullRate();
        if (QTest::currentTestFailed())
            return;
        const Parameter *estop = session->map().find(QStringLiteral("estop"));
        QVERIFY(estop);
        PollWatch watch;
        watch.attach(SessionInternals::link(*session));
        for (int round = 0; round < 4; ++round) {
            QVERIFY(sim()->command(QStringLiteral("motor1.forward")));
            QTRY_VERIFY(sim()->running(1));
            // Land at different points of a cycle: after one more poll request each round.
            const qsizetype running = watch.dispatched.size();
            QVERIFY(QTest::qWaitFor([&] { return watch.dispatched.size() >= running + 1 + round; },
                                    10000));
            const qsizetype before = watch.dispatched.size();
            session->emergencyStop();
            QTRY_VERIFY(watch.dispatched.size() > before);
            const Request next = watch.dispatched.at(before);
            QCOMPARE(next.type, Request::Type::WriteCoil);
            QCOMPARE(int(next.address), int(estop->address));
            QTRY_VERIFY_WITH_TIMEOUT(!sim()->running(1), 1000);
        }
        QCOMPARE(watch.maxOutstanding, 1);
        QVERIFY(session->status()->isActive());
        QTRY_VERIFY(!session->status()->isFast());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestPoller, Guiless)
#include "tst_poller.moc"
