// BusPoller with a reader of its own (no link): the turns in rounds, as stepcomctl's monitor of
// several devices takes them, what it counts of each device, and an answer after stop() dropped.
#include "device/deviceclient.h"
#include "map/registermap.h"
#include "session/buspoller.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

class TestBusPoller : public QObject
{
    Q_OBJECT

    struct Turn
    {
        int id = 0;
        QStringList keys;
        std::function<void(const ReadOutcome &)> done;
    };

    // A reader that keeps each turn for the test to answer.
    static BusPoller::Reader keeping(QList<Turn> *turns)
    {
        return [turns](int id, const QList<const Parameter *> &params,
                       std::function<void(const ReadOutcome &)> done) {
            Turn t{id, {}, std::move(done)};
            for (const Parameter *p : params)
                t.keys << p->key;
            turns->append(std::move(t));
        };
    }

    static ReadOutcome answered(qint64 position)
    {
        ReadOutcome r;
        r.ok = true;
        r.values.insert(QStringLiteral("motor1.position"), position);
        return r;
    }

    static ReadOutcome failed(const QStringList &errors)
    {
        ReadOutcome r;
        r.errors = errors;
        return r;
    }

private Q_SLOTS:
    void roundsTakeEachDeviceInTheOrderGiven()
    {
        const RegisterMap &map = RegisterMap::builtin();
        QList<Turn> turns;
        BusPoller poller(map, keeping(&turns));
        poller.setKeys({QStringLiteral("motor1.position"), QStringLiteral("no.such.key")});
        poller.setPacing(BusPoller::Pacing::Rounds);
        poller.setIntervalMs(0);
        poller.setDevices({3, 1, 2});
        QSignalSpy changed(&poller, &BusPoller::statusChanged);
        poller.start();
        QList<int> order;
        for (int i = 0; i < 6; ++i) {
            // One turn at a time: the next one only once this one was answered.
            QVERIFY(QTest::qWaitFor([&] { return turns.size() == i + 1; }, 10000));
            QCOMPARE(turns.size(), i + 1);
            const Turn t = turns.at(i);
            QCOMPARE(t.keys, QStringList{QStringLiteral("motor1.position")}); // known keys only
            order << t.id;
            t.done(t.id == 1 ? failed({QStringLiteral("timeout"), QStringLiteral("again")})
                             : answered(100 * i));
        }
        QCOMPARE(order, (QList<int>{3, 1, 2, 3, 1, 2}));
        QCOMPARE(changed.size(), 6);
        const BusDeviceStatus two = poller.status(2);
        QCOMPARE(two.cycles, 2);
        QCOMPARE(two.errors, 0);
        QCOMPARE(two.state, BusDeviceStatus::State::Answering);
        QCOMPARE(two.values.value(QStringLiteral("motor1.position")), 500);
        const BusDeviceStatus one = poller.status(1);
        QCOMPARE(one.cycles, 2);
        QCOMPARE(one.errors, 2);
        QCOMPARE(one.state, BusDeviceStatus::State::NotAnswering);
        QCOMPARE(one.lastError, QStringLiteral("timeout"));
        QVERIFY(poller.client() == nullptr); // it reads through the reader alone
    }

    void anAnswerAfterStopIsDropped()
    {
        const RegisterMap &map = RegisterMap::builtin();
        QList<Turn> turns;
        BusPoller poller(map, keeping(&turns));
        poller.setKeys({QStringLiteral("motor1.position")});
        poller.setPacing(BusPoller::Pacing::Rounds);
        poller.setDevices({1, 2});
        poller.start();
        QVERIFY(QTest::qWaitFor([&] { return !turns.isEmpty(); }, 10000));
        poller.stop();
        QSignalSpy changed(&poller, &BusPoller::statusChanged);
        turns.first().done(answered(7));
        QCOMPARE(changed.size(), 0);
        QCOMPARE(poller.status(1).cycles, 0);
        QCOMPARE(poller.status(1).state, BusDeviceStatus::State::Unknown);
    }

    // Rounds take the interval as it is asked for; the window's spread background never goes
    // below 50 ms a device.
    void theIntervalOfEachPacing()
    {
        BusPoller poller(RegisterMap::builtin(), [](int, const QList<const Parameter *> &,
                                                    std::function<void(const ReadOutcome &)>) {});
        poller.setIntervalMs(20);
        QCOMPARE(poller.intervalMs(), 50);
        poller.setPacing(BusPoller::Pacing::Rounds);
        QCOMPARE(poller.intervalMs(), 20);
        poller.setIntervalMs(0);
        QCOMPARE(poller.intervalMs(), 0);
        poller.setIntervalMs(-5);
        QCOMPARE(poller.intervalMs(), 0);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBusPoller, Guiless)
#include "tst_buspoller.moc"
