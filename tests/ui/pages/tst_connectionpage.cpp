#include "bus/modbuslink.h"
#include "dialogs/busscandialog.h"
#include "line/busscanner.h"
#include "pages/connectionpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

#include <memory>

using namespace stepcom;

// The Connection page and the bus scan dialog, driven like a technician would, against the
// built-in simulator and a simulator on a pty.
class TstConnectionPage : public QObject
{
    Q_OBJECT

private:
    static QPushButton *button(QWidget *parent, const char *name)
    {
        auto *b = parent->findChild<QPushButton *>(QLatin1String(name));
        if (!b)
            qWarning("no button %s", name);
        return b;
    }
    static void click(QWidget *parent, const char *name)
    {
        QPushButton *b = button(parent, name);
        QVERIFY(b);
        QVERIFY2(b->isEnabled(), name);
        QTest::mouseClick(b, Qt::LeftButton);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("StepComTest");
        QCoreApplication::setApplicationName("tst_connectionpage");
    }

    void init()
    {
        QSettings().remove("connection"); // every test starts from the factory defaults
    }

    void defaults()
    {
        DeviceSession session;
        ConnectionPage page(&session);
        QCOMPARE(page.title(), QString("Connection"));
        QCOMPARE(page.transport(), ConnectionPage::Transport::Serial);
        const LinkSettings s = page.currentSettings();
        QCOMPARE(s.transport, LinkSettings::Transport::Rtu);
        QCOMPARE(s.baud, 9600);
        QCOMPARE(s.parity, QSerialPort::NoParity);
        QCOMPARE(s.stopBits, QSerialPort::OneStop);
        QCOMPARE(s.deviceId, 1);
        QCOMPARE(s.timeoutMs, 500);
        QCOMPARE(s.retries, 2);
        QCOMPARE(s.tcpPort, 502);
        // The port can be typed: pseudo-terminals are never listed.
        auto *port = page.findChild<QComboBox *>("port");
        QVERIFY(port && port->isEditable());
        QVERIFY(page.statusText().contains("Not connected"));
    }

    void roundTrip_data()
    {
        QTest::addColumn<bool>("tcp");
        QTest::newRow("serial") << false;
        QTest::newRow("tcp") << true;
    }
    void roundTrip()
    {
        QFETCH(bool, tcp);
        DeviceSession session;
        ConnectionPage page(&session);
        LinkSettings s;
        s.transport = tcp ? LinkSettings::Transport::Tcp : LinkSettings::Transport::Rtu;
        s.portName = "/dev/pts/77";
        s.baud = 38400;
        s.parity = QSerialPort::EvenParity;
        s.stopBits = QSerialPort::TwoStop;
        s.host = "10.0.0.9";
        s.tcpPort = 1502;
        s.deviceId = 42;
        s.timeoutMs = 750;
        s.retries = 4;
        page.applySettings(s);
        QCOMPARE(page.currentSettings(), s);
        QCOMPARE(page.transport(),
                 tcp ? ConnectionPage::Transport::Tcp : ConnectionPage::Transport::Serial);
        // Only the chosen transport's fields are shown.
        page.show();
        QCOMPARE(page.findChild<QComboBox *>("port")->isVisible(), !tcp);
        QCOMPARE(page.findChild<QWidget *>("host")->isVisible(), tcp);
    }

