// The window listening beside another master (a line of three: the PLC's pty, the simulated
// controller, the window's): the strip and the pages follow what the PLC reads and writes,
// marked as heard; the PLC's writes are listed; nothing can write, jog or poll and the
// window's pty sends nothing; the E-STOP asks first, then goes into the line and is
// acknowledged: its answer heard and both axes read back stopped.
#include "base/emergencystop.h"
#include "enabledcontrols.h"
#include "line/linksettingsstore.h"
#include "pages/connectionpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "sim/serve/linehub.h"
#include "widgets/docks/machinestrip.h"
#include "window/listenmode.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QComboBox>
#include <QFrame>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSerialPort>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

QByteArray rtu(const QByteArray &hex)
{
    QByteArray f = QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
    quint16 crc = 0xFFFF;
    for (const char c : f) {
        crc ^= quint8(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? quint16((crc >> 1) ^ 0xA001) : quint16(crc >> 1);
    }
    f.append(char(crc & 0xFF));
    f.append(char(crc >> 8));
    return f;
}

// The PLC: one request, and its answer read off the line before the next.
bool ask(QSerialPort &plc, const QByteArray &request, int answerBytes)
{
    plc.readAll();
    plc.write(request);
    QByteArray answer;
    return QTest::qWaitFor(
        [&] {
            answer += plc.readAll();
            return answer.size() >= answerBytes;
        },
        10000);
}

} // namespace

class TestListenWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void followsThePlcAndSendsNothing()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.checkBaud = false;
        options.answerDelayMs = 2;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        LineHub hub;
        QVERIFY2(hub.open(3, &error), qPrintable(error));
        QVERIFY2(hub.attach(host.ptyPath(), &error), qPrintable(error));

        DeviceSession session;
        MainWindow window(&session);
        window.resize(1280, 800);
        window.show();
        ListenMode *listen = window.listenMode();
        LinkSettings line;
        line.portName = hub.paths().at(2);
        QVERIFY2(listen->start(line, &error), qPrintable(error));
        QVERIFY(listen->banner()->isVisible());
        QVERIFY(session.parameters()->store()->isReplay()); // values shown are not StepCom's reads
        QVERIFY(!session.parameters()->store()->shownValue(QStringLiteral("motor1.speed")));

        QSerialPort plc;
        plc.setPortName(hub.paths().at(0));
        QVERIFY(plc.open(QIODevice::ReadWrite));
        // A write: in the store as heard, in the writes list.
        QVERIFY(ask(plc, rtu("01 06 00 05 03 09"), 8));
        QTRY_COMPARE(
            session.parameters()->store()->shownValue(QStringLiteral("motor1.speed")).value_or(0),
            777);
        QCOMPARE(listen->writes()->count(), 1);
        QVERIFY2(listen->writes()->item(0)->text().contains(u"motor1.speed = 777 rpm"),
                 qPrintable(listen->writes()->item(0)->text()));
        // The positions the PLC polls reach the strip; a move it starts moves the strip too.
        MachineStrip *strip = window.findChild<MachineStrip *>();
        QVERIFY(strip);
        QVERIFY(ask(plc, rtu("01 03 00 6B 00 04"), 13));
        QTRY_VERIFY(session.parameters()
                        ->store()
                        ->shownValue(QStringLiteral("motor1.position"))
                        .has_value());
        const QString before = strip->positionLabel(1)->text();
        QVERIFY(ask(plc, rtu("01 05 00 00 FF 00"), 8)); // motor1.move
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                ask(plc, rtu("01 03 00 6B 00 04"), 13);
                return session.parameters()
                           ->store()
                           ->shownValue(QStringLiteral("motor1.position"))
                           .value_or(0) != 0;
            }(),
            20000);
        QTRY_VERIFY(strip->positionLabel(1)->text() != before);
        QCOMPARE(listen->writes()->count(), 2); // the move command is the PLC's too

        // Nothing that writes, jogs or polls is on; the window sent nothing.
        QCOMPARE(enabledControls(&window, {QStringLiteral("stopListening")}), QStringList());
        QVERIFY(!session.connection()->isConnected());
        QCOMPARE(hub.bytesSent(2), 0);

        // The E-STOP asks first; nothing leaves until it is confirmed.
        WindowProbe(window).emergencyStop()->trigger();
        QTRY_VERIFY(listen->estopQuestion() && listen->estopQuestion()->isVisible());
        QTest::qWait(100);
        QCOMPARE(hub.bytesSent(2), 0);
        QSignalSpy said(listen, &ListenMode::finished);
        listen->estopQuestion()->button(QMessageBox::Yes)->click();
        QTRY_VERIFY(hub.bytesSent(2) >= 8);
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                for (const QList<QVariant> &s : said)
                    if (s.at(1).toString() ==
                        u"E-STOP acknowledged by controller 1: both axes stopped")
                        return true;
                return false;
            }(),
            10000);
        QVERIFY(said.first().at(1).toString() ==
                QStringLiteral("E-STOP sent into a line driven by another master"));
        QVERIFY(hub.bytesSent(2) >= 16); // the E-STOP, then the read of the motion state

        listen->stop();
        QVERIFY(!session.parameters()->store()->isReplay());
        QVERIFY(!listen->banner()->isVisible());
        hub.close();
        host.stop();
    }

    // The RS-485 direction is chosen on the Connection page and kept with the line.
    void rs485OnTheConnectionPage()
    {
        DeviceSession session;
        MainWindow window(&session);
        auto *page = window.findChild<ConnectionPage *>();
        QVERIFY(page);
        auto *rs485 = page->findChild<QComboBox *>(QStringLiteral("rs485"));
        QVERIFY(rs485);
        QCOMPARE(page->currentSettings().rs485, LinkSettings::Rs485::Auto);
        rs485->setCurrentIndex(2);
        QCOMPARE(page->currentSettings().rs485, LinkSettings::Rs485::Rts);
        QTemporaryDir dir;
        QSettings store(dir.filePath(QStringLiteral("line.ini")), QSettings::IniFormat);
        LinkSettings line = page->currentSettings();
        line.rs485 = LinkSettings::Rs485::Kernel;
        line.rs485DelayAfterUs = 500;
        LinkSettingsStore::write(store, line);
        const LinkSettings back = LinkSettingsStore::read(store);
        QCOMPARE(back.rs485, LinkSettings::Rs485::Kernel);
        QCOMPARE(back.rs485DelayAfterUs, 500);
        page->applySettings(back);
        QCOMPARE(rs485->currentIndex(), 1);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestListenWindow, Gui)
#include "tst_listenwindow.moc"
