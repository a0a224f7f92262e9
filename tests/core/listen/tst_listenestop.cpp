// The E-STOP sent into a line another master drives, through an adapter that hears its own
// bytes (LineHub's echo on the listener's party): a PLC (pymodbus) polls the line, the listener
// sends the E-STOP. Its own echo is never taken for the controller's acknowledgement: with the
// controller off the line the E-STOP is not acknowledged; with it on the line it is, the
// motion state read back; without an echo as before.
#include "listen/linelistener.h"
#include "map/registermap.h"
#include "sim/host/simhost.h"
#include "sim/serve/linehub.h"
#include "testpaths.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

struct Outcome
{
    // What emergencyStopSettled said.
    bool settled = false;
    bool acknowledged = false;
    QString text;
    int echoSuspected = 0;
};

} // namespace

class TestListenEstop : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        if (QProcess::execute(QStringLiteral("/usr/bin/python3"),
                              {QStringLiteral("-c"), QStringLiteral("import pymodbus.client")}) !=
            0)
            QSKIP("python3-pymodbus is missing (scripts/deps.sh --test)");
    }

    void throughAnAdapter_data()
    {
        QTest::addColumn<bool>("adapterEchoes");
        QTest::addColumn<bool>("echoOption");
        QTest::addColumn<bool>("controller");
        QTest::addColumn<QString>("said");
        const QString stopped =
            QStringLiteral("E-STOP acknowledged by controller 1: both axes stopped");
        QTest::newRow("echo, controller off the line")
            << true << true << false << "not acknowledged by controller 1: only our own echo heard";
        QTest::newRow("echo not set, controller off the line")
            << true << false << false
            << "not acknowledged by controller 1: only our own echo heard";
        QTest::newRow("echo, controller on the line") << true << true << true << stopped;
        QTest::newRow("echo not set, controller on the line") << true << false << true << stopped;
        QTest::newRow("no echo, controller on the line") << false << false << true << stopped;
        QTest::newRow("echo set, none heard, controller on the line")
            << false << true << true << stopped;
        QTest::newRow("no echo, controller off the line")
            << false << false << false << "and controller 1 never answered it";
    }
    void throughAnAdapter()
    {
        QFETCH(bool, adapterEchoes);
        QFETCH(bool, echoOption);
        QFETCH(bool, controller);
        QFETCH(QString, said);

        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.checkBaud = false;
        options.answerDelayMs = 5;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        LineHub hub;
        QVERIFY2(hub.open(2, &error), qPrintable(error));
        if (controller)
            QVERIFY2(hub.attach(host.ptyPath(), &error), qPrintable(error));
        hub.setEcho(1, adapterEchoes);
        const QStringList paths = hub.paths();

        LineListener listener(&RegisterMap::builtin());
        listener.setMayTransmit(true);
        LinkSettings line;
        line.portName = paths.at(1);
        line.baud = 38400;
        line.echo = echoOption;
        QVERIFY2(listener.open(line, &error), qPrintable(error));
        QSignalSpy frames(&listener, &LineListener::frameHeard);

        QProcess plc;
        plc.start(QStringLiteral("/usr/bin/python3"),
                  {sourcePath(QStringLiteral("tests/fixtures/plc_master.py")), paths.at(0),
                   QStringLiteral("38400"), QStringLiteral("60")});
        QVERIFY(plc.waitForStarted());
        // The PLC is on the line before the E-STOP goes into it.
        QTRY_VERIFY_WITH_TIMEOUT(frames.size() >= 2, 20000);

        Outcome outcome;
        connect(&listener, &LineListener::emergencyStopSettled, this,
                [&](bool acknowledged, const QString &text) {
                    QVERIFY(!outcome.settled); // said once
                    outcome.settled = true;
                    outcome.acknowledged = acknowledged;
                    outcome.text = text;
                });
        connect(&listener, &LineListener::echoSuspected, this, [&] { ++outcome.echoSuspected; });
        QVERIFY(listener.sendEmergencyStop(1));
        QTRY_VERIFY_WITH_TIMEOUT(outcome.settled, 60000);
        QVERIFY2(outcome.text.contains(said), qPrintable(outcome.text));
        QCOMPARE(outcome.acknowledged, controller);
        // The echo went unnoticed only when the option said so; said once.
        QCOMPARE(outcome.echoSuspected, adapterEchoes && !echoOption ? 1 : 0);
        // The E-STOP is the system's (coil 00042), not a motor's stop the PLC also writes.
        QVERIFY(LineListener::emergencyStopFrame(RegisterMap::builtin(), 1)
                    .startsWith(QByteArray::fromHex("01050029ff00")));
        // Past the E-STOP, the read of the motion state went out too.
        QVERIFY(hub.bytesSent(1) >= (controller ? 16 : 8));
        QVERIFY(!listener.isSending());

        plc.kill();
        plc.waitForFinished(5000);
        listener.close();
        hub.close();
        host.stop();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestListenEstop, Guiless)
#include "tst_listenestop.moc"
