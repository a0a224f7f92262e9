#include "bus/modbuslink.h"
#include "scripteddevice.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;
using Direction = JogController::Direction;
using Source = JogController::Source;
using State = JogController::State;

// Hold-to-move jogging against the built-in simulator (and a controller that ignores stops).
class TestJogController : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<JogController> jog;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    void connectSim() { test::connectToSimulator(*session); }
    static QStringList texts(const QSignalSpy &spy, int column)
    {
        QStringList all;
        for (const QList<QVariant> &args : spy)
            all << args.at(column).toString();
        return all;
    }
    // The requests put on the wire, by what they were for ("motor1.stop").
    static QStringList whats(const QSignalSpy &dispatched)
    {
        QStringList all;
        for (const QList<QVariant> &args : dispatched)
            all << args.at(1).value<Request>().what;
        return all;
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        jog = std::make_unique<JogController>(session.get());
        jog->setSettleMs(100);
    }
    void cleanup()
    {
        jog.reset();
        session.reset();
    }

    void pressRunsAndReleaseStops()
    {
        connectSim();
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        QSignalSpy warnings(jog.get(), &JogController::warning);
        QVERIFY(jog->press(1, Direction::Forward));
        QCOMPARE(jog->state(1), State::Jogging);
        QCOMPARE(jog->direction(1).value_or(Direction::Reverse), Direction::Forward);
        QTRY_VERIFY(sim()->running(1));
        const qint64 from = sim()->position(1);
        QTRY_VERIFY(sim()->position(1) > from); // forward: the position grows
        QVERIFY(!sim()->running(2));
        jog->release(1);
        QTRY_VERIFY(!sim()->running(1));
        QTRY_COMPARE(jog->state(1), State::Idle); // the running flag was read back as 0
        QVERIFY(!jog->isBusy());
        QVERIFY(warnings.isEmpty());
        bool emergency = false;
        for (const QList<QVariant> &args : dispatched) {
            const auto r = args.at(1).value<Request>();
            if (r.what == QLatin1String("motor1.stop"))
                emergency = r.priority == Priority::Emergency;
        }
        QVERIFY2(emergency, "the stop goes out at emergency priority");
        // The running flag was read back after the stop, at command priority (ahead of polls).
        const Parameter *running = session->map().find(QStringLiteral("motor1.running"));
        bool readBack = false;
        for (const QList<QVariant> &args : dispatched) {
            const auto r = args.at(1).value<Request>();
            readBack = readBack ||
                       (r.type == Request::Type::ReadHolding && r.address == running->address &&
                        r.count == 1 && r.priority == Priority::Command);
        }
        QVERIFY(readBack);
    }

    void releaseBeforeTheStartIsAnsweredStopsAfterIt()
    {
        connectSim();
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        QVERIFY(jog->press(2, Direction::Reverse));
        jog->release(2); // the start is still queued: a stop now would overtake it
        QCOMPARE(jog->state(2), State::Stopping);
        QTRY_COMPARE(jog->state(2), State::Idle);
        QVERIFY(!sim()->running(2));
        const QStringList order = whats(dispatched);
        QVERIFY(order.indexOf(QStringLiteral("motor2.reverse")) >= 0);
        QVERIFY(order.indexOf(QStringLiteral("motor2.stop")) >
                order.indexOf(QStringLiteral("motor2.reverse")));
    }

    void refusedPressesSayWhy()
    {
        QSignalSpy messages(jog.get(), &JogController::message);
        QVERIFY(!jog->press(1, Direction::Forward)); // not connected
        QVERIFY(
            texts(messages, 1).join(QLatin1Char('\n')).contains(QLatin1String("Not connected")));
        connectSim();
        QVERIFY(!jog->press(1, Direction::Forward, Source::Keyboard)); // keyboard jogging is off
        QVERIFY(
            messages.last().at(1).toString().contains(QLatin1String("Keyboard jogging is off")));
        QVERIFY(jog->press(1, Direction::Forward));
        QVERIFY(!jog->press(1, Direction::Reverse));
        QVERIFY(messages.last().at(1).toString().contains(QLatin1String("already jogs forward")));
        QTRY_VERIFY(sim()->running(1));
        jog->release(1, Source::Keyboard);            // not the hand that holds it
        QVERIFY(test::waitForStatusCycles(*session)); // a stop would have gone out by then
        QVERIFY(sim()->running(1));
        QCOMPARE(jog->state(1), State::Jogging);
        jog->release(1);
        QTRY_COMPARE(jog->state(1), State::Idle);
        QVERIFY(!sim()->running(1));
        // A motor moving on its own (a single move) is not jogged on top.
        QVERIFY(sim()->setValue(QStringLiteral("motor2.speed"), 30));
        QVERIFY(sim()->command(QStringLiteral("motor2.move")));
        QTRY_COMPARE(session->parameters()
                         ->store()
                         ->deviceValue(QStringLiteral("motor2.running"))
                         .value_or(-1),
                     qint64(1));
        QVERIFY(!jog->press(2, Direction::Forward));
        QVERIFY(messages.last().at(1).toString().contains(QLatin1String("is moving")));
        QVERIFY(sim()->command(QStringLiteral("motor2.stop")));
    }

    void stopAllStopsEveryJog()
    {
        connectSim();
        jog->setKeyboardEnabled(true);
        QVERIFY(jog->press(1, Direction::Forward));
        QVERIFY(jog->press(2, Direction::Reverse, Source::Keyboard));
        QTRY_VERIFY(sim()->running(1) && sim()->running(2));
        QCOMPARE(jog->stopAll(QStringLiteral("focus loss")), 2);
        QTRY_VERIFY(!sim()->running(1) && !sim()->running(2));
        QTRY_VERIFY(!jog->isBusy());
        QCOMPARE(jog->state(1), State::Idle);
        QCOMPARE(jog->state(2), State::Idle);
        QCOMPARE(jog->stopAll(QStringLiteral("again")), 0); // nothing held: nothing sent

        // Switching keyboard jogging off lets go of the keys.
        QVERIFY(jog->press(2, Direction::Forward, Source::Keyboard));
        QTRY_VERIFY(sim()->running(2));
        jog->setKeyboardEnabled(false);
        QTRY_VERIFY(!sim()->running(2));
    }

    void emergencyStopWhileJoggingRaisesNoFalseAlarm()
    {
        connectSim();
        QSignalSpy warnings(jog.get(), &JogController::warning);
        QVERIFY(jog->press(1, Direction::Forward));
        QTRY_VERIFY(sim()->running(1));
        session->emergencyStop();
        QTRY_VERIFY(!sim()->running(1));
        jog->release(1);
        QTRY_COMPARE(jog->state(1), State::Idle);
        QVERIFY(warnings.isEmpty());
    }

    void settledFollowsTheLastCheck()
    {
        connectSim();
        QSignalSpy settled(jog.get(), &JogController::settled);
        QVERIFY(jog->press(1, Direction::Reverse));
        QTRY_VERIFY(sim()->running(1));
        jog->stopAll(QStringLiteral("exit"));
        QVERIFY(jog->isBusy());
        QTRY_VERIFY(!settled.isEmpty());
        QVERIFY(!jog->isBusy());
        QVERIFY(!sim()->running(1));
    }

    void linkLossWhileJoggingStopsWhenTheLinkIsBack()
    {
        connectSim();
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 60)); // 5 mm/s: far from a limit
        QSignalSpy warnings(jog.get(), &JogController::warning);
        QVERIFY(jog->press(1, Direction::Forward));
        QTRY_VERIFY(sim()->running(1));
        QSignalSpy reopened(test::simHost(*session), &SimHost::reopened);
        test::simHost(*session)->hangUp(400);
        QTRY_COMPARE_WITH_TIMEOUT(jog->state(1), State::PossiblyRunning, 5000);
        QVERIFY(!warnings.isEmpty());
        QVERIFY2(texts(warnings, 1)
                     .join(QLatin1Char('\n'))
                     .contains(QLatin1String("possibly "
                                             "still running")),
                 qPrintable(texts(warnings, 1).join(QLatin1Char('\n'))));
        QVERIFY(sim()->running(1)); // nobody could stop it
        QVERIFY(!jog->press(1, Direction::Forward));

        QTRY_COMPARE_WITH_TIMEOUT(reopened.size(), 1, 5000);
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        QSignalSpy connected(session->connection(), &SessionConnection::connected);
        test::useBuiltinSimulator(*session);
        session->connection()->connectSimulator();
        QTRY_COMPARE_WITH_TIMEOUT(connected.size(), 1, 5000);
        QVERIFY(connected.at(0).at(0).toBool());
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(!dispatched.isEmpty());
        QCOMPARE(whats(dispatched).first(), QStringLiteral("motor1.stop")); // before any read
        QTRY_COMPARE(jog->state(1), State::Idle);
    }

    void startWithoutAnswerIsStoppedAnyway()
    {
        // The forward command arrives and acts, but its answer is lost: the motor may run.
        test::ScriptedDevice device;
        QString error;
        QVERIFY2(device.open(&error), qPrintable(error));
        device.registers = QList<quint16>(320, 0);
        const quint16 forward = session->map().find(QStringLiteral("motor1.forward"))->address;
        const quint16 stop = session->map().find(QStringLiteral("motor1.stop"))->address;
        const quint16 running = session->map().find(QStringLiteral("motor1.running"))->address;
        device.setResponder([&](const QByteArray &req, int) -> std::optional<QByteArray> {
            const auto word = [&](int at) {
                return quint16((quint8(req.at(at)) << 8) | quint8(req.at(at + 1)));
            };
            switch (quint8(req.at(1))) {
            case 0x03:
                return device.registerDevice(req);
            case 0x05:
                if (word(2) == stop)
                    device.registers[running] = 0;
                if (word(2) != forward)
                    return req;
                device.registers[running] = 1;
                return std::nullopt; // acted, but the answer never arrives
            default:
                return std::nullopt;
            }
        });
        LinkSettings s;
        s.portName = device.clientPath();
        s.timeoutMs = 200;
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);

        QSignalSpy messages(jog.get(), &JogController::message);
        QVERIFY(jog->press(1, Direction::Forward));
        QTRY_COMPARE(device.registers[running], quint16(1));
        QTRY_COMPARE_WITH_TIMEOUT(device.registers[running], quint16(0), 3000); // stop sent
        QTRY_COMPARE(jog->state(1), State::Idle);                               // and checked
        QVERIFY(texts(messages, 1).join(QLatin1Char('\n')).contains(QLatin1String("failed")));
    }

    void stillRunningAfterTheStopIsReported()
    {
        // A controller that starts on forward but ignores the stop.
        test::ScriptedDevice device;
        QString error;
        QVERIFY2(device.open(&error), qPrintable(error));
        device.useRegisterDevice(1);
        const Parameter *forward = session->map().find(QStringLiteral("motor1.forward"));
        const Parameter *running = session->map().find(QStringLiteral("motor1.running"));
        QVERIFY(forward && running);
        connect(&device, &test::ScriptedDevice::requestReceived, this, [&](const QByteArray &f) {
            if (quint8(f.at(1)) == 0x05 &&
                ((quint8(f.at(2)) << 8) | quint8(f.at(3))) == forward->address)
                device.registers[running->address] = 1;
        });
        LinkSettings s;
        s.portName = device.clientPath();
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);

        QSignalSpy warnings(jog.get(), &JogController::warning);
        QVERIFY(jog->press(1, Direction::Forward));
        QTRY_COMPARE(device.registers[running->address], quint16(1));
        jog->release(1);
        QTRY_COMPARE(warnings.size(), 1);
        QCOMPARE(warnings.at(0).at(0).toInt(), 1);
        QVERIFY2(
            warnings.at(0).at(1).toString().contains(QLatin1String("still runs after its stop")),
            qPrintable(warnings.at(0).at(1).toString()));
        QCOMPARE(jog->state(1), State::StillRunning);
        QCOMPARE(session->parameters()
                     ->store()
                     ->deviceValue(QStringLiteral("motor1.running"))
                     .value_or(-1),
                 qint64(1));
        QVERIFY(!jog->press(1, Direction::Reverse)); // not on top of a runaway

        // stopAll tries again; once the controller reports idle the warning state ends.
        QCOMPARE(jog->stopAll(QStringLiteral("focus loss")), 1);
        QTRY_COMPARE(warnings.size(), 2);
        device.registers[running->address] = 0;
        QTRY_COMPARE(jog->state(1), State::Idle);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestJogController, Gui)
#include "tst_jogcontroller.moc"
