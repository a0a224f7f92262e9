#include "sim/model/simdevice.h"

#include <QDataStream>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

// The controller's protocol rules, the worked frames of the manual, the state file.
class TstSimProtocol : public QObject
{
    Q_OBJECT

private:
    static QModbusRequest req(int fc, const char *hex)
    {
        return QModbusRequest(QModbusPdu::FunctionCode(fc), QByteArray::fromHex(hex));
    }
    static QByteArray pdu(const QModbusResponse &r)
    {
        if (!r.isValid())
            return "invalid";
        return (QByteArray(1, char(r.functionCode() | (r.isException() ? 0x80 : 0))) + r.data())
            .toHex();
    }
    static QByteArray ask(SimDevice &d, int fc, const char *hex)
    {
        return pdu(d.handle(req(fc, hex)).response);
    }

private Q_SLOTS:
    void manualFrames()
    {
        SimDevice d;
        // Frame 1: read 40001-40002 -> 1.80 and 8.
        QCOMPARE(ask(d, 0x03, "00000002"), QByteArray("030400b40008"));
        // Frame 2: write 40002 = 4 -> echo.
        QCOMPARE(ask(d, 0x06, "00010004"), QByteArray("0600010004"));
        QCOMPARE(d.value(QStringLiteral("motor1.microsteps")), 4);
        // Frame 4: coil 0x0007 ON -> echo; by the table that is motor 2 reverse.
        QCOMPARE(ask(d, 0x05, "0007ff00"), QByteArray("050007ff00"));
        QVERIFY(d.running(2));
        // Frame 3 (FC10 at 0x0009) starts at the high word of motor 1's move distance, which
        // the table puts at 0x0008-0x0009: half a 32-bit value, so illegal data address.
        QCOMPARE(ask(d, 0x10, "000900020400c80000"), QByteArray("9002"));
        // The same data at the distance's own address is fine (200 = 2.00, low word first).
        QCOMPARE(ask(d, 0x10, "000800020400c80000"), QByteArray("1000080002"));
        QCOMPARE(d.value(QStringLiteral("motor1.move_distance")), 200);
    }

    void onlyFourFunctionCodes_data()
    {
        QTest::addColumn<int>("fc");
        QTest::addColumn<QByteArray>("data");
        QTest::newRow("01 read coils") << 0x01 << QByteArray("00000001");
        QTest::newRow("02 read inputs") << 0x02 << QByteArray("00000001");
        QTest::newRow("04 read input registers") << 0x04 << QByteArray("00000002");
        QTest::newRow("0F write coils") << 0x0F << QByteArray("000000010101");
        QTest::newRow("17 read/write") << 0x17 << QByteArray("000000010000000102ffff");
        QTest::newRow("2B identification") << 0x2B << QByteArray("0e0100");
        QTest::newRow("41 user code") << 0x41 << QByteArray("0102");
    }
    void onlyFourFunctionCodes()
    {
        QFETCH(int, fc);
        QFETCH(QByteArray, data);
        SimDevice d;
        const QModbusResponse r = d.handle(req(fc, data.constData())).response;
        QVERIFY(r.isException());
        QCOMPARE(int(r.exceptionCode()), 1);
        QCOMPARE(int(r.functionCode()), fc);
    }

