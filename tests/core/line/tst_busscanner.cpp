// Scan results a person reads: "id 7 at 9600 8N1 — a 2-axis controller, step angle 1.80°",
// from what the device showed, and a real scan of the simulator at id 7.
#include "line/busscanner.h"
#include "map/registermap.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace stepcom;

class TestBusScanner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void where_data()
    {
        QTest::addColumn<int>("baud");
        QTest::addColumn<int>("parity");
        QTest::addColumn<int>("stopBits");
        QTest::addColumn<QString>("text");
        QTest::newRow("9600 8N1") << 9600 << int(QSerialPort::NoParity) << int(QSerialPort::OneStop)
                                  << "9600 8N1";
        QTest::newRow("19200 8E1")
            << 19200 << int(QSerialPort::EvenParity) << int(QSerialPort::OneStop) << "19200 8E1";
        QTest::newRow("4800 8O2") << 4800 << int(QSerialPort::OddParity)
                                  << int(QSerialPort::TwoStop) << "4800 8O2";
    }
    void where()
    {
        QFETCH(int, baud);
        QFETCH(int, parity);
        QFETCH(int, stopBits);
        QFETCH(QString, text);
        LinkSettings s;
        s.baud = baud;
        s.parity = QSerialPort::Parity(parity);
        s.stopBits = QSerialPort::StopBits(stopBits);
        QCOMPARE(BusScanner::where(s), text);
        s.transport = LinkSettings::Transport::Tcp;
        s.host = QStringLiteral("192.168.1.20");
        s.tcpPort = 502;
        QCOMPARE(BusScanner::where(s), QStringLiteral("192.168.1.20:502"));
    }

    void describe_data()
    {
        QTest::addColumn<QList<qint64>>("angles");
        QTest::addColumn<int>("exception");
        QTest::addColumn<QString>("summary");
        QTest::newRow("two motors alike")
            << QList<qint64>{180, 180} << 0
            << "id 7 at 9600 8N1 — a 2-axis controller, step angle 1.80°";
        QTest::newRow("two motors differ")
            << QList<qint64>{180, 90} << 0
            << "id 7 at 9600 8N1 — a 2-axis controller, step angles 1.80° and 0.90°";
        QTest::newRow("motor 2 unread")
            << QList<qint64>{180} << 0
            << "id 7 at 9600 8N1 — a controller, step angle 1.80° (only 1 of 2 motors answered)";
        QTest::newRow("refused")
            << QList<qint64>{} << 2
            << "id 7 at 9600 8N1 — a device that refused the first register: illegal data "
               "address (02)";
    }
    void describe()
    {
        QFETCH(QList<qint64>, angles);
        QFETCH(int, exception);
        QFETCH(QString, summary);
        BusScanner::Found f;
        f.baud = 9600;
        f.deviceId = 7;
        f.where = QStringLiteral("9600 8N1");
        f.stepAngles = angles;
        f.exceptionCode = exception;
        f.motorsInMap = RegisterMap::builtin().blockCount(QStringLiteral("motor"));
        QCOMPARE(f.motorsInMap, 2);
        f.detail = BusScanner::describe(f, RegisterMap::builtin());
        QCOMPARE(f.summary(), summary);
        QVERIFY(!f.summary().contains(QStringLiteral("40001")));
    }

    // The simulator at id 7: found, with both motors' step angles read from the device.
    void scanTheSimulator()
    {
        SimHost sim;
        SimOptions options;
        options.rtu = true;
        options.deviceId = 7;
        QString error;
        QVERIFY2(sim.start(options, &error), qPrintable(error));
        BusScanner scanner;
        QSignalSpy finished(&scanner, &BusScanner::finished);
        LinkSettings s;
        s.portName = sim.rtuPath();
        scanner.start(s, {9600}, 6, 8, 100);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(scanner.found().size(), 1);
        const BusScanner::Found f = scanner.found().first();
        QCOMPARE(f.stepAngles,
                 (QList<qint64>{*sim.device()->value(QStringLiteral("motor1.step_angle")),
                                *sim.device()->value(QStringLiteral("motor2.step_angle"))}));
        QCOMPARE(f.summary(),
                 QStringLiteral("id 7 at 9600 8N1 — a 2-axis controller, step angle 1.80°"));
    }

    // Request frame (8 bytes) + the 35 ms answer delay + the longest answer (7 bytes) + the
    // margin: USB adapters on a serial line, a converter's buffering over a network.
    void fittedProbeTimeout()
    {
        LinkSettings s;
        s.baud = 9600; // 15 characters of 10 bits: 15.6 ms
        QCOMPARE(BusScanner::fittedProbeTimeoutMs(s), 51 + BusScanner::kUsbMarginMs);
        s.baud = 19200;
        s.parity = QSerialPort::EvenParity; // 11 bits: 8.6 ms
        QCOMPARE(BusScanner::fittedProbeTimeoutMs(s), 44 + BusScanner::kUsbMarginMs);
        s.baud = 4800;
        s.parity = QSerialPort::NoParity;
        s.answerDelayMs = 100; // a controller set to answer later
        QCOMPARE(BusScanner::fittedProbeTimeoutMs(s), 132 + BusScanner::kUsbMarginMs);
        s.answerDelayMs = 35;
        s.baud = 9600;
        s.transport = LinkSettings::Transport::RtuTcp;
        QCOMPARE(BusScanner::fittedProbeTimeoutMs(s), 51 + BusScanner::kNetworkMarginMs);
        // Asked for more: more; asked for less: never below the fitted one.
        QCOMPARE(BusScanner::probeTimeoutMs(s, 400), 400);
        QCOMPARE(BusScanner::probeTimeoutMs(s, 20), BusScanner::fittedProbeTimeoutMs(s));
        // A late answer's suggestion: half as long again, in 50 ms steps, at least 500 ms.
        QCOMPARE(BusScanner::suggestedTimeoutMs(36), 500);
        QCOMPARE(BusScanner::suggestedTimeoutMs(400), 600);
        QCOMPARE(BusScanner::suggestedTimeoutMs(401), 650);
    }

    // After a line's last probe its late answers are listened for as long as the probe
    // timeout says, once more, not a fixed half second: ids 1-40 where nobody answers stay
    // within 1.5x of the wire's limit. A slow controller seen in the scan makes it longer.
    void theTailIsWhatTheProbeTimeoutSays()
    {
        LinkSettings line;
        line.baud = 9600;
        const int timeoutMs = BusScanner::fittedProbeTimeoutMs(line);
        QCOMPARE(BusScanner::lateListenMs(timeoutMs, -1), 2 * timeoutMs);
        QCOMPARE(BusScanner::lateListenMs(600, -1), 1200); // a --probe-timeout given
        QCOMPARE(BusScanner::lateListenMs(timeoutMs, 400), 600);
        BusScanner::Plan plan;
        plan.bauds = {9600};
        for (int id = 1; id <= 40; ++id)
            plan.ids << id;
        const qint64 probesMs = 40 * qint64(std::ceil(8 * line.charTimeMs() + timeoutMs));
        const qint64 tailMs = BusScanner::worstCaseMs(plan) - BusScanner::kOpenQuietMs - probesMs;
        QCOMPARE(tailMs, qint64(timeoutMs));
    }

    // Two controllers that answer after 300 ms, one of them the last id: the first one's late
    // answer says the line has slow controllers, so the scan listens long enough after the
    // last probe to find the second.
    void aSlowControllerSeenMakesTheTailWaitForItsLike()
    {
        SimHost sim;
        SimOptions options;
        options.rtu = true;
        options.ids = {2, 8};
        options.answerDelayMs = 300;
        QString error;
        QVERIFY2(sim.start(options, &error), qPrintable(error));
        BusScanner scanner;
        QSignalSpy finished(&scanner, &BusScanner::finished);
        BusScanner::Plan plan;
        plan.base.portName = sim.rtuPath();
        plan.bauds = {9600};
        plan.ids = {1, 2, 3, 4, 5, 6, 7, 8};
        scanner.start(plan);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
        QList<int> ids;
        for (const BusScanner::Found &f : scanner.found()) {
            ids << f.deviceId;
            QVERIFY(f.late);
        }
        QCOMPARE(ids, (QList<int>{2, 8}));
    }

    void linesOfAPlan()
    {
        BusScanner::Plan plan;
        plan.bauds = {9600, 19200};
        plan.parities = {QSerialPort::NoParity, QSerialPort::EvenParity};
        QStringList where;
        for (const LinkSettings &line : BusScanner::lines(plan))
            where << BusScanner::where(line);
        QCOMPARE(where, (QStringList{"9600 8N1", "9600 8E1", "19200 8N1", "19200 8E1"}));
        // Over a network the converter's line is its own: one line, bauds ignored.
        plan.base.transport = LinkSettings::Transport::RtuTcp;
        plan.base.host = QStringLiteral("10.0.0.5");
        plan.base.tcpPort = 4001;
        QCOMPARE(BusScanner::lines(plan).size(), 1);
        QCOMPARE(BusScanner::where(BusScanner::lines(plan).first()),
                 QStringLiteral("10.0.0.5:4001"));
    }

    // A controller that answers after 300 ms, scanned with the fitted timeout: its answer comes
    // while later ids are probed and is counted for the id it carries, not for the id in flight.
    void lateAnswerCountsForItsId()
    {
        SimHost sim;
        SimOptions options;
        options.rtu = true;
        options.deviceId = 4;
        options.answerDelayMs = 300;
        QString error;
        QVERIFY2(sim.start(options, &error), qPrintable(error));
        BusScanner scanner;
        QSignalSpy finished(&scanner, &BusScanner::finished);
        BusScanner::Plan plan;
        plan.base.portName = sim.rtuPath();
        plan.bauds = {9600};
        plan.ids = {3, 4, 5, 6, 7, 8, 9, 10};
        scanner.start(plan);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
        QCOMPARE(finished.first().at(1).toString(), QString());
        QCOMPARE(scanner.found().size(), 1);
        const BusScanner::Found f = scanner.found().first();
        QCOMPARE(f.deviceId, 4);
        QVERIFY(f.late);
        QVERIFY(f.answerMs >= 300);
        QCOMPARE(f.stepAngles.size(), 2); // identified with a timeout fitted to its delay
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBusScanner, Guiless)
#include "tst_busscanner.moc"