    void simulatorConnectAndDisconnect()
    {
        DeviceSession session;
        stepcom::test::useBuiltinSimulator(session); // as the stepcom program does
        ConnectionPage page(&session);
        page.show();
        const auto radios = page.findChildren<QRadioButton *>();
        QCOMPARE(radios.size(), 3);
        QTest::mouseClick(radios.at(2), Qt::LeftButton, {}, QPoint(4, 4));
        QCOMPARE(page.transport(), ConnectionPage::Transport::Simulator);
        QVERIFY(!page.findChild<QComboBox *>("port")->isVisible());
        click(&page, "connect");
        QTRY_VERIFY_WITH_TIMEOUT(session.connection()->isConnected(), 5000);
        QVERIFY(session.connection()->isSimulator());
        QTRY_COMPARE_WITH_TIMEOUT(
            session.parameters()->store()->deviceValue("motor1.step_angle").value_or(-1),
            qint64(180), 5000);
        QVERIFY2(page.statusText().contains("Connected to the built-in simulator"),
                 qPrintable(page.statusText()));
        // The simulator's pty is not a setting: the page stays on the simulator choice.
        QCOMPARE(page.transport(), ConnectionPage::Transport::Simulator);
        QCOMPARE(page.currentSettings().portName, QString());
        QVERIFY(page.findChild<QLabel *>("status")->text().contains("built-in simulator"));
        QVERIFY(!button(&page, "connect")->isEnabled());
        click(&page, "disconnect");
        QTRY_VERIFY(!session.connection()->isConnected());
        QVERIFY(!session.parameters()->store()->deviceValue("motor1.step_angle").has_value());
        QVERIFY(page.statusText().contains("Disconnected"));
        QVERIFY(button(&page, "connect")->isEnabled());
    }

    void missingPortNamesThePort()
    {
        DeviceSession session;
        ConnectionPage page(&session);
        LinkSettings s;
        s.portName = "/dev/stepcom-no-such-port";
        page.applySettings(s);
        click(&page, "connect");
        QTRY_VERIFY(page.statusText().contains("/dev/stepcom-no-such-port"));
        QVERIFY(!session.connection()->isConnected());
        const auto *label = page.findChild<QLabel *>("status");
        QVERIFY(label->text().contains("Could not connect"));
        QVERIFY(label->text().contains("/dev/stepcom-no-such-port"));
    }

    void settingsRemembered()
    {
        DeviceSession session;
        LinkSettings s;
        s.transport = LinkSettings::Transport::Tcp;
        s.portName = "/dev/ttyUSB3";
        s.baud = 19200;
        s.parity = QSerialPort::OddParity;
        s.host = "192.168.7.7";
        s.tcpPort = 5020;
        s.deviceId = 9;
        s.timeoutMs = 300;
        s.retries = 1;
        s.answerDelayMs = 20;
        s.turnaroundMs = 5;
        s.echo = true;
        {
            ConnectionPage page(&session);
            page.applySettings(s);
        }
        {
            ConnectionPage page(&session);
            QCOMPARE(page.currentSettings(), s);
            QCOMPARE(page.transport(), ConnectionPage::Transport::Tcp);
            page.setTransport(ConnectionPage::Transport::Simulator);
        }
        ConnectionPage page(&session);
        QCOMPARE(page.transport(), ConnectionPage::Transport::Simulator);
        QCOMPARE(page.currentSettings(), s);
        // In the test location, never in the user's own settings.
        QVERIFY(QSettings().fileName().contains(".qttest"));
    }

