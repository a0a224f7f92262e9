#include "base/emergencystop.h"
#include "base/language.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "device/parameterstore.h"
#include "motion/referencetracker.h"
#include "pages/motionpage.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/messageview.h"
#include "widgets/docks/statusdock.h"
#include "widgets/fields/led.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/homingordereditor.h"
#include "widgets/motion/jogbutton.h"
#include "widgets/motion/jogpanel.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include "darkpalette.h"
#include "screenshots.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QWidget>

#include <memory>

using namespace stepcom;
using State = JogController::State;

// The "Jog and home" page against the built-in simulator, offscreen.
class TestMotionPage : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> dialogs; // the write flow's dialogs open over it
    WriteFlow *writes = nullptr;      // the window's one, for a page on its own

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    qint64 simValue(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }
    void connectSim() { test::connectToSimulator(*session); }
    static void showActive(QWidget *w)
    {
        w->resize(1100, 800);
        w->show();
        w->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(w));
    }
    static void sendKey(QWidget *to, QEvent::Type type, int key, bool autoRepeat = false)
    {
        QKeyEvent e(type, key, Qt::NoModifier, QString(), autoRepeat);
        QApplication::sendEvent(to, &e);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
    }
    void init()
    {
        session = std::make_unique<DeviceSession>();
        dialogs = std::make_unique<QWidget>();
        writes = new WriteFlow(session.get(), dialogs.get());
    }
    void cleanup()
    {
        dialogs.reset();
        session.reset();
    }

    void holdingTheButtonMovesAndLettingGoStops()
    {
        MotionPage page(session.get(), writes);
        QCOMPARE(page.title(), QStringLiteral("Jog and home"));
        QCOMPARE(page.motorCount(), 2);
        session->jog()->setSettleMs(100);
        JogPanel *p = page.panel(1);
        QVERIFY(!p->forwardButton()->isEnabled()); // not connected
        showActive(&page);
        connectSim();
        QTRY_VERIFY(p->forwardButton()->isEnabled());
        QCOMPARE(p->runningLed()->state(), Led::State::Off);
        QCOMPARE(p->positionText(), QStringLiteral("0.00 mm"));

        QTest::mousePress(p->forwardButton(), Qt::LeftButton);
        QTRY_VERIFY(sim()->running(1));
        QTRY_COMPARE(p->runningLed()->state(), Led::State::On);
        QCOMPARE(p->statusText(), QStringLiteral("Jogging forward"));
        QTRY_VERIFY(p->positionText() != QStringLiteral("0.00 mm"));
        QTest::mouseRelease(p->forwardButton(), Qt::LeftButton);
        QTRY_VERIFY(!sim()->running(1));
        QTRY_COMPARE(session->jog()->state(1), State::Idle);
        QTRY_COMPARE(p->runningLed()->state(), Led::State::Off);

        // Sliding off the button stops; sliding back does not restart.
        QTest::mousePress(p->reverseButton(), Qt::LeftButton);
        QTRY_VERIFY(sim()->running(1));
        QTest::mouseMove(p->reverseButton(), QPoint(-30, -30));
        QTRY_VERIFY(!sim()->running(1));
        QTest::mouseMove(p->reverseButton(), p->reverseButton()->rect().center());
        QVERIFY(test::waitForStatusCycles(*session)); // a jog would have gone out by then
        QVERIFY(!sim()->running(1));
        QTest::mouseRelease(p->reverseButton(), Qt::LeftButton);
        QVERIFY(!page.bannerShown());

        // The stop button stops whatever moves, at once.
        QVERIFY(sim()->command(QStringLiteral("motor2.forward")));
        QTest::mouseClick(page.panel(2)->stopButton(), Qt::LeftButton);
        QTRY_VERIFY(!sim()->running(2));
    }

    void deactivationAndPageChangeStopAJog()
    {
        MainWindow window(session.get());
        showActive(&window);
        connectSim();
        MotionPage *page = WindowProbe(window).motionPage();
        QVERIFY(page);
        session->jog()->setSettleMs(100);
        WindowProbe(window).showPage(int(WindowProbe(window).pages().indexOf(page)));
        QCOMPARE(WindowProbe(window).currentPage(), page);
        JogButton *forward = page->panel(1)->forwardButton();

        QTest::mousePress(forward, Qt::LeftButton);
        QTRY_VERIFY(sim()->running(1));
        QWidget other;
        showActive(&other); // another window takes the focus
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(!forward->isHeld());
        QTRY_COMPARE(session->jog()->state(1), State::Idle);

        showActive(&window);
        QTest::mousePress(forward, Qt::LeftButton);
        QTRY_VERIFY(sim()->running(1));
        WindowProbe(window).showPage(0);
        QTRY_VERIFY(!sim()->running(1));
        QTRY_COMPARE(session->jog()->state(1), State::Idle);
        QVERIFY(WindowProbe(window)
                    .messageView()
                    ->texts()
                    .join(QLatin1Char('\n'))
                    .contains(QLatin1String("Motor 1 stopped")));

        // Closing the window with a jog held: the stop goes out before it goes away.
        WindowProbe(window).showPage(int(WindowProbe(window).pages().indexOf(page)));
        QTest::mousePress(page->panel(2)->reverseButton(), Qt::LeftButton);
        QTRY_VERIFY(sim()->running(2));
        window.close();
        QTRY_VERIFY(!window.isVisible());
        QVERIFY(!sim()->running(2));
    }

    void keyboardJoggingIsOptInAndStopsOnRelease()
    {
        MotionPage page(session.get(), writes);
        session->jog()->setSettleMs(100);
        showActive(&page);
        connectSim();
        QVERIFY(!page.keyboardCheck()->isChecked());
        QVERIFY(page.keyboardIndicator()->isHidden());
        QTest::keyPress(&page, Qt::Key_Right);
        QVERIFY(test::waitForStatusCycles(*session)); // a jog would have gone out by then
        QVERIFY(!sim()->running(1));                  // off by default: keys do nothing
        QTest::keyRelease(&page, Qt::Key_Right);

        page.keyboardCheck()->click();
        QVERIFY(session->jog()->keyboardEnabled());
        QVERIFY(!page.keyboardIndicator()->isHidden());
        QTest::keyPress(&page, Qt::Key_Right);
        QTRY_VERIFY(sim()->running(1));
        QCOMPARE(session->jog()->direction(1).value_or(JogController::Direction::Reverse),
                 JogController::Direction::Forward);
        // Auto-repeat (a release+press pair on X11) neither stops nor restarts.
        sendKey(&page, QEvent::KeyRelease, Qt::Key_Right, true);
        sendKey(&page, QEvent::KeyPress, Qt::Key_Right, true);
        QVERIFY(test::waitForStatusCycles(*session)); // a stop would have gone out by then
        QVERIFY(sim()->running(1));
        QTest::keyRelease(&page, Qt::Key_Right);
        QTRY_VERIFY(!sim()->running(1));

        QTest::keyPress(&page, Qt::Key_Up); // motor 2 forward
        QTRY_VERIFY(sim()->running(2));
        QTest::keyRelease(&page, Qt::Key_Up);
        QTRY_VERIFY(!sim()->running(2));

        // A key held through a stop does not restart by repeating.
        QTest::keyPress(&page, Qt::Key_Left);
        QTRY_VERIFY(sim()->running(1));
        session->jog()->stopAll(QStringLiteral("focus loss"));
        QTRY_VERIFY(!sim()->running(1));
        QTRY_COMPARE(session->jog()->state(1), State::Idle);
        sendKey(&page, QEvent::KeyPress, Qt::Key_Left, true);
        QVERIFY(test::waitForStatusCycles(*session)); // a jog would have gone out by then
        QVERIFY(!sim()->running(1));
        QTest::keyRelease(&page, Qt::Key_Left);

        // The page alone (no main window) stops a key held when its window loses the focus.
        QTest::keyPress(&page, Qt::Key_Down);
        QTRY_VERIFY(sim()->running(2));
        {
            QWidget other;
            showActive(&other);
            QTRY_VERIFY(!sim()->running(2));
            QTest::keyRelease(&other, Qt::Key_Down);
        }
        showActive(&page);
        QTRY_COMPARE(session->jog()->state(2), State::Idle);

        // Typing in a field keeps the arrows for the field.
        QWidget *speed = page.panel(1)->speedField()->editor();
        speed->setFocus();
        QTRY_VERIFY(speed->hasFocus());
        QTest::keyPress(speed, Qt::Key_Right);
        QVERIFY(test::waitForStatusCycles(*session)); // a jog would have gone out by then
        QVERIFY(!sim()->running(1));
        QTest::keyRelease(speed, Qt::Key_Right);

        page.keyboardCheck()->click();
        QVERIFY(page.keyboardIndicator()->isHidden());
        QTest::keyPress(&page, Qt::Key_Right);
        QVERIFY(test::waitForStatusCycles(*session)); // a jog would have gone out by then
        QVERIFY(!sim()->running(1));
        QTest::keyRelease(&page, Qt::Key_Right);
    }

    void singleMoveAndHomingEndAtZero()
    {
        connectSim();
        for (const char *k : {"motor1.speed", "motor2.speed"})
            QVERIFY(sim()->setValue(QLatin1String(k), 1200)); // 100 mm/s: a quick test
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        MotionPage page(session.get(), writes);
        showActive(&page);
        JogPanel *p = page.panel(1);
        QCOMPARE(p->moveText(), QStringLiteral("10.00 mm, Forward, at 1200 rpm"));
        QVERIFY(p->moveButton()->isEnabled());
        QVERIFY(session->parameters()
                    ->store()
                    ->edit(QStringLiteral("motor1.move_distance"), 2000)
                    .isEmpty());
        QVERIFY(!p->moveButton()->isEnabled()); // the controller would move by what it holds
        QVERIFY(p->moveButton()->toolTip().contains(QLatin1String("not written")));
        session->parameters()->store()->revert(QStringLiteral("motor1.move_distance"));
        QVERIFY(p->moveButton()->isEnabled());

        p->moveButton()->click();
        QTRY_COMPARE(simValue("motor1.position"), 1000);
        QTRY_COMPARE(p->statusText(),
                     QStringLiteral("Idle — Single move of motor 1: done at 10.00 mm"));
        QVERIFY(p->referenceText().startsWith(QLatin1String("not referenced")));
        p->homeButton()->click();
        QTRY_VERIFY(p->statusText().startsWith(QLatin1String("Homing")));
        QTRY_COMPARE(p->statusText(),
                     QStringLiteral("Idle — Homing motor 1: referenced at 0.00 mm"));
        QCOMPARE(p->referenceText(), QStringLiteral("referenced"));
        QCOMPARE(simValue("motor1.position"), 0);
        QCOMPARE(p->positionText(), QStringLiteral("0.00 mm"));

        // Both away from home, then home in the controller's order.
        QVERIFY(sim()->command(QStringLiteral("motor1.move")));
        QVERIFY(sim()->command(QStringLiteral("motor2.move")));
        QTRY_VERIFY(!sim()->running(1) && !sim()->running(2));
        QCOMPARE(simValue("motor2.position"), 1000);
        QTRY_VERIFY(page.homeAllButton()->isEnabled());
        // Every status the page showed on the way (connected after the page, so each is read
        // once the page has taken the change): a busy computer may let a poll see a motor run
        // and the next see it home before a test looking now and then sees the first.
        QStringList shown;
        const auto record = [&shown, &page] {
            if (shown.isEmpty() || shown.last() != page.homingStatus())
                shown << page.homingStatus();
        };
        const QMetaObject::Connection motion =
            connect(session->motion(), &MotionSupervisor::changed, this, record);
        const QMetaObject::Connection values =
            connect(session->parameters()->store(), &ParameterStore::valueChanged, this, record);
        page.homeAllButton()->click();
        QTRY_VERIFY2_WITH_TIMEOUT(
            shown.filter(QLatin1String("motor 1 running")).size() > 0 ||
                page.homingStatus().startsWith(QLatin1String("Homing in order: referenced")),
            qPrintable(shown.join(QLatin1String(" | "))), 10000);
        disconnect(motion);
        disconnect(values);
        QVERIFY2(shown.filter(QLatin1String("motor 1 running")).size() > 0,
                 qPrintable(shown.join(QLatin1String(" | "))));
        QTRY_VERIFY_WITH_TIMEOUT(
            page.homingStatus().startsWith(QLatin1String("Homing in order: referenced")), 5000);
        QCOMPARE(simValue("motor1.position"), 0);
        QCOMPARE(simValue("motor2.position"), 0);
        QCOMPARE(page.homingStatus(),
                 QStringLiteral("Homing in order: referenced at (0.00, 0.00) mm"));
        QCOMPARE(page.panel(2)->referenceText(), QStringLiteral("referenced"));
        // Zeroing moves the zero: no axis is referenced after it.
        QTRY_VERIFY(page.zeroButton()->isEnabled());
        page.zeroButton()->click();
        QTRY_COMPARE(p->referenceText(), QStringLiteral("not referenced (coordinates zeroed)"));
    }

    // A bug once seen: E-STOP during homing showed "Idle — Homing done".
    void eStopDuringHomingIsNotReferenced()
    {
        connectSim();
        sim()->setMachinePosition(1, 60.0); // a long way from the home switch
        MotionPage page(session.get(), writes);
        showActive(&page);
        JogPanel *p = page.panel(1);
        QTRY_VERIFY(p->homeButton()->isEnabled());
        QSignalSpy messages(session.get(), &DeviceSession::message);
        p->homeButton()->click();
        QTRY_VERIFY(sim()->running(1));
        QTRY_VERIFY(p->statusText().startsWith(QStringLiteral("Homing motor 1…")));
        session->emergencyStop();
        QTRY_VERIFY2(p->statusText().contains(QLatin1String("(E-STOP): not referenced")),
                     qPrintable(p->statusText()));
        QVERIFY2(
            p->statusText().startsWith(QStringLiteral("Idle — Homing motor 1 interrupted at ")),
            qPrintable(p->statusText()));
        QVERIFY(sim()->position(1) != 0);
        QVERIFY(p->referenceText().startsWith(QLatin1String("not referenced")));
        StatusDock dock(session.get());
        QCOMPARE(dock.referenceText(1), QStringLiteral("not referenced (homing was interrupted)"));
        // Logged when it was known, in other words than when it was sent.
        QStringList said;
        for (const auto &m : std::as_const(messages))
            said << m.at(1).toString();
        QVERIFY2(said.contains(QStringLiteral("Home: sent")), qPrintable(said.join('|')));
        QVERIFY(!said.join('|').contains(QLatin1String("Home: done")));
        QVERIFY(said.last().contains(QLatin1String("not referenced")));
    }

    // After a possible restart the reference is not known: the strip says so, as the jog panel
    // and the status dock do, and does not guess "not referenced".
    void aReferenceNotKnownIsSaidAlikeEverywhere()
    {
        connectSim();
        ReferenceTracker *references = session->motion()->references();
        references->setReason(1, ReferenceTracker::Reason::Homed);
        EmergencyStop estop(session.get());
        MachineStrip strip(session.get(), &estop);
        StatusDock dock(session.get());
        MotionPage page(session.get(), writes);
        QTRY_COMPARE(strip.referenceLabel(1)->text(), QStringLiteral("referenced"));
        references->setReason(1, ReferenceTracker::Reason::Silent);
        QTRY_COMPARE(strip.referenceLabel(1)->text(), QStringLiteral("reference not known"));
        QVERIFY(dock.referenceText(1).startsWith(QLatin1String("reference not known")));
        QVERIFY(page.panel(1)->referenceText().startsWith(QLatin1String("reference not known")));
        QVERIFY(
            strip.referenceLabel(1)->toolTip().startsWith(QLatin1String("reference not known")));
        // What is known is still said as before.
        references->setReason(1, ReferenceTracker::Reason::Restarted);
        QTRY_COMPARE(strip.referenceLabel(1)->text(), QStringLiteral("not referenced"));
    }

    void aStopDuringASingleMoveSaysWhereItStopped()
    {
        connectSim();
        QVERIFY(sim()->setValue(QStringLiteral("motor1.move_distance"), 20000)); // 200 mm
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 120));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        MotionPage page(session.get(), writes);
        showActive(&page);
        JogPanel *p = page.panel(1);
        QTRY_VERIFY(p->moveButton()->isEnabled());
        p->moveButton()->click();
        QTRY_VERIFY(sim()->running(1));
        QTRY_VERIFY(p->statusText().startsWith(QStringLiteral("Single move of motor 1…")));
        QTest::mousePress(p->stopButton(), Qt::LeftButton);
        QTest::mouseRelease(p->stopButton(), Qt::LeftButton);
        QTRY_VERIFY2(
            p->statusText().contains(QLatin1String("not at the end point 200.00 mm (stop)")),
            qPrintable(p->statusText()));
        QVERIFY(p->statusText().contains(QLatin1String("stopped at ")));
        QVERIFY(!p->statusText().contains(QLatin1String("done")));
    }

    // A link lost while a move runs: not "done", the cause is the link, references are gone.
    void aLinkLostDuringAMoveIsSaid()
    {
        connectSim();
        QVERIFY(sim()->setValue(QStringLiteral("motor1.move_distance"), 20000));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 120));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        MotionSupervisor *motion = session->motion();
        session->command(QStringLiteral("motor1.home"));
        QTRY_VERIFY_WITH_TIMEOUT(motion->references()->isReferenced(1), 10000);
        QSignalSpy finished(motion, &MotionSupervisor::finished);
        session->command(QStringLiteral("motor1.move"));
        QTRY_VERIFY(motion->active(1).has_value());
        QTRY_VERIFY(sim()->running(1));
        test::simHost(*session)->hangUp(60000);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const auto o = motion->lastOutcome(1);
        QVERIFY(o);
        QCOMPARE(o->verdictWord(), QStringLiteral("stopped"));
        QCOMPARE(o->causeWord(), QStringLiteral("link_lost"));
        QVERIFY2(motion->text(*o).endsWith(QLatin1String("(link lost)")),
                 qPrintable(motion->text(*o)));
        QCOMPARE(motion->references()->reason(1), ReferenceTracker::Reason::LinkLost);
    }

    // F12 while a jog button is held: the jog ends on the page at once, not at the release.
    void eStopLetsGoOfAHeldJog()
    {
        EmergencyStop estop(session.get());
        MotionPage page(session.get(), writes);
        session->jog()->setSettleMs(50);
        showActive(&page);
        connectSim();
        JogPanel *p = page.panel(1);
        QTRY_VERIFY(p->forwardButton()->isEnabled());
        QTest::mousePress(p->forwardButton(), Qt::LeftButton);
        QTRY_VERIFY(sim()->running(1));
        QCOMPARE(p->statusText(), QStringLiteral("Jogging forward"));
        QTest::keyClick(&page, Qt::Key_F12);
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(!p->forwardButton()->isDown());
        QTRY_COMPARE(session->jog()->state(1), State::Idle);
        QVERIFY(p->statusText() != QStringLiteral("Jogging forward"));
        QTest::mouseRelease(p->forwardButton(), Qt::LeftButton);
        QVERIFY(!sim()->running(1));
    }

    void homingOrderRefusesDuplicates()
    {
        connectSim();
        MotionPage page(session.get(), writes);
        HomingOrderEditor *order = page.homingOrder();
        QCOMPARE(order->combo(0)->currentText(), QStringLiteral("Motor 1"));
        QCOMPARE(order->combo(1)->currentText(), QStringLiteral("Motor 2"));
        QVERIFY(!page.applyOrderButton()->isEnabled());
        QVERIFY(!order->choose(0, 2)); // motor 2 is already 2nd
        QVERIFY(page.bannerShown());
        QVERIFY2(page.bannerText().contains(QLatin1String("Motor 2 is already the 2nd")),
                 qPrintable(page.bannerText()));
        QCOMPARE(order->combo(0)->currentText(), QStringLiteral("Motor 1"));
        QVERIFY(!session->parameters()->store()->hasEdits());
        // The same through the list, as a user picks it.
        Q_EMIT order->combo(1)->activated(order->combo(1)->findText(QStringLiteral("Motor 1")));
        QCOMPARE(order->combo(1)->currentText(), QStringLiteral("Motor 2"));
        QVERIFY(!session->parameters()->store()->hasEdits());

        QVERIFY(order->choose(1, 0));
        QVERIFY(order->choose(0, 2));
        QVERIFY(!page.homeAllButton()->isEnabled()); // edited: the controller holds another order
        QVERIFY(page.applyOrderButton()->isEnabled());
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        page.applyOrderButton()->click();
        QVERIFY(writes->dialog()); // the write dialog of "Write changes", for the order alone
        writes->dialog()->accept();
        QTRY_COMPARE(written.size(), 1);
        QCOMPARE(simValue("homing.first"), 2);
        QCOMPARE(simValue("homing.second"), 0);
        QVERIFY(!session->parameters()->store()->hasEdits());
        QVERIFY(page.homeAllButton()->isEnabled());
    }

    void applySpeedWritesOnlyTheSpeed()
    {
        connectSim();
        MotionPage page(session.get(), writes);
        JogPanel *p = page.panel(2);
        QVERIFY(!p->applySpeedButton()->isEnabled());
        QVERIFY(session->parameters()
                    ->store()
                    ->edit(QStringLiteral("motor2.microsteps"), 16)
                    .isEmpty());
        p->speedField()->enterText(QStringLiteral("450"));
        QVERIFY(p->applySpeedButton()->isEnabled());
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        p->applySpeedButton()->click();
        QVERIFY(writes->dialog()); // the write dialog of "Write changes", for the speed alone
        writes->dialog()->accept();
        QTRY_COMPARE(written.size(), 1);
        QCOMPARE(simValue("motor2.speed"), 450);
        QCOMPARE(simValue("motor2.microsteps"), 8); // the other edit waits for "Write changes"
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor2.speed")),
                 ParameterStore::State::InSync);
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor2.microsteps")),
                 ParameterStore::State::Edited);
        QVERIFY(!p->applySpeedButton()->isEnabled());
    }

    void outputsShowInTheLeds()
    {
        connectSim();
        MotionPage page(session.get(), writes);
        QTRY_COMPARE(page.outputLed(1)->state(), Led::State::Off);
        page.outputButton(QStringLiteral("output1_on"))->click();
        QTRY_COMPARE(page.outputLed(1)->state(), Led::State::On);
        QVERIFY(sim()->output(1));
        QCOMPARE(page.outputLed(2)->state(), Led::State::Off);
        page.outputButton(QStringLiteral("output1_off"))->click();
        QTRY_COMPARE(page.outputLed(1)->state(), Led::State::Off);
        page.outputButton(QStringLiteral("outputs_all_on"))->click();
        QTRY_VERIFY(page.outputLed(1)->state() == Led::State::On &&
                    page.outputLed(2)->state() == Led::State::On &&
                    page.outputLed(3)->state() == Led::State::On);
        page.outputButton(QStringLiteral("outputs_all_off"))->click();
        QTRY_COMPARE(page.outputLed(3)->state(), Led::State::Off);
        session->connection()->disconnectFrom();
        QCOMPARE(page.outputLed(1)->state(), Led::State::Unknown);
        QVERIFY(!page.outputButton(QStringLiteral("output1_on"))->isEnabled());
    }

    // The page in both languages, light and dark, motor 2 jogging: each picture is checked.
    // STEPCOM_SCREENSHOTS=/tmp/shots tests_ui tst_motionpage screenshots keeps them to look at.
    void screenshots()
    {
        const test::ScreenshotDir dir;
        QVERIFY(dir.isValid());
        connectSim();
        const QPalette dark = stepcom::test::darkPalette();
        const QPalette light = QApplication::palette();
        for (const QString &lang : {QStringLiteral("en"), QStringLiteral("zh_CN")}) {
            Language::instance().setLanguage(lang);
            for (const bool isDark : {false, true}) {
                QApplication::setPalette(isDark ? dark : light);
                MotionPage page(session.get(), writes);
                page.resize(page.sizeHint().expandedTo(QSize(1000, 760)));
                page.show();
                QVERIFY(QTest::qWaitForWindowExposed(&page));
                page.keyboardCheck()->setChecked(true);
                session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 450);
                page.homingOrder()->choose(0, 2);
                QTest::mousePress(page.panel(2)->forwardButton(), Qt::LeftButton);
                QTRY_VERIFY_WITH_TIMEOUT(sim()->running(2) &&
                                             page.panel(2)->runningLed()->state() == Led::State::On,
                                         10000);
                const QString problem = test::saveAndCheckGrab(
                    &page,
                    dir.filePath(QStringLiteral("motion-%1%2.png")
                                     .arg(lang, isDark ? QStringLiteral("-dark") : QString())));
                QTest::mouseRelease(page.panel(2)->forwardButton(), Qt::LeftButton);
                session->parameters()->store()->revertAll();
                QVERIFY2(problem.isEmpty(), qPrintable(problem));
                QTRY_VERIFY_WITH_TIMEOUT(
                    !sim()->running(2) && session->jog()->state(2) == State::Idle, 10000);
            }
        }
        QApplication::setPalette(light);
        Language::instance().setLanguage(QStringLiteral("en"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestMotionPage, Gui)
#include "tst_motionpage.moc"
