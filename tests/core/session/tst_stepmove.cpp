#include "bus/modbuslink.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h"
#include "session/stepmove.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;

// Step jog and move-to over the single move, against the built-in simulator: where the axis
// ends, the frames that went out, and the user's own single-move values put back.
class TestStepMove : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    static QStringList whats(const QSignalSpy &dispatched)
    {
        QStringList all;
        for (const QList<QVariant> &args : dispatched)
            all << args.at(1).value<Request>().what;
        return all;
    }
    static bool wrote(const QSignalSpy &dispatched, const QString &key)
    {
        for (const QList<QVariant> &args : dispatched) {
            const auto r = args.at(1).value<Request>();
            const bool write = r.type == Request::Type::WriteHolding;
            if (write && r.what.split(QStringLiteral(", ")).contains(key))
                return true;
        }
        return false;
    }
    // The user's own single move: 12.34 mm in reverse.
    void connectWithUserMove()
    {
        test::useBuiltinSimulator(*session);
        test::connectToSimulator(*session);
        QVERIFY(sim()->setValue(QStringLiteral("motor1.move_distance"), 1234));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.direction"), 1));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
    }
    StepMoveResult run(const StepMoveRequest &request)
    {
        QSignalSpy finished(session->stepMove(), &StepMove::finished);
        const QString refused = session->stepMove()->start(request);
        if (!refused.isEmpty()) {
            StepMoveResult r;
            r.text = refused;
            return r;
        }
        if (!finished.wait(20000) && finished.isEmpty())
            return {};
        return finished.first().first().value<StepMoveResult>();
    }
    void userValuesBack()
    {
        QCOMPARE(sim()->value(QStringLiteral("motor1.move_distance")).value_or(-1), 1234);
        QCOMPARE(sim()->value(QStringLiteral("motor1.direction")).value_or(-1), 1);
        QCOMPARE(
            session->parameters()->store()->deviceValue(QStringLiteral("motor1.move_distance")),
            std::optional<qint64>(1234));
        QCOMPARE(session->parameters()->store()->deviceValue(QStringLiteral("motor1.direction")),
                 std::optional<qint64>(1));
    }

