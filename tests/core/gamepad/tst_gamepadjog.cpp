#include "gamepad/gamepadjog.h"
#include "gamepad/sdlgamepad.h"
#include "gamepad/virtualgamepad.h"
#include "motion/travellimits.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QJsonObject>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;

// A game pad jogging the simulated controller, the pad being SDL's own virtual joystick read
// through SdlGamepad as a real one is: the stick with the dead-man held jogs, letting go of
// either stops, no dead-man no motion, an unplugged pad stops its jogs, a diagonal jogs both
// motors, the soft limits and another hand end the pad's jog, Back sends the E-STOP.
class TestGamepadJog : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<SdlGamepad> sdl;
    std::unique_ptr<GamepadJog> pad;
    std::unique_ptr<VirtualGamepad> virtualPad;

    SimDevice *sim() const { return host->device(); }
    bool running(int motor) const
    {
        return sim()->value(QStringLiteral("motor%1.running").arg(motor)).value_or(0) != 0;
    }
    using Axis = VirtualGamepad::Axis;
    void axis(Axis a, double v) { QVERIFY(virtualPad->setAxis(a, v)); }
    void button(int b, bool down) { QVERIFY(virtualPad->setButton(b, down)); }
    void deadman(bool held) { axis(Axis::RightTrigger, held ? 1.0 : 0.0); }
    // Nothing moved after a few status polls: what would have gone out has gone.
    void nothingMoves()
    {
        QVERIFY(test::waitForStatusCycles(*session, 3));
        QVERIFY(!running(1));
        QVERIFY(!running(2));
        QVERIFY(pad->jogging().isEmpty());
    }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        QVERIFY(test::startProofSim(*host, test::proofAxis()));
        session = test::proofSession(*host);
        sdl = std::make_unique<SdlGamepad>();
        QString why;
        QVERIFY2(sdl->start(&why), qPrintable(why));
        virtualPad = std::make_unique<VirtualGamepad>();
        QVERIFY2(virtualPad->attach(QStringLiteral("StepCom test pad"), &why), qPrintable(why));
        pad = std::make_unique<GamepadJog>(session->jog());
        connect(sdl.get(), &SdlGamepad::state, pad.get(), &GamepadJog::update);
        connect(sdl.get(), &SdlGamepad::detached, pad.get(), &GamepadJog::detached);
        QTRY_VERIFY_WITH_TIMEOUT(sdl->info().has_value(), 5000);
        QCOMPARE(sdl->info()->name, QStringLiteral("StepCom test pad"));
        deadman(false);
        pad->setEnabled(true);
    }
    void cleanup()
    {
        pad.reset();
        virtualPad.reset();
        sdl.reset();
        session.reset();
        host.reset();
    }

    void theStickJogsWhileTheDeadmanIsHeldAndStopsWhenLetGo()
    {
        deadman(true);
        axis(Axis::LeftX, 0.8);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        QCOMPARE(session->jog()->source(1), JogController::Source::Gamepad);
        QCOMPARE(*session->jog()->direction(1), JogController::Direction::Forward);
        QVERIFY(!running(2));
        axis(Axis::LeftX, 0);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        // Up on the stick is motor 2 forward.
        axis(Axis::LeftY, -0.9);
        QTRY_VERIFY_WITH_TIMEOUT(running(2), 5000);
        QCOMPARE(*session->jog()->direction(2), JogController::Direction::Forward);
        // Letting go of the dead-man with the stick still over stops it.
        deadman(false);
        QTRY_VERIFY_WITH_TIMEOUT(!running(2), 5000);
        QVERIFY(pad->jogging().isEmpty());
    }

    void withoutTheDeadmanNothingMoves()
    {
        axis(Axis::LeftX, 1.0);
        nothingMoves();
        // A stick inside the dead zone is centred, dead-man or not.
        deadman(true);
        axis(Axis::LeftX, 0.1);
        nothingMoves();
        // And a pad not enabled moves nothing.
        pad->setEnabled(false);
        axis(Axis::LeftX, 1.0);
        nothingMoves();
    }

    void anUnpluggedPadStopsItsJogs()
    {
        deadman(true);
        axis(Axis::LeftX, -1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        QSignalSpy gone(sdl.get(), &SdlGamepad::detached);
        virtualPad->detach();
        QTRY_COMPARE_WITH_TIMEOUT(gone.size(), 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        QVERIFY(pad->jogging().isEmpty());
    }

    void readingsThatStopComingStopTheJog()
    {
        deadman(true);
        axis(Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        // The pad is not read any more (as when its reader stalls): the silence stops the jog.
        sdl->stop();
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        QVERIFY(pad->jogging().isEmpty());
    }

    void theWindowLosingFocusDoesNotStopThePadButClosingDoes()
    {
        deadman(true);
        axis(Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        QCOMPARE(session->stopJogging(DeviceSession::JogStop::FocusLost), 0);
        QCOMPARE(session->stopJogging(DeviceSession::JogStop::PageLeft), 0);
        QVERIFY(test::waitForStatusCycles(*session, 2));
        QVERIFY(running(1));
        QCOMPARE(session->stopJogging(DeviceSession::JogStop::WindowClosing), 1);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        QTRY_VERIFY(pad->jogging().isEmpty());
    }

    void aDiagonalJogsBothMotors()
    {
        deadman(true);
        axis(Axis::LeftX, 0.7);
        axis(Axis::LeftY, -0.7);
        QTRY_VERIFY_WITH_TIMEOUT(running(1) && running(2), 5000);
        QCOMPARE(pad->jogging(), (QList<int>{1, 2}));
        // Back to straight across: motor 2 stops, motor 1 goes on.
        axis(Axis::LeftY, 0);
        QTRY_VERIFY_WITH_TIMEOUT(!running(2), 5000);
        QVERIFY(running(1));
        deadman(false);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
    }

    void theSoftLimitStopsThePadsJog()
    {
        const Parameter *p = TravelLimits::positionParameter(session->map(), 1);
        const double here = p->toEngineering(*sim()->value(QStringLiteral("motor1.position")));
        TravelLimits limits;
        QCOMPARE(limits.setAxis(session->map(), 1, std::nullopt, here + 2.0), QString());
        session->setTravelLimits(limits);
        deadman(true);
        axis(Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 10000);
        QVERIFY(pad->jogging().isEmpty());
        // Held on: the pad does not press on into the limit.
        nothingMoves();
    }

    void anotherHandEndsThePadsJog()
    {
        deadman(true);
        axis(Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        // The mouse on the same motor: the pad lets go, and the mouse presses again.
        QVERIFY(!session->jog()->press(1, JogController::Direction::Reverse,
                                       JogController::Source::Pointer));
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        QTRY_VERIFY(pad->jogging().isEmpty());
    }

    void backSendsTheEmergencyStopAndBStops()
    {
        int estops = 0;
        pad->setEmergencyStop([this, &estops] {
            ++estops;
            session->emergencyStop();
        });
        deadman(true);
        axis(Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        // B stops, the stick still over.
        button(GamepadState::B, true);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        QVERIFY(pad->jogging().isEmpty());
        button(GamepadState::B, false);
        axis(Axis::LeftX, 0);
        QVERIFY(test::waitForStatusCycles(*session, 2));
        axis(Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        // Back: the E-STOP, which stops it.
        button(GamepadState::Back, true);
        QTRY_COMPARE_WITH_TIMEOUT(estops, 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        QVERIFY(pad->jogging().isEmpty());
    }

    void theMappingIsReadBackOrRefusedWhole()
    {
        GamepadMapping m;
        m.deadman = GamepadState::LeftShoulder;
        m.deadzone = 0.4;
        QString why;
        QCOMPARE(GamepadMapping::fromJson(m.toJson(), &why), std::optional<GamepadMapping>(m));
        QJsonObject bad = m.toJson();
        bad.insert(QStringLiteral("colour"), 1);
        QVERIFY(!GamepadMapping::fromJson(bad, &why));
        QVERIFY2(why.contains(QLatin1String("colour")), qPrintable(why));
        bad = m.toJson();
        bad.insert(QStringLiteral("stop"), GamepadState::LeftShoulder);
        QVERIFY(!GamepadMapping::fromJson(bad, &why));
        QVERIFY2(why.contains(QLatin1String("two things")), qPrintable(why));
        bad = m.toJson();
        bad.insert(QStringLiteral("deadzone"), 2);
        QVERIFY(!GamepadMapping::fromJson(bad, &why));
        bad = m.toJson();
        bad.insert(QStringLiteral("home"), 57);
        QVERIFY(!GamepadMapping::fromJson(bad, &why));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestGamepadJog, Guiless)
#include "tst_gamepadjog.moc"
