#include "motion/travellimits.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/motion/jogkeys.h"

#include <QTest>
#include <QWidget>

#include <memory>

using namespace stepcom;

// The keyboard's diagonals (Home, PgUp, End, PgDn: the keypad's 7 9 1 3) jog both motors, each
// at its own speed, and letting go stops both; an axis at its limit stays, the other goes on.
class TestJogKeys : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> scope;
    std::unique_ptr<JogKeys> keys;

    bool running(int motor) const
    {
        return host->device()->value(QStringLiteral("motor%1.running").arg(motor)).value_or(0) != 0;
    }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        QVERIFY(test::startProofSim(*host, test::proofAxis()));
        session = test::proofSession(*host);
        scope = std::make_unique<QWidget>();
        keys = std::make_unique<JogKeys>(session->jog(), scope.get());
        session->jog()->setKeyboardEnabled(true);
        scope->show();
        scope->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(scope.get()));
    }
    void cleanup()
    {
        keys.reset();
        scope.reset();
        session.reset();
        host.reset();
    }

    void theBindings()
    {
        using D = JogController::Direction;
        QCOMPARE(JogKeys::bindingsFor(Qt::Key_Right).size(), 1);
        const auto upRight = JogKeys::bindingsFor(Qt::Key_PageUp);
        QCOMPARE(upRight.size(), 2);
        QCOMPARE(upRight[0].motor, 1);
        QCOMPARE(upRight[0].direction, D::Forward);
        QCOMPARE(upRight[1].motor, 2);
        QCOMPARE(upRight[1].direction, D::Forward);
        const auto downLeft = JogKeys::bindingsFor(Qt::Key_End);
        QCOMPARE(downLeft[0].direction, D::Reverse);
        QCOMPARE(downLeft[1].direction, D::Reverse);
        QVERIFY(JogKeys::bindingsFor(Qt::Key_A).isEmpty());
    }

    void aDiagonalJogsBothAndLettingGoStopsBoth()
    {
        QTest::keyPress(scope.get(), Qt::Key_PageUp);
        QTRY_VERIFY_WITH_TIMEOUT(running(1) && running(2), 5000);
        QTest::keyRelease(scope.get(), Qt::Key_PageUp);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1) && !running(2), 5000);
    }

    void anAxisAtItsLimitStaysTheOtherGoesOn()
    {
        const Parameter *p = TravelLimits::positionParameter(session->map(), 1);
        const double here =
            p->toEngineering(*host->device()->value(QStringLiteral("motor1.position")));
        TravelLimits limits;
        QCOMPARE(limits.setAxis(session->map(), 1, std::nullopt, here), QString());
        session->setTravelLimits(limits);
        QTest::keyPress(scope.get(), Qt::Key_PageUp); // motor 1 forward is at its limit
        QTRY_VERIFY_WITH_TIMEOUT(running(2), 5000);
        QVERIFY(!running(1));
        QTest::keyRelease(scope.get(), Qt::Key_PageUp);
        QTRY_VERIFY_WITH_TIMEOUT(!running(2), 5000);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestJogKeys, Gui)
#include "tst_jogkeys.moc"
