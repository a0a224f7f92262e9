#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

// One line, three controllers (ids 1, 2, 3): the session polls them fairly, shows any of them
// without reconnecting, and its E-STOP reaches every one.
class TestDeviceBus : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    QList<Request> sent; // every request the link put on the wire, in order

    SimHost *host() const { return test::simHost(*session); }
    ModbusLink *link() const { return SessionInternals::link(*session); }
    int unitOf(const Request &r) const
    {
        return r.unitId > 0 ? r.unitId : link()->settings().deviceId;
    }
    void connectBus(const QList<int> &lineIds, const QList<int> &listIds)
    {
        test::useBuiltinSimulator(*session, lineIds);
        session->line()->setDeviceIds(listIds);
        session->line()->setBackgroundIntervalMs(400);
        test::connectToSimulator(*session);
        QCOMPARE(session->line()->deviceInView(), 1);
        connect(link(), &ModbusLink::dispatched, this,
                [this](quint64, const Request &r) { sent.append(r); });
    }
    // The ids the E-STOP coil frames on the wire were addressed to, in order.
    QList<int> estopFramesOnTheWire() const
    {
        const Parameter *estop = session->map().find(QStringLiteral("estop"));
        QList<int> ids;
        for (const TrafficEntry &e : link()->traffic()->entries()) {
            if (e.direction != TrafficEntry::Direction::Sent || e.bytes.size() < 4)
                continue;
            const int address = (quint8(e.bytes.at(2)) << 8) | quint8(e.bytes.at(3));
            if (quint8(e.bytes.at(1)) == 0x05 && address == estop->address)
                ids << quint8(e.bytes.at(0));
        }
        return ids;
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        sent.clear();
    }
    void cleanup() { session.reset(); }

    void pollingIsFairAcrossTheDevices()
    {
        connectBus({1, 2, 3}, {1, 2, 3});
        QTRY_VERIFY_WITH_TIMEOUT(session->line()->deviceStatus(2).cycles >= 3 &&
                                     session->line()->deviceStatus(3).cycles >= 3,
                                 15000);
        QCOMPARE(session->line()->deviceStatus(2).state, BusDeviceStatus::State::Answering);
        QCOMPARE(session->line()->deviceStatus(3).state, BusDeviceStatus::State::Answering);
        QCOMPARE(session->line()->deviceStatus(2).errors, 0);
        // Every status value of the background devices arrived.
        QCOMPARE(session->line()->deviceStatus(2).values.size(), session->status()->keys().size());
        // Counted on the link: round robin, so 2 and 3 are never more than one turn apart,
        // and the device in view (live rate) is read at least as often as either.
        QHash<int, int> reads;
        for (const Request &r : std::as_const(sent))
            if (r.priority == Priority::Poll)
                ++reads[unitOf(r)];
        QVERIFY2(reads.value(2) > 0 && reads.value(3) > 0, "both background devices polled");
        const int blocks = reads.value(2) / std::max(1, session->line()->deviceStatus(2).cycles);
        QVERIFY2(
            std::abs(reads.value(2) - reads.value(3)) <= blocks,
            qPrintable(QStringLiteral("2: %1, 3: %2").arg(reads.value(2)).arg(reads.value(3))));
        QVERIFY2(
            reads.value(1) >= reads.value(2),
            qPrintable(QStringLiteral("1: %1, 2: %2").arg(reads.value(1)).arg(reads.value(2))));
        QVERIFY(!reads.contains(4));
    }

    void emergencyStopReachesEveryControllerNext()
    {
        connectBus({1, 2, 3}, {1, 2, 3});
        for (SimDevice *d : host()->devices())
            QVERIFY(d->command(QStringLiteral("motor1.move")));
        QTRY_VERIFY(host()->deviceAt(3)->running(1));
        QSignalSpy finished(session.get(), &DeviceSession::emergencyStopFinished);
        sent.clear();
        session->emergencyStop();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QCOMPARE(finished.at(0).at(0).value<QList<int>>(), (QList<int>{1, 2, 3}));
        QCOMPARE(finished.at(0).at(1).value<QList<int>>(), QList<int>{});
        // Next on the wire, in the order of the list, before any poll.
        QVERIFY(sent.size() >= 3);
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(sent.at(i).priority, Priority::Emergency);
            QCOMPARE(unitOf(sent.at(i)), i + 1);
        }
        QCOMPARE(estopFramesOnTheWire(), (QList<int>{1, 2, 3}));
        for (SimDevice *d : host()->devices())
            QVERIFY(!d->running(1));
    }

    void emergencyStopSaysWhichDidNotAcknowledge()
    {
        connectBus({1, 2, 3}, {1, 2, 4, 3}); // nobody at id 4
        QSignalSpy finished(session.get(), &DeviceSession::emergencyStopFinished);
        QSignalSpy said(session.get(), &DeviceSession::message);
        session->emergencyStop();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(finished.at(0).at(0).value<QList<int>>(), (QList<int>{1, 2, 3}));
        QCOMPARE(finished.at(0).at(1).value<QList<int>>(), QList<int>{4});
        bool named = false;
        for (const QList<QVariant> &m : std::as_const(said))
            named =
                named || m.at(1).toString().contains(QStringLiteral("NOT acknowledged by id 4"));
        QVERIFY(named);
    }

    void showingAnotherDeviceNeedsNoReconnect()
    {
        connectBus({1, 2, 3}, {1, 2, 3});
        QVERIFY(host()->deviceAt(2)->setValue(QStringLiteral("motor1.speed"), 444));
        QSignalSpy connected(session->connection(), &SessionConnection::connected);
        QSignalSpy disconnected(session->connection(), &SessionConnection::disconnected);
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        QSignalSpy shown(session->line(), &SessionLine::deviceInViewChanged);
        QVERIFY(session->line()->showDevice(2));
        QCOMPARE(shown.size(), 1);
        QCOMPARE(session->line()->deviceInView(), 2);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QVERIFY(read.at(0).at(0).toBool());
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("motor1.speed")), 444);
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("device.id")), 2);
        QCOMPARE(connected.size(), 0);
        QCOMPARE(disconnected.size(), 0);
        QVERIFY(session->connection()->isConnected());
        // Device 1 is now in the background poll.
        QTRY_VERIFY_WITH_TIMEOUT(session->line()->deviceStatus(1).cycles >= 1, 10000);
        QVERIFY(!session->line()->showDevice(9));
        QCOMPARE(session->line()->deviceInView(), 2);
    }

    void aCommandGoesToTheDeviceThatWasInView()
    {
        connectBus({1, 2, 3}, {1, 2, 3});
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        session->command(QStringLiteral("motor1.move"));
        QVERIFY(session->line()->showDevice(3)); // before the pulse reached the wire
        QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 10000);
        QVERIFY(host()->deviceAt(1)->running(1));
        QVERIFY(!host()->deviceAt(3)->running(1));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDeviceBus, Guiless)
#include "tst_devicebus.moc"
