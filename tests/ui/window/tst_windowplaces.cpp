// One place for each live value, one E-STOP: the machine strip carries the machine's state (the
// positions, the motion, the lamps) and the window's only E-STOP; the Status dock, which shows
// the same, is off until the View menu brings it back; how often the status is read, and was,
// is the Connection page's Link box; the Jog page shows what the jog does, not a third
// position. While a replay or a profile file stands where the controller's values would and
// nothing is connected, the E-STOP has nothing to stop: greyed, its tooltip says why, and F12
// still reaches the session from every page and dialog.
#include "base/emergencystop.h"
#include "base/language.h"
#include "base/page.h"
#include "logbuilder.h"
#include "pages/connectionpage.h"
#include "pages/motionpage.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "simsession.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/statusdock.h"
#include "widgets/fields/statuspollrow.h"
#include "window/mainwindow.h"
#include "window/offlineactions.h"
#include "window/windowprobe.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

using namespace stepcom;

namespace {

// The E-STOP buttons the user can see now, on the window and every dialog open over it.
QList<QToolButton *> shownEmergencyStops(QWidget *window)
{
    QList<QToolButton *> shown;
    for (QToolButton *b :
         window->findChildren<QToolButton *>(QStringLiteral("emergencyStopButton"))) {
        if (b->isVisibleTo(window) && !b->visibleRegion().isEmpty())
            shown << b;
    }
    return shown;
}

// Texts shown on `root` that look like a position of the map's unit ("12.50 mm", "—" aside).
QStringList positionTexts(QWidget *root, const QString &position)
{
    QStringList found;
    for (QLabel *label : root->findChildren<QLabel *>()) {
        if (label->isVisibleTo(root) && label->text() == position)
            found << label->objectName();
    }
    return found;
}

} // namespace