    void rules_data()
    {
        QTest::addColumn<int>("fc");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<QByteArray>("answer");
        QTest::newRow("read 50 -> 03") << 3 << QByteArray("00000032") << QByteArray("8303");
        QTest::newRow("read 0 -> 03") << 3 << QByteArray("00000000") << QByteArray("8303");
        QTest::newRow("read reserved reads 0")
            << 3 << QByteArray("00140001") << QByteArray("03020000");
        // 40019-40022: motor 2's move distance (1000, 0), then reserved 40021-40022.
        QTest::newRow("read across reserved")
            << 3 << QByteArray("00120004") << QByteArray("030803e8000000000000");
        QTest::newRow("read past the last register -> 02")
            << 3 << QByteArray("012c0002") << QByteArray("8302");
        QTest::newRow("read last register")
            << 3 << QByteArray("012c0001") << QByteArray("03020000");
        QTest::newRow("read top of space -> 02")
            << 3 << QByteArray("ffff0002") << QByteArray("8302");
        // The live status in one read, as a planner merging gaps does: 40108-40156.
        QTest::newRow("read 49 across gaps")
            << 3 << QByteArray("006b0031") << QByteArray("0362" + QByteArray(196, '0'));
        QTest::newRow("read malformed -> 03") << 3 << QByteArray("000000") << QByteArray("8303");
        QTest::newRow("read high word alone")
            << 3 << QByteArray("00070001") << QByteArray("03020000");
        QTest::newRow("read status block") << 3 << QByteArray("006b0004")
                                           << QByteArray("030800000000"
                                                         "00000000");
        QTest::newRow("write 50 -> 03")
            << 16 << (QByteArray("0000003264") + QByteArray(200, '0')) << QByteArray("9003");
        QTest::newRow("write byte count wrong -> 03")
            << 16 << QByteArray("000000010300b4") << QByteArray("9003");
        QTest::newRow("coil 1234 -> 03") << 5 << QByteArray("00001234") << QByteArray("8503");
        QTest::newRow("coil 00ff -> 03") << 5 << QByteArray("000000ff") << QByteArray("8503");
        QTest::newRow("coil reserved -> 02") << 5 << QByteArray("0010ff00") << QByteArray("8502");
        QTest::newRow("coil off accepted")
            << 5 << QByteArray("00000000") << QByteArray("0500000000");
        QTest::newRow("write read-only position -> 02")
            << 6 << QByteArray("006b0001") << QByteArray("8602");
        QTest::newRow("write input -> 02") << 6 << QByteArray("007b0001") << QByteArray("8602");
        QTest::newRow("write reserved -> 02") << 6 << QByteArray("00140001") << QByteArray("8602");
        QTest::newRow("FC06 on half of a 32-bit value -> 02")
            << 6 << QByteArray("000603e8") << QByteArray("8602");
        QTest::newRow("FC10 on the high word only -> 02")
            << 16 << QByteArray("00070001020000") << QByteArray("9002");
        QTest::newRow("FC10 read-only inside -> 02") << 16
                                                     << QByteArray("006b000204"
                                                                   "00000000")
                                                     << QByteArray("9002");
        QTest::newRow("microsteps 0 -> 03") << 6 << QByteArray("00010000") << QByteArray("8603");
        QTest::newRow("baud 1234 -> 03") << 6 << QByteArray("00d404d2") << QByteArray("8603");
        QTest::newRow("id 0 -> 03") << 6 << QByteArray("00d30000") << QByteArray("8603");
        QTest::newRow("mode 6 -> 03") << 6 << QByteArray("012b0006") << QByteArray("8603");
        QTest::newRow("address check before value check")
            << 16 << QByteArray("000000152a" + QByteArray(84, '0')) << QByteArray("9002");
    }
    void rules()
    {
        QFETCH(int, fc);
        QFETCH(QByteArray, data);
        QFETCH(QByteArray, answer);
        SimDevice d;
        QCOMPARE(ask(d, fc, data.constData()), answer);
    }

    void everyWritableParameterRoundTrips()
    {
        SimDevice d;
        int checked = 0; // registers
        for (const Parameter *p : d.map().holdings()) {
            if (!p->writable())
                continue;
            // Another allowed value than the current one: the next enum value or the maximum.
            const qint64 now = *d.value(p->key);
            qint64 raw = now == p->rawMax ? p->rawMin : p->rawMax;
            for (const EnumValue &v : p->values) {
                if (v.value != now) {
                    raw = v.value;
                    break;
                }
            }
            const QVector<quint16> words = p->encode(raw);
            QByteArray data;
            QDataStream s(&data, QIODevice::WriteOnly);
            s << p->address << quint16(words.size()) << quint8(2 * words.size());
            for (quint16 w : words)
                s << w;
            const QModbusResponse w =
                d.handle(QModbusRequest(QModbusPdu::WriteMultipleRegisters, data)).response;
            QVERIFY2(!w.isException(), qPrintable(p->key));
            const QModbusResponse r = d.handle(QModbusRequest(QModbusPdu::ReadHoldingRegisters,
                                                              p->address, quint16(p->words)))
                                          .response;
            QByteArray expected(1, char(2 * words.size()));
            for (quint16 v : words)
                expected += char(v >> 8), expected += char(v & 0xFF);
            QCOMPARE(r.data(), expected);
            QCOMPARE(*d.value(p->key), raw);
            checked += p->words;
        }
        QCOMPARE(checked, 62); // every writable register of the built-in map
    }

    void strictReads()
    {
        SimDevice d;
        d.setStrictReads(true);
        QCOMPARE(ask(d, 0x03, "00140001"), QByteArray("8302"));
        QCOMPARE(ask(d, 0x03, "00120004"), QByteArray("8302"));
        QCOMPARE(ask(d, 0x03, "00000002"), QByteArray("030400b40008"));
    }

    void rejectedWriteChangesNothing()
    {
        SimDevice d;
        // step angle 2.00 (ok) then microsteps 0 (bad): neither is written.
        QCOMPARE(ask(d, 0x10, "000000020400c80000"), QByteArray("9003"));
        QCOMPARE(d.value(QStringLiteral("motor1.step_angle")), 180);
        QCOMPARE(ask(d, 0x10, "000000020400c80010"), QByteArray("1000000002"));
        QCOMPARE(d.value(QStringLiteral("motor1.step_angle")), 200);
        QCOMPARE(d.value(QStringLiteral("motor1.microsteps")), 16);
        // Pitch 10.00 as one 32-bit value, low word first.
        QCOMPARE(ask(d, 0x10, "000600020403e80000"), QByteArray("1000060002"));
        QCOMPARE(d.value(QStringLiteral("motor1.pitch")), 1000);
    }

