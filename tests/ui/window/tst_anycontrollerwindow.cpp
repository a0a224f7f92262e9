// The window on any controller: a controller that answers in 2, 5, 15 or 35 ms on a
// modelled wire at 9600 and 38400 baud. The window polls it at its defaults: the machine strip
// follows the controller's positions as an axis moves and says when it stands, the strip's
// E-STOP stops it at once, and no message speaks of an echo or of a missing answer.
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/machinestrip.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

using namespace stepcom;

class TestAnyControllerWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void theWindowFollowsAnyController_data() { test::addAnswerTimeRows(); }
    void theWindowFollowsAnyController()
    {
        QFETCH(int, delayMs);
        QFETCH(int, baud);
        SimHost host;
        QVERIFY(test::startModelledController(host, delayMs, baud));
        SimDevice *sim = host.device();

        DeviceSession session;
        QStringList said;
        connect(&session, &DeviceSession::message, this,
                [&said](DeviceSession::Severity, const QString &text) { said << text; });
        MainWindow window(&session);
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        LinkSettings s;
        s.portName = host.rtuPath();
        s.baud = baud;
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        session.connection()->connectTo(s);
        QVERIFY(read.wait(10000) || !read.isEmpty());
        QVERIFY2(read.at(0).at(0).toBool(), qPrintable(said.join(QLatin1Char('\n'))));

        MachineStrip *strip = WindowProbe(window).machineStrip();
        QVERIFY(strip);
        const Parameter *position = session.map().find(QStringLiteral("motor1.position"));
        const auto shows = [&](qint64 raw) {
            return strip->positionLabel(1)->text().startsWith(position->displayRaw(raw));
        };
        // An axis moving: the strip says so and follows it.
        QVERIFY(sim->command(QStringLiteral("motor1.forward")));
        QTRY_COMPARE_WITH_TIMEOUT(strip->motion(1), MachineStrip::Motion::Running, 5000);
        const QString before = strip->positionLabel(1)->text();
        QTRY_VERIFY_WITH_TIMEOUT(strip->positionLabel(1)->text() != before, 5000);
        // The strip's E-STOP: the controller stops, the strip shows where it stood.
        QSignalSpy commands(&session, &DeviceSession::commandFinished);
        strip->emergencyStopButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!sim->running(1), 2000);
        const auto acknowledged = [&commands] {
            for (const QList<QVariant> &c : std::as_const(commands)) {
                if (c.at(0).toString() == QLatin1String("estop"))
                    return c.at(1).toBool();
            }
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(acknowledged(), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(strip->motion(1), MachineStrip::Motion::Idle, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(shows(sim->position(1)), 5000);
        // Nothing was taken for an echo, nothing went unanswered.
        const QString all = said.join(QLatin1Char('\n'));
        QVERIFY2(!all.contains(QLatin1String("echo"), Qt::CaseInsensitive), qPrintable(all));
        QVERIFY2(!all.contains(QLatin1String("no answer"), Qt::CaseInsensitive), qPrintable(all));
        session.connection()->disconnectFrom();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestAnyControllerWindow, Gui)
#include "tst_anycontrollerwindow.moc"
