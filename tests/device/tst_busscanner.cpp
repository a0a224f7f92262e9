// Scan results a person reads: "id 7 at 9600 8N1 — a 2-axis controller, step angle 1.80°",
// from what the device showed, and a real scan of the simulator at id 7.
#include "device/busscanner.h"
#include "map/registermap.h"
#include "sim/simdevice.h"
#include "sim/simhost.h"

#include <QSignalSpy>
#include <QTest>

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
};

QTEST_GUILESS_MAIN(TestBusScanner)
#include "tst_busscanner.moc"