class TestWindowPlaces : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QSettings().clear();
        Language::instance().setLanguage(QStringLiteral("en"));
    }

    // Two E-STOPs were always on screen (the toolbar's and the strip's): one remains, on
    // every page, and the window's accessor is that one.
    void oneEmergencyStopOnEveryPage()
    {
        DeviceSession session;
        MainWindow window(&session);
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i) {
            WindowProbe(window).showPage(i);
            QCoreApplication::processEvents();
            const QList<QToolButton *> shown = shownEmergencyStops(&window);
            QVERIFY2(shown.size() == 1,
                     qPrintable(QStringLiteral("%1 E-STOPs on %2")
                                    .arg(shown.size())
                                    .arg(WindowProbe(window).pages().at(i)->title())));
            QCOMPARE(shown.first(), WindowProbe(window).emergencyStopButton());
            QCOMPARE(shown.first(), WindowProbe(window).machineStrip()->emergencyStopButton());
        }
    }

    // The Jog page at 1280×800, connected: each motor's position shows once, in the strip;
    // the Status dock is off (the View menu brings it back, and then it is the user's choice).
    void theJogPageShowsEachPositionOnce()
    {
        QSettings().clear();
        DeviceSession session;
        MainWindow window(&session);
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        test::connectToSimulator(session);
        WindowProbe(window).showPage(
            int(WindowProbe(window).pages().indexOf(WindowProbe(window).motionPage())));
        QLabel *strip1 = WindowProbe(window).machineStrip()->positionLabel(1);
        QTRY_VERIFY(strip1->text() != QStringLiteral("—"));
        // A few more status cycles: every view has had its update.
        QVERIFY(test::waitForStatusCycles(session, 3));
        const QString position = strip1->text();
        QVERIFY(!WindowProbe(window).statusDock()->isVisible());
        const QStringList shown = positionTexts(&window, position);
        QVERIFY2(shown.size() == 2, qPrintable(shown.join(QStringLiteral(", ")))); // both motors
        QVERIFY(shown.contains(QStringLiteral("stripPosition1")));
        QVERIFY(shown.contains(QStringLiteral("stripPosition2")));
        QAction *toggle = WindowProbe(window).statusDock()->toggleViewAction();
        toggle->trigger();
        QVERIFY(WindowProbe(window).statusDock()->isVisible());
        session.connection()->disconnectFrom();
    }

    // The update rate and the poll choice are where the link is described: the Connection
    // page's Link box, not the Status dock.
    void pollChoiceAndRateLiveWithTheLink()
    {
        DeviceSession session;
        MainWindow window(&session);
        ConnectionPage *connection = nullptr;
        for (Page *p : WindowProbe(window).pages())
            connection = connection ? connection : qobject_cast<ConnectionPage *>(p);
        QVERIFY(connection);
        QVERIFY(connection->statusPoll());
        QVERIFY(connection->isAncestorOf(connection->statusPoll()->intervalBox()));
        QVERIFY(!WindowProbe(window).statusDock()->findChild<QComboBox *>(
            QStringLiteral("pollInterval")));
        QVERIFY(
            !WindowProbe(window).statusDock()->findChild<QLabel *>(QStringLiteral("statusRate")));
        QCOMPARE(window.findChildren<QComboBox *>(QStringLiteral("pollInterval")).size(), 1);
    }

    // Replay and offline editing with nothing connected: the E-STOP is greyed and says why;
    // connected, it is red again. F12 still goes to the session (it says nothing was sent).
    void emergencyStopHasNothingToStopWithoutAController()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session);
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QToolButton *estop = WindowProbe(window).emergencyStopButton();
        QAction *menu = WindowProbe(window).action(QStringLiteral("emergencyStop"));
        QVERIFY(estop->isEnabled()); // nothing open: a reconnect would still take it
        // A profile file edited without a controller.
        QVERIFY(WindowProbe(window).offlineActions()->newFromFactory());
        QTRY_VERIFY(!estop->isEnabled());
        QVERIFY(!menu->isEnabled());
        QVERIFY2(estop->toolTip().contains(QStringLiteral("Nothing to stop")),
                 qPrintable(estop->toolTip()));
        QVERIFY(estop->toolTip().contains(QStringLiteral("profile file")));
        QVERIFY(!WindowProbe(window).machineStrip()->emergencyStopButton()->isEnabled());
        QSignalSpy stops(WindowProbe(window).emergencyStop(), &EmergencyStop::triggered);
        QTest::keyClick(&window, Qt::Key_F12);
        QCOMPARE(stops.size(), 1);
        QVERIFY(WindowProbe(window).offlineActions()->closeFile());
        QTRY_VERIFY(estop->isEnabled());

        // A session log replayed.
        const Parameter *speed = session.map().find(QStringLiteral("motor1.speed"));
        QVERIFY(speed);
        test::LogBuilder log;
        log.header();
        log.read(1, speed->address, {300});
        const QString path = log.save(dir, QStringLiteral("replayed.log"));
        QSignalSpy opened(WindowProbe(window).replayMode(), &ReplayMode::opened);
        QVERIFY(WindowProbe(window).replayMode()->openPath(path));
        QVERIFY(opened.wait(10000) || !opened.isEmpty());
        QTRY_VERIFY(!estop->isEnabled());
        QVERIFY2(estop->toolTip().contains(QStringLiteral("replayed")),
                 qPrintable(estop->toolTip()));
        QVERIFY(menu->toolTip().contains(QStringLiteral("Nothing to stop")));
        // In Chinese too.
        const QString english = estop->toolTip();
        Language::instance().setLanguage(QStringLiteral("zh_CN"));
        QCoreApplication::processEvents();
        QVERIFY2(estop->toolTip() != english, qPrintable(estop->toolTip()));
        QCOMPARE(estop->text(), QStringLiteral("急停"));
        Language::instance().setLanguage(QStringLiteral("en"));
        // Connecting ends the replay: a controller to stop again.
        session.connection()->connectSimulator();
        QTRY_VERIFY(session.connection()->isConnected());
        QTRY_VERIFY(estop->isEnabled());
        QVERIFY(menu->isEnabled());
        QVERIFY(estop->toolTip().contains(QStringLiteral("coil 00042")));
        session.connection()->disconnectFrom();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestWindowPlaces, Gui)
#include "tst_windowplaces.moc"
