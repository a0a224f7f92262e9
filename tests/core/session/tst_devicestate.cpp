#include "bus/modbuslink.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/sessioninternals.h"
#include "session/stepmove.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

// Three controllers on one line: each keeps its own values, edits, motion supervision and
// references while another is in view, and showing one needs no reconnect.
class TestDeviceState : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    QList<Request> sent; // every request the link put on the wire, in order

    SimHost *host() const { return test::simHost(*session); }
    ModbusLink *link() const { return SessionInternals::link(*session); }
    std::optional<qint64> held(const char *key) const
    {
        return session->parameters()->store()->deviceValue(QLatin1String(key));
    }
    void connectBus()
    {
        test::useBuiltinSimulator(*session, {1, 2, 3});
        session->line()->setDeviceIds({1, 2, 3});
        session->line()->setBackgroundIntervalMs(300);
        test::connectToSimulator(*session);
        connect(link(), &ModbusLink::dispatched, this,
                [this](quint64, const Request &r) { sent.append(r); });
    }
    // Shows `id` and waits for its read-all.
    void show(int id)
    {
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        QVERIFY(session->line()->showDevice(id));
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QVERIFY(read.at(0).at(0).toBool());
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        sent.clear();
    }
    void cleanup() { session.reset(); }

    void eachDeviceKeepsItsValuesAndEdits()
    {
        connectBus();
        QVERIFY(host()->deviceAt(1)->setValue(QStringLiteral("motor1.speed"), 111));
        QVERIFY(host()->deviceAt(2)->setValue(QStringLiteral("motor1.speed"), 222));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QCOMPARE(held("motor1.speed"), 111);
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor2.speed"), 321).isEmpty());
        QSignalSpy connected(session->connection(), &SessionConnection::connected);
        QSignalSpy disconnected(session->connection(), &SessionConnection::disconnected);
        show(2);
        QCOMPARE(held("motor1.speed"), 222);
        QCOMPARE(held("device.id"), 2);
        // Device 1's edit stays with device 1: nothing typed for it can be written to 2.
        QVERIFY(!session->parameters()->store()->hasEdits());
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 999).isEmpty());
        // Back to 1: its values and its edit at once, before anything was read again.
        QVERIFY(session->line()->showDevice(1));
        QCOMPARE(held("motor1.speed"), 111);
        QCOMPARE(held("device.id"), 1);
        QCOMPARE(session->parameters()->store()->editedKeys(),
                 QStringList{QStringLiteral("motor2.speed")});
        QCOMPARE(*session->parameters()->store()->shownValue(QStringLiteral("motor2.speed")), 321);
        // And 2's edit is back with 2.
        QVERIFY(session->line()->showDevice(2));
        QCOMPARE(held("motor1.speed"), 222);
        QCOMPARE(*session->parameters()->store()->shownValue(QStringLiteral("motor1.speed")), 999);
        QCOMPARE(connected.size(), 0);
        QCOMPARE(disconnected.size(), 0);
        QVERIFY(session->connection()->isConnected());
        // Device 3 was never in view: its status is known from the background poll only.
        QTRY_VERIFY_WITH_TIMEOUT(session->line()->deviceStatus(3).cycles >= 1, 10000);
        QVERIFY(session->line()->showDevice(3));
        QVERIFY(held("motor1.position").has_value());
        QVERIFY(!held("motor1.speed").has_value()); // not read yet, so not shown as known
        QTRY_COMPARE_WITH_TIMEOUT(held("device.id"), 3, 10000);
    }

    void referencesStayWithTheirDevice()
    {
        connectBus();
        show(2);
        MotionSupervisor *motion = session->motion();
        session->command(QStringLiteral("motor1.home"));
        QTRY_VERIFY_WITH_TIMEOUT(motion->references()->isReferenced(1), 10000);
        QVERIFY(motion->references()->isReferencedOn(2, 1));
        QVERIFY(!motion->references()->isReferencedOn(1, 1));
        QSignalSpy refs(motion->references(), &ReferenceTracker::changed);
        show(3);
        QVERIFY(!refs.isEmpty()); // the pages hear that what they show changed
        QVERIFY(!motion->references()->isReferenced(1)); // device 3's motor 1
        QVERIFY(motion->references()->isReferencedOn(2, 1));
        // An E-STOP to device 3 alone takes device 3's references, not device 2's.
        session->command(QStringLiteral("motor1.home"));
        QTRY_VERIFY_WITH_TIMEOUT(motion->references()->isReferenced(1), 10000);
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        session->command(QStringLiteral("estop"));
        QTRY_COMPARE(done.size(), 1);
        QCOMPARE(motion->references()->reasonOn(3, 1), ReferenceTracker::Reason::EmergencyStop);
        QVERIFY(motion->references()->isReferencedOn(2, 1));
        QVERIFY(session->line()->showDevice(2));
        QVERIFY(motion->references()->isReferenced(1));
    }

    void homingIsJudgedOnADeviceNotInView()
    {
        connectBus();
        show(2);
        host()->deviceAt(2)->setMachinePosition(1, 10.0); // a while from the home switch
        QSignalSpy acknowledged(session.get(), &DeviceSession::commandFinished);
        MotionSupervisor *motion = session->motion();
        QSignalSpy judged(motion, &MotionSupervisor::deviceFinished);
        QSignalSpy finishedInView(motion, &MotionSupervisor::finished);
        session->command(QStringLiteral("motor1.home"));
        QTRY_COMPARE(acknowledged.size(), 1);
        QVERIFY(motion->active(1).has_value());
        QVERIFY(session->line()->showDevice(3)); // while device 2 still homes
        QVERIFY(!motion->active(1).has_value()); // nothing runs on device 3
        QCOMPARE(motion->activeOn(2).size(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(judged.size(), 1, 20000);
        QCOMPARE(judged.at(0).at(0).toInt(), 2);
        const auto outcome = judged.at(0).at(1).value<MotionOutcome>();
        QCOMPARE(outcome.verdict, MotionOutcome::Verdict::Referenced);
        QCOMPARE(finishedInView.size(), 0); // not the device in view's
        QVERIFY(motion->references()->isReferencedOn(2, 1));
        QVERIFY(!motion->references()->isReferenced(1));
        QVERIFY(motion->activeOn(2).isEmpty());
        // Its end was read from device 2 itself, not from the device in view.
        bool readFromTwo = false;
        for (const Request &r : std::as_const(sent))
            readFromTwo = readFromTwo || (r.priority == Priority::Read && r.unitId == 2);
        QVERIFY(readFromTwo);
        QVERIFY(session->line()->showDevice(2));
        QCOMPARE(motion->lastOutcome(1)->verdict, MotionOutcome::Verdict::Referenced);
    }

    // A step move puts its device's move settings back at its end: the view stays with it.
    void aStepMoveKeepsItsDeviceInView()
    {
        connectBus();
        QVERIFY(host()->deviceAt(1)->setValue(QStringLiteral("motor1.speed"), 30));
        QSignalSpy finished(session->stepMove(), &StepMove::finished);
        QVERIFY(session->stepMove()->start({StepMoveRequest::Kind::By, 1, 20}).isEmpty());
        QSignalSpy said(session.get(), &DeviceSession::message);
        QVERIFY(!session->line()->showDevice(2));
        QCOMPARE(session->line()->deviceInView(), 1);
        QVERIFY(said.last().at(1).toString().contains(QLatin1String("step move")));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
        QVERIFY(finished.first().first().value<StepMoveResult>().restored);
        QVERIFY(session->line()->showDevice(2));
    }

    void everyDevicesStatusIsCountedWithItsErrors()
    {
        test::useBuiltinSimulator(*session, {1, 2, 3});
        session->line()->setDeviceIds({1, 2, 4}); // nobody answers at 4
        session->line()->setBackgroundIntervalMs(300);
        test::connectToSimulator(*session);
        QTRY_VERIFY_WITH_TIMEOUT(session->line()->deviceStatus(4).errors >= 1 &&
                                     session->line()->deviceStatus(2).cycles >= 2 &&
                                     session->line()->deviceStatus(1).cycles >= 2,
                                 20000);
        QCOMPARE(session->line()->deviceStatus(1).state, BusDeviceStatus::State::Answering);
        QCOMPARE(session->line()->deviceStatus(1).errors, 0);
        QCOMPARE(session->line()->deviceStatus(2).state, BusDeviceStatus::State::Answering);
        QCOMPARE(session->line()->deviceStatus(4).state, BusDeviceStatus::State::NotAnswering);
        QVERIFY(!session->line()->deviceStatus(4).lastError.isEmpty());
        // What is known of device 2 (not in view) comes from its own status reads.
        QCOMPARE(session->line()->knownValues(2).value(QStringLiteral("motor1.position"), -1),
                 *host()->deviceAt(2)->value(QStringLiteral("motor1.position")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDeviceState, Guiless)
#include "tst_devicestate.moc"