    void echoingAdapterIsOfferedTheEchoOption()
    {
        SimHost sim;
        SimOptions options;
        options.rtu = true;
        options.echo = true; // a half-duplex adapter without echo suppression
        QString error;
        QVERIFY2(sim.start(options, &error), qPrintable(error));

        DeviceSession session;
        ConnectionPage page(&session);
        LinkSettings s;
        s.portName = sim.rtuPath();
        s.timeoutMs = 200;
        s.retries = 0;
        page.applySettings(s);
        page.show();
        QPushButton *accept = button(&page, "acceptEcho");
        QVERIFY(accept && !accept->isVisible());
        click(&page, "connect");
        // Answers begin with the request's own bytes: said, and the option offered.
        QTRY_VERIFY_WITH_TIMEOUT(accept->isVisible(), 5000);
        QVERIFY(!session.parameters()->store()->deviceValue("motor1.step_angle").has_value());
        click(&page, "acceptEcho");
        QVERIFY(!accept->isVisible());
        QVERIFY(page.currentSettings().echo);
        QTRY_VERIFY_WITH_TIMEOUT(
            session.connection()->isConnected() && session.connection()->settings().echo, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(
            session.parameters()->store()->deviceValue("motor1.step_angle").has_value(), 5000);
        QVERIFY(!accept->isVisible());
        session.connection()->disconnectFrom();
    }

    void busScanFindsTheSimulator()
    {
        SimHost sim;
        SimOptions options;
        options.rtu = true;
        options.deviceId = 7;
        QString error;
        QVERIFY2(sim.start(options, &error), qPrintable(error));
        QCOMPARE(sim.device()->baud(), 9600);
        const QString path = sim.rtuPath();
        QVERIFY(!path.isEmpty());

        DeviceSession session;
        ConnectionPage page(&session);
        LinkSettings s;
        s.portName = path;
        s.deviceId = 1; // the forgotten id
        page.applySettings(s);
        page.show();
        click(&page, "scan");
        BusScanDialog *dialog = page.scanDialog();
        QVERIFY(dialog && dialog->isVisible());
        QCOMPARE(dialog->baseSettings().portName, path);

        // Checkboxes all on by default, 1-247, 150 ms: set a short scan like a technician.
        QCOMPARE(dialog->checkedBauds(), QList<int>({4800, 9600, 19200, 38400}));
        QCOMPARE(dialog->findChild<QSpinBox *>("lastId")->value(), 247);
        dialog->findChild<QCheckBox *>("baud4800")->setChecked(false);
        dialog->findChild<QCheckBox *>("baud38400")->setChecked(false);
        dialog->findChild<QSpinBox *>("lastId")->setValue(10);
        dialog->findChild<QSpinBox *>("probeTimeout")->setValue(80);
        QSignalSpy progress(dialog->scanner(), &BusScanner::progress);
        QSignalSpy finished(dialog->scanner(), &BusScanner::finished);
        click(dialog, "start");
        QVERIFY(dialog->isScanning());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(finished.at(0).at(1).toString(), QString());
        QCOMPARE(progress.size(), 20); // ids 1-10 at two bauds: the silence at 19200 was waited out
        QCOMPARE(dialog->foundCount(), 1);
        QCOMPARE(dialog->settingsFor(0).baud, 9600);
        QCOMPARE(dialog->settingsFor(0).deviceId, 7);
        QVERIFY(sim.stats().wrongBaud > 0);

        QSignalSpy requested(dialog, &BusScanDialog::connectRequested);
        click(dialog, "connect");
        QCOMPARE(requested.size(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(session.connection()->isConnected(), 5000);
        QCOMPARE(session.connection()->settings().deviceId, 7);
        QCOMPARE(session.connection()->settings().baud, 9600);
        QCOMPARE(page.currentSettings().deviceId, 7);
        QTRY_VERIFY_WITH_TIMEOUT(
            session.parameters()->store()->deviceValue("motor1.step_angle").has_value(), 5000);
        session.connection()->disconnectFrom();
    }

    void busScanDisconnectsFirstAndCancels()
    {
        SimHost sim;
        SimOptions options;
        options.rtu = true;
        QString error;
        QVERIFY2(sim.start(options, &error), qPrintable(error));

        DeviceSession session;
        ConnectionPage page(&session);
        LinkSettings s;
        s.portName = sim.rtuPath();
        page.applySettings(s);
        click(&page, "connect");
        QTRY_VERIFY_WITH_TIMEOUT(session.connection()->isConnected(), 5000);

        BusScanDialog *dialog = page.openBusScan();
        auto *warning = dialog->findChild<QLabel *>("warning");
        QVERIFY(warning->isVisible());
        QVERIFY(warning->text().contains("disconnects first"));
        click(dialog, "start");
        QVERIFY(!session.connection()->isConnected());
        QVERIFY(dialog->isScanning());
        click(dialog, "cancel");
        QVERIFY(!dialog->isScanning()); // at once, not after the probe in flight
        QVERIFY(dialog->statusText().contains("cancelled"));
        // No baud rate chosen: nothing starts, and the dialog says why.
        dialog->setCheckedBauds({});
        click(dialog, "start");
        QVERIFY(!dialog->isScanning());
        QVERIFY(dialog->statusText().contains("at least one baud"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstConnectionPage, Gui)
#include "tst_connectionpage.moc"