private Q_SLOTS:
    void init()
    {
        qRegisterMetaType<StepMoveResult>();
        session = std::make_unique<DeviceSession>();
    }
    void cleanup() { session.reset(); }

    void stepByEndsThereAndRestores()
    {
        connectWithUserMove();
        const qint64 from = sim()->position(1);
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        const StepMoveResult r = run({StepMoveRequest::Kind::By, 1, 1.5});
        QVERIFY2(r.ok(), qPrintable(r.text));
        QVERIFY(r.started);
        QCOMPARE(sim()->position(1), from + 150);
        QVERIFY(r.outcome);
        QCOMPARE(r.outcome->verdict, MotionOutcome::Verdict::Done);
        // The frames: the step's distance and direction, the move coil, then the user's back.
        const QStringList w = whats(dispatched);
        QVERIFY(wrote(dispatched, QStringLiteral("motor1.move_distance")));
        QVERIFY(wrote(dispatched, QStringLiteral("motor1.direction")));
        const qsizetype move = w.indexOf(QStringLiteral("motor1.move"));
        QVERIFY(move > 0);
        int distanceWrites = 0;
        for (const QList<QVariant> &args : dispatched) {
            const auto req = args.at(1).value<Request>();
            if (req.what.split(QStringLiteral(", "))
                    .contains(QStringLiteral("motor1.move_distance")) &&
                req.type == Request::Type::WriteHolding)
                ++distanceWrites;
        }
        QCOMPARE(distanceWrites, 2); // the step's, then the user's
        userValuesBack();
        QVERIFY(r.text.contains(QStringLiteral("back (verified)")));
    }

    void moveToEndsThereAndRestores()
    {
        connectWithUserMove();
        StepMoveResult r = run({StepMoveRequest::Kind::To, 1, -2.5});
        QVERIFY2(r.ok(), qPrintable(r.text));
        QCOMPARE(sim()->position(1), -250);
        userValuesBack();
        // Steps of 0.1 add up exactly in the register's hundredths.
        r = run({StepMoveRequest::Kind::By, 1, 0.1});
        QVERIFY2(r.ok(), qPrintable(r.text));
        QCOMPARE(sim()->position(1), -240);
        userValuesBack();
        QVERIFY(!session->parameters()->store()->unsavedToFlash());
    }

    void refusedOverPendingEdits()
    {
        connectWithUserMove();
        QVERIFY(session->parameters()
                    ->store()
                    ->edit(QStringLiteral("motor1.move_distance"), 500)
                    .isEmpty());
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        const QString why = session->stepMove()->start({StepMoveRequest::Kind::By, 1, 1});
        QVERIFY(why.contains(QStringLiteral("Write or revert them first")));
        QVERIFY(!wrote(dispatched, QStringLiteral("motor1.move_distance")));
    }

    void refusedBeyondSoftwareLimit()
    {
        connectWithUserMove();
        TravelLimits limits;
        QVERIFY(limits.setAxis(session->map(), 1, std::nullopt, 1.0).isEmpty());
        session->setTravelLimits(limits);
        const qint64 from = sim()->position(1);
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        const StepMoveResult r = run({StepMoveRequest::Kind::To, 1, from / 100.0 + 1.01});
        QVERIFY(!r.started);
        QVERIFY(!r.arrived);
        QVERIFY2(r.text.contains(QStringLiteral("beyond the software travel limit")),
                 qPrintable(r.text));
        QVERIFY(!wrote(dispatched, QStringLiteral("motor1.move_distance")));
        QVERIFY(!whats(dispatched).contains(QStringLiteral("motor1.move")));
        QCOMPARE(sim()->position(1), from);
        // Exactly on the limit is allowed.
        const StepMoveResult onIt = run({StepMoveRequest::Kind::To, 1, 1.0});
        QVERIFY2(onIt.ok(), qPrintable(onIt.text));
        QCOMPARE(sim()->position(1), 100);
    }

    void stepCutOffByStopSaysWhereItEnded()
    {
        connectWithUserMove();
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 30));
        QSignalSpy finished(session->stepMove(), &StepMove::finished);
        QVERIFY(session->stepMove()->start({StepMoveRequest::Kind::By, 1, 50}).isEmpty());
        QTRY_VERIFY(sim()->running(1));
        session->command(QStringLiteral("motor1.stop"));
        QVERIFY(finished.wait(20000) || !finished.isEmpty());
        const auto r = finished.first().first().value<StepMoveResult>();
        QVERIFY(r.started);
        QVERIFY(!r.arrived);
        QVERIFY(r.restored);
        QVERIFY(r.outcome);
        QCOMPARE(r.outcome->causeWord(), QStringLiteral("stop"));
        QVERIFY2(r.text.contains(QStringLiteral("stopped")), qPrintable(r.text));
        userValuesBack();
    }

    void jogCrossingSoftwareLimitIsStopped()
    {
        test::connectToSimulator(*session);
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 60));
        TravelLimits limits;
        QVERIFY(limits.setAxis(session->map(), 1, std::nullopt, 1.0).isEmpty());
        session->setTravelLimits(limits);
        QSignalSpy warnings(session->jog(), &JogController::warning);
        QVERIFY(session->jog()->press(1, JogController::Direction::Forward));
        QTRY_VERIFY_WITH_TIMEOUT(!warnings.isEmpty(), 20000);
        QVERIFY(warnings.first().at(1).toString().contains(QStringLiteral("limit")));
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(sim()->position(1) >= 100);
        QTRY_COMPARE(session->jog()->state(1), JogController::State::Idle);
        // At the limit, a jog toward it does not start; back the other way it does.
        QVERIFY(!session->jog()->press(1, JogController::Direction::Forward));
        QVERIFY(session->jog()->press(1, JogController::Direction::Reverse));
        session->jog()->release(1);
        QTRY_COMPARE(session->jog()->state(1), JogController::State::Idle);
    }

    void oneShotSessionPollsOnlyForTheMove()
    {
        session->setLive(false); // as stepcomctl
        test::useBuiltinSimulator(*session);
        QSignalSpy connected(session->connection(), &SessionConnection::connected);
        session->connection()->connectSimulator();
        QTRY_COMPARE(connected.size(), 1);
        QVERIFY(connected.first().first().toBool());
        QVERIFY(!session->status()->isActive());
        const qint64 from = sim()->position(2);
        const StepMoveResult r = run({StepMoveRequest::Kind::By, 2, -0.75});
        QVERIFY2(r.ok(), qPrintable(r.text));
        QCOMPARE(sim()->position(2), from - 75);
        QVERIFY(!session->status()->isActive());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestStepMove, Guiless)
#include "tst_stepmove.moc"
