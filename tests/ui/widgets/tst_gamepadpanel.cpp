#include "gamepad/sdlgamepad.h"
#include "gamepad/virtualgamepad.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/motion/gamepadpanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <memory>

using namespace stepcom;

// The Jog page's game pad: off until ticked and remembered so; the pad connected by its name;
// the mapping changed and saved, a mapping that gives one button two jobs refused; jogging and
// the E-STOP through the window's own; Y asks before homing.
class TestGamepadPanel : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<GamepadPanel> panel;
    std::unique_ptr<VirtualGamepad> virtualPad;

    bool running(int motor) const
    {
        return host->device()->value(QStringLiteral("motor%1.running").arg(motor)).value_or(0) != 0;
    }
    void attachPad()
    {
        virtualPad = std::make_unique<VirtualGamepad>();
        QString why;
        QVERIFY2(virtualPad->attach(QStringLiteral("Panel test pad"), &why), qPrintable(why));
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init()
    {
        QSettings().remove(GamepadPanel::settingsGroup());
        host = std::make_unique<SimHost>();
        QVERIFY(test::startProofSim(*host, test::proofAxis()));
        session = test::proofSession(*host);
        panel = std::make_unique<GamepadPanel>(session.get());
    }
    void cleanup()
    {
        virtualPad.reset();
        panel.reset();
        session.reset();
        host.reset();
    }

    void offUntilTickedThenRememberedAndShowsThePad()
    {
        QVERIFY(!panel->enableBox()->isChecked());
        QVERIFY(!panel->jog()->isEnabled());
        QVERIFY(!panel->reader()->isRunning());
        panel->enableBox()->setChecked(true);
        QVERIFY(panel->jog()->isEnabled());
        QVERIFY(panel->padLabel()->text().contains(QLatin1String("No pad connected")));
        attachPad();
        QTRY_VERIFY_WITH_TIMEOUT(
            panel->padLabel()->text().contains(QLatin1String("Panel test pad")), 5000);
        QVERIFY2(panel->stateLabel()->text().contains(QLatin1String("right trigger")),
                 qPrintable(panel->stateLabel()->text()));
        // Another start of the page: still on.
        virtualPad.reset();
        panel.reset();
        panel = std::make_unique<GamepadPanel>(session.get());
        QVERIFY(panel->enableBox()->isChecked());
        QVERIFY(panel->jog()->isEnabled());
    }

    void theMappingIsSavedAndOneButtonDoesOneThing()
    {
        QComboBox *deadman = panel->deadmanBox();
        deadman->setCurrentIndex(deadman->findData(int(GamepadState::LeftShoulder)));
        QCOMPARE(panel->jog()->mapping().deadman, int(GamepadState::LeftShoulder));
        panel.reset();
        panel = std::make_unique<GamepadPanel>(session.get());
        QCOMPARE(panel->jog()->mapping().deadman, int(GamepadState::LeftShoulder));
        QCOMPARE(panel->deadmanBox()->currentData().toInt(), int(GamepadState::LeftShoulder));
        // B is the stop already: refused, and the box shows what holds.
        panel->deadmanBox()->setCurrentIndex(panel->deadmanBox()->findData(int(GamepadState::B)));
        QCOMPARE(panel->jog()->mapping().deadman, int(GamepadState::LeftShoulder));
        QCOMPARE(panel->deadmanBox()->currentData().toInt(), int(GamepadState::LeftShoulder));
        QVERIFY2(panel->stateLabel()->text().contains(QLatin1String("two things")),
                 qPrintable(panel->stateLabel()->text()));
    }

    void jogsAndSendsTheWindowsEmergencyStop()
    {
        int estops = 0;
        panel->setEmergencyStop([this, &estops] {
            ++estops;
            session->emergencyStop();
        });
        panel->enableBox()->setChecked(true);
        attachPad();
        QTRY_VERIFY_WITH_TIMEOUT(panel->reader()->info().has_value(), 5000);
        virtualPad->setAxis(VirtualGamepad::Axis::RightTrigger, 1.0);
        virtualPad->setAxis(VirtualGamepad::Axis::LeftX, 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(running(1), 5000);
        QTRY_VERIFY(panel->stateLabel()->text().contains(QLatin1String("Jogging motor 1")));
        virtualPad->setButton(GamepadState::Back, true);
        QTRY_COMPARE_WITH_TIMEOUT(estops, 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!running(1), 5000);
        // Switched off: the pad moves nothing.
        virtualPad->setButton(GamepadState::Back, false);
        panel->enableBox()->setChecked(false);
        QVERIFY(!panel->jog()->isEnabled());
        QVERIFY(!panel->reader()->isRunning());
    }

    void yAsksBeforeHoming()
    {
        QStringList asked;
        panel->setConfirmer([&asked](const QString &q) {
            asked << q;
            return false;
        });
        panel->enableBox()->setChecked(true);
        attachPad();
        QTRY_VERIFY_WITH_TIMEOUT(panel->reader()->info().has_value(), 5000);
        virtualPad->setAxis(VirtualGamepad::Axis::RightTrigger, 1.0);
        virtualPad->setButton(GamepadState::Y, true);
        QTRY_COMPARE_WITH_TIMEOUT(asked.size(), 1, 5000);
        QVERIFY(asked.first().contains(QLatin1String("Home")));
        QVERIFY(!running(1) && !running(2)); // not confirmed: nothing moves
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestGamepadPanel, Gui)
#include "tst_gamepadpanel.moc"