    void statusRegistersReflectState()
    {
        SimDevice d;
        QCOMPARE(ask(d, 0x05, "0000ff00"), QByteArray("050000ff00")); // motor 1 move
        QCOMPARE(ask(d, 0x03, "00a70001"), QByteArray("03020001"));   // 40168 running
        d.advance(2000);
        // 40108-40109: 10.00 mm = 1000 = 0x03E8, low word first.
        QCOMPARE(ask(d, 0x03, "006b0002"), QByteArray("030403e80000"));
        QCOMPARE(ask(d, 0x03, "00a70002"), QByteArray("030400000000"));
        QCOMPARE(ask(d, 0x05, "0030ff00"), QByteArray("050030ff00")); // 00049 output 1 on
        QCOMPARE(ask(d, 0x03, "00930003"), QByteArray("0306000100000000"));
        // Negative position: two's complement over both words.
        QCOMPARE(ask(d, 0x06, "00040001"), QByteArray("0600040001"));
        QCOMPARE(ask(d, 0x05, "0000ff00"), QByteArray("050000ff00"));
        d.advance(3000);
        QCOMPARE(ask(d, 0x05, "0000ff00"), QByteArray("050000ff00"));
        d.advance(3000);
        QCOMPARE(ask(d, 0x03, "006b0002"), QByteArray("0304fc18ffff")); // -10.00
        d.setInput(3, SimDevice::InputForce::On);
        QCOMPARE(ask(d, 0x03, "007b0004"), QByteArray("03080000000000010000"));
    }

    void idAndBaudChangeReported()
    {
        SimDevice d;
        SimAnswer a = d.handle(req(0x06, "00d30005"));
        QCOMPARE(pdu(a.response), QByteArray("0600d30005"));
        QVERIFY(a.linkChanged);
        QCOMPARE(d.deviceId(), 5);
        a = d.handle(req(0x06, "00d30005"));
        QVERIFY(!a.linkChanged); // same value: nothing to follow
        a = d.handle(req(0x06, "00d44b00"));
        QVERIFY(a.linkChanged);
        QCOMPARE(d.baud(), 19200);
        a = d.handle(req(0x06, "00010004"));
        QVERIFY(!a.linkChanged);
    }

    void saveSurvivesRestart()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("state.json"));
        {
            SimDevice d;
            d.setStatePath(path);
            QString error;
            QVERIFY(d.loadState(&error)); // no file yet: factory values
            QCOMPARE(ask(d, 0x06, "00010010"), QByteArray("0600010010"));
            QCOMPARE(ask(d, 0x06, "00d30007"), QByteArray("0600d30007"));
            QVERIFY(!QFile::exists(path));
            QCOMPARE(ask(d, 0x05, "005fff00"), QByteArray("05005fff00")); // 00096 save
            QVERIFY(QFile::exists(path));
            QCOMPARE(ask(d, 0x06, "00020100"), QByteArray("0600020100")); // not saved
        }
        SimDevice d;
        d.setStatePath(path);
        QString error;
        QVERIFY2(d.loadState(&error), qPrintable(error));
        QCOMPARE(d.value(QStringLiteral("motor1.microsteps")), 16);
        QCOMPARE(d.deviceId(), 7);
        QCOMPARE(d.value(QStringLiteral("motor1.start_frequency")), 400);
    }

    void brokenStateFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("state.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{ not json");
        f.close();
        SimDevice d;
        d.setStatePath(path);
        QString error;
        QVERIFY(!d.loadState(&error));
        QVERIFY(error.contains(path));
    }

    void saveFailureIsDeviceFailure()
    {
        SimDevice d;
        d.setStatePath(QStringLiteral("/nonexistent-dir/state.json"));
        QCOMPARE(ask(d, 0x05, "005fff00"), QByteArray("8504"));
    }

    void factoryReset()
    {
        SimDevice d;
        QCOMPARE(ask(d, 0x06, "00010010"), QByteArray("0600010010"));
        QCOMPARE(ask(d, 0x06, "012b0002"), QByteArray("06012b0002"));
        QCOMPARE(ask(d, 0x06, "00d30009"), QByteArray("0600d30009"));
        QCOMPARE(ask(d, 0x05, "0048ff00"), QByteArray("050048ff00")); // 00073
        QCOMPARE(d.value(QStringLiteral("motor1.microsteps")), 8);
        QCOMPARE(d.value(QStringLiteral("mode.system")), 0);
        QCOMPARE(d.deviceId(), 9); // the link settings stay: the master keeps its device
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimProtocol, Guiless)
#include "tst_simprotocol.moc"
