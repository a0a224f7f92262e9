#include "dialogs/pendantdialog.h"
#include "map/factoryvalues.h"
#include "pendant/pendantcontrol.h"
#include "pendant/pendantserver.h"
#include "profile/profile.h"
#include "profile/profilefile.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/sessionlog.h"
#include "simsession.h"
#include "testregistry.h"
#include "widgets/docks/machinestrip.h"
#include "window/mainwindow.h"
#include "window/offlineactions.h"
#include "window/pendantactions.h"
#include "window/windowprobe.h"

#include <QAction>
#include <QCheckBox>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

// A phone as far as the window can tell: a WebSocket handshake on a plain socket (the window's
// tests need no WebSocket client of their own).
void openSocket(QTcpSocket &socket, const QUrl &page)
{
    socket.connectToHost(QStringLiteral("127.0.0.1"), quint16(page.port()));
    socket.write("GET " + page.path().toLatin1() +
                 "/ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\n"
                 "Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                 "Sec-WebSocket-Version: 13\r\n\r\n");
}

} // namespace

// Device → Pendant… in the window: the dialog with its QR code and address, the phones with
// Disconnect, jogging allowed or not, the holder and "Take control back", the strip's line.
class TestPendantWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void theDialogStartsPairsAndShowsThePhones()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session);
        MainWindow window(&session);
        window.show();
        test::connectToSimulator(session); // a session log is written from the first connection
        QAction *action = WindowProbe(window).action(QStringLiteral("pendant"));
        QVERIFY(action);
        QVERIFY(action->isEnabled());
        PendantServer *server = window.pendantActions()->server();
        QVERIFY(!server->isRunning()); // off at every start
        QVERIFY(WindowProbe(window).machineStrip()->pendantLabel()->isHidden());
        action->trigger();
        PendantDialog *dialog = window.pendantActions()->dialog();
        QVERIFY(dialog && dialog->isVisible());
        QVERIFY(!dialog->allowJog()->isEnabled());
        dialog->startButton()->click();
        if (!server->isRunning()) // port 8470 taken on this machine: any free one then
            QVERIFY2(server->start(QHostAddress::LocalHost, 0), qPrintable(server->error()));
        QTRY_VERIFY(dialog->allowJog()->isEnabled());
        QVERIFY(!dialog->allowJog()->isChecked());
        const QString url = server->url().toString();
        QVERIFY(url.contains(QStringLiteral("/p/") + server->token()));
        QCOMPARE(dialog->addressLabel()->text(), url);
        QVERIFY(!dialog->qrLabel()->pixmap().isNull());
        const QImage code = PendantDialog::qrCode(url, 4);
        QCOMPARE(code.width(), code.height());
        QVERIFY(code.width() >= (21 + 8) * 4); // at least a version-1 code with its quiet zone
        QCOMPARE(code.pixelColor(0, 0), QColor(Qt::white));
        QCOMPARE(WindowProbe(window).machineStrip()->pendantLabel()->text(),
                 QStringLiteral("Pendant: on, no phone yet"));

        QTcpSocket phone;
        openSocket(phone, server->url());
        QTRY_COMPARE(server->clients().size(), 1);
        QTRY_COMPARE(dialog->phones()->rowCount(), 1);
        QCOMPARE(dialog->phones()->item(0, 0)->text(), QStringLiteral("127.0.0.1"));
        QCOMPARE(WindowProbe(window).machineStrip()->pendantLabel()->text(),
                 QStringLiteral("Pendant: 1 phone watching"));
        QVERIFY(!dialog->takeBackButton()->isEnabled());

        dialog->allowJog()->click();
        QVERIFY(server->control()->isAllowed());
        QVERIFY(server->control()->take(server->clients().first().id).isEmpty());
        QCOMPARE(WindowProbe(window).machineStrip()->pendantLabel()->text(),
                 QStringLiteral("Pendant: jogging from 127.0.0.1"));
        QCOMPARE(dialog->controlLabel()->text(), QStringLiteral("Control: 127.0.0.1"));
        if (qEnvironmentVariableIsSet("STEPCOM_TEST_GRAB"))
            dialog->grab().save(qEnvironmentVariable("STEPCOM_TEST_GRAB")),
                code.save(qEnvironmentVariable("STEPCOM_TEST_GRAB") + QStringLiteral(".qr.png"));
        dialog->takeBackButton()->click();
        QCOMPARE(server->control()->holder(), 0);
        QCOMPARE(WindowProbe(window).machineStrip()->pendantLabel()->text(),
                 QStringLiteral("Pendant: 1 phone watching"));

        dialog->phones()->selectRow(0);
        QVERIFY(dialog->disconnectButton()->isEnabled());
        dialog->disconnectButton()->click();
        QTRY_VERIFY(server->clients().isEmpty());
        QTRY_VERIFY(phone.state() != QAbstractSocket::ConnectedState);

        // What the phones did is in the session log as user actions (a replay shows them).
        QFile log(WindowProbe(window).sessionLog()->currentFile());
        QVERIFY2(log.open(QIODevice::ReadOnly), qPrintable(log.fileName()));
        const QByteArray logged = log.readAll();
        QVERIFY2(logged.contains("user     pendant 127.0.0.1: took control"), logged.right(2000));
        QVERIFY(logged.contains("user     pendant: jogging allowed in the window"));

        dialog->startButton()->click(); // stop
        QVERIFY(!server->isRunning());
        QVERIFY(!server->control()->isAllowed()); // allowed for one run only
        QVERIFY(WindowProbe(window).machineStrip()->pendantLabel()->isHidden());
    }

    void aProfileEditedOfflineServesNoPendant()
    {
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        PendantServer *server = window.pendantActions()->server();
        QVERIFY(server->start(QHostAddress::LocalHost, 0));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("machine.json"));
        const Profile p =
            Profile::fromValues(session.map(), FactoryValues::writable(session.map()), false);
        QVERIFY(ProfileFile::save(path, p, session.map()).isEmpty());
        QVERIFY(WindowProbe(window).offlineActions()->openFile(path));
        QTRY_VERIFY(!server->isRunning()); // stopped, the phones told
        QAction *action = WindowProbe(window).action(QStringLiteral("pendant"));
        QVERIFY(!action->isEnabled());
        QVERIFY(!window.pendantActions()->refusal().isEmpty());
        QVERIFY(!window.pendantActions()->openDialog());
    }

    void aReplayServesNoPendant()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session);
        MainWindow window(&session);
        window.show();
        test::connectToSimulator(session); // a session log to replay
        const QString path = WindowProbe(window).sessionLog()->currentFile();
        session.connection()->disconnectFrom();
        PendantServer *server = window.pendantActions()->server();
        QVERIFY(server->start(QHostAddress::LocalHost, 0));
        QVERIFY(WindowProbe(window).replayMode()->openPath(path));
        QTRY_VERIFY_WITH_TIMEOUT(WindowProbe(window).replayMode()->isActive(), 20000);
        QTRY_VERIFY(!server->isRunning());
        QVERIFY(!WindowProbe(window).action(QStringLiteral("pendant"))->isEnabled());
        QVERIFY(!window.pendantActions()->openDialog());
    }
};

STEPCOM_TEST(TestPendantWindow, Gui)
#include "tst_pendantwindow.moc"
