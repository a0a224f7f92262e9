#include "programrun.h"
#include "scripteddevice.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "testpaths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>
#include <QTimer>

using namespace stepcom::test;

namespace {

using Run = ProgramRun;

} // namespace

class TestStepcomctl : public QObject
{
    Q_OBJECT
    std::unique_ptr<ScriptedDevice> device;

    // Runs stepcomctl without blocking the event loop, so the fake device keeps answering.
    Run ctl(const QStringList &args, bool withPort = true)
    {
        const QStringList link{QStringLiteral("--port"),    device->clientPath(),
                               QStringLiteral("--timeout"), QStringLiteral("200"),
                               QStringLiteral("--retries"), QStringLiteral("0")};
        return runProgram(QStringLiteral("stepcomctl"), (withPort ? link : QStringList()) + args);
    }

    // What --json's object holds as the result, once its exit is the program's.
    static QJsonValue result(const Run &r)
    {
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        if (o.value(QStringLiteral("exit")).toInt(-1) != r.exitCode)
            return QJsonValue(QJsonValue::Undefined);
        return o.value(QStringLiteral("result"));
    }

private Q_SLOTS:
    void init()
    {
        device = std::make_unique<ScriptedDevice>();
        QString error;
        QVERIFY2(device->open(&error), qPrintable(error));
        device->useRegisterDevice();
        device->registers[0] = 180; // motor1.step_angle 1.80
        device->registers[1] = 8;
        device->registers[5] = 300;
        device->registers[107] = quint16(-250 & 0xFFFF); // motor1.position -2.50, low word
        device->registers[108] = 0xFFFF;
        device->registers[212] = 9600; // device.baud
    }

    void readsInEngineeringUnits()
    {
        const Run r = ctl({QStringLiteral("read"), QStringLiteral("motor1.step_angle"),
                           QStringLiteral("motor1.microsteps"), QStringLiteral("motor1.position"),
                           QStringLiteral("motor1.direction")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("motor1.step_angle = 1.80 °")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("motor1.microsteps = 8\n")));
        QVERIFY(r.out.contains(QStringLiteral("motor1.position = -2.50 mm")));
        QVERIFY(r.out.contains(QStringLiteral("motor1.direction = 0 (Forward)")));
    }

    void readAllAsJsonUsesThePlannedReads()
    {
        const Run r = ctl({QStringLiteral("--json"), QStringLiteral("read")});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = result(r).toObject();
        QCOMPARE(o.size(), 57);
        QCOMPARE(o.value(QStringLiteral("motor1.step_angle")).toDouble(), 1.8);
        QCOMPARE(o.value(QStringLiteral("motor1.position")).toDouble(), -2.5);
        QCOMPARE(o.value(QStringLiteral("device.baud")).toInt(), 9600);
        QCOMPARE(device->requests().size(), 5); // the optimum plan at 9600 baud
    }

    void writeVerifies()
    {
        const Run r = ctl({QStringLiteral("write"), QStringLiteral("motor1.speed=450"),
                           QStringLiteral("motor2.pitch=5")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(device->registers[5], quint16(450));
        QCOMPARE(device->registers[16], quint16(500));
        QCOMPARE(device->requests().at(0),
                 withCrc(fromHex("01 06 00 05 01 C2"))); // FC06 for one register
        QCOMPARE(device->requests().at(1).mid(0, 6),
                 fromHex("01 10 00 10 00 02")); // pitch as one FC10
        QVERIFY(r.out.contains(QStringLiteral("motor1.speed = 450 rpm  (written, verified)")));
        QVERIFY(r.out.contains(QStringLiteral("motor2.pitch = 5.00 mm")));
    }

    void invalidValuesWriteNothing_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("out of range")
            << QStringList{"write", "motor1.speed=99999", "motor1.microsteps=4"}
            << "motor1.speed: 99999 is out of range";
        QTest::newRow("too many decimals")
            << QStringList{"write", "motor1.step_angle=1.805"} << "more than 2 decimal";
        QTest::newRow("unknown key")
            << QStringList{"write", "motor9.speed=1"} << "unknown parameter 'motor9.speed'";
        QTest::newRow("read-only")
            << QStringList{"write", "motor1.position=0"} << "motor1.position is read-only";
        QTest::newRow("not key=value")
            << QStringList{"write", "motor1.speed"} << "is not KEY=VALUE";
        QTest::newRow("destructive without yes")
            << QStringList{"command", "factory_reset"} << "add --yes";
        QTest::newRow("unknown command")
            << QStringList{"frobnicate"}
            << "unknown command 'frobnicate' (params, read, write, "
               "command, move, run, lost-steps, margin, backlash, monitor, listen, dump, diff, "
               "apply, assign-id, scan, ports, report, replay, bundle)";
        QTest::newRow("read unknown") << QStringList{"read", "nope"} << "unknown parameter 'nope'";
    }
    void invalidValuesWriteNothing()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const QList<quint16> before = device->registers;
        const Run r = ctl(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(device->takeEverythingSent());
        QCOMPARE(device->requests().size(), 0); // nothing was sent at all
        QCOMPARE(device->registers, before);
    }

    void verificationCatchesADeviceThatIgnoresAWrite()
    {
        // Acknowledges every write but keeps its old values.
        auto honest = device->registers;
        device->setResponder(
            [this, honest](const QByteArray &request, int) -> std::optional<QByteArray> {
                if (quint8(request.at(1)) == 0x06)
                    return request;
                QList<quint16> regs = honest;
                QByteArray answer = request.left(2);
                const int address = (quint8(request.at(2)) << 8) | quint8(request.at(3));
                const int count = (quint8(request.at(4)) << 8) | quint8(request.at(5));
                answer.append(char(count * 2));
                for (int i = 0; i < count; ++i) {
                    answer.append(char(regs[address + i] >> 8));
                    answer.append(char(regs[address + i] & 0xFF));
                }
                return withCrc(answer);
            });
        const Run r = ctl({QStringLiteral("write"), QStringLiteral("motor1.speed=450")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(
            r.err.contains(QStringLiteral("motor1.speed: wrote 450 but the controller holds 300")),
            qPrintable(r.err));
    }

    void silentDeviceIsALinkError()
    {
        device->setResponder({});
        const Run r = ctl({QStringLiteral("read"), QStringLiteral("motor1.speed")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("no answer within 200 ms")), qPrintable(r.err));
    }

    void aDeadLineIsSaidOnce()
    {
        // Every block of a whole read gets the same "no answer": said once, with how many more.
        device->setResponder({});
        const Run r = ctl({QStringLiteral("read")});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err.count(QStringLiteral("no answer within 200 ms")), 1);
        QVERIFY2(r.err.contains(QStringLiteral("(the same for 4 more reads of this command)")),
                 qPrintable(r.err));
    }

    void commandPulsesTheCoil()
    {
        const Run r = ctl({QStringLiteral("command"), QStringLiteral("motor2.reverse")});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(device->requests().value(0), fromHex("01 05 00 07 FF 00 3D FB"));
    }

    void noTargetIsAUsageError()
    {
        const Run r = ctl({QStringLiteral("read")}, false);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QStringLiteral("--port PATH, --tcp HOST[:PORT] or --sim")));
    }

    void missingPortIsNamed()
    {
        const Run r =
            ctl({QStringLiteral("--port"), QStringLiteral("/dev/ttyNOPE9"), QStringLiteral("read")},
                false);
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains(QStringLiteral("/dev/ttyNOPE9 does not exist")));
    }

    void modbusTcpThroughAGateway()
    {
        stepcom::SimHost host;
        stepcom::SimOptions options;
        options.tcp = true;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        const QString target = QStringLiteral("127.0.0.1:%1").arg(host.tcpPort());
        Run r = ctl({"--tcp", target, "--verbose", "write", "motor2.move_distance=12.5",
                     "motor2.speed=275"},
                    false);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(*host.device()->value(QStringLiteral("motor2.speed")), 275);
        // the traffic shows the MBAP frames both ways
        QVERIFY2(r.err.contains(QStringLiteral("TX  00")) &&
                     r.err.contains(QStringLiteral("RX  00")),
                 qPrintable(r.err));
        r = ctl({"--tcp", target, "--json", "read", "motor2.speed"}, false);
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(result(r).toObject().value(QStringLiteral("motor2.speed")).toInt(), 275);
        host.stop();
        r = ctl({"--tcp", target, "read"}, false);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("refused")), qPrintable(r.err));
    }

    // `command --wait` judges the end as the window does; exit 0 only for done / referenced.
    void waitJudgesTheOutcome()
    {
        stepcom::SimHost host;
        stepcom::SimOptions options;
        options.tcp = true;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        stepcom::SimDevice *sim = host.device();
        QVERIFY(sim->setValue(QStringLiteral("motor1.speed"), 1200));
        const QString target = QStringLiteral("127.0.0.1:%1").arg(host.tcpPort());

        Run r = ctl({"--tcp", target, "--json", "command", "motor1.move", "--wait"}, false);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject done = result(r).toObject();
        QCOMPARE(done.value(QStringLiteral("outcome")).toString(), QStringLiteral("done"));
        QCOMPARE(done.value(QStringLiteral("message")).toString(),
                 QStringLiteral("Single move of motor 1: done at 10.00 mm"));
        QCOMPARE(sim->position(1), 1000);

        // An E-STOP (from the machine, another master) while homing: not referenced, exit 1.
        QVERIFY(sim->setValue(QStringLiteral("motor1.speed"), 300));
        sim->setMachinePosition(1, 80.0);
        QTimer watcher;
        bool stopped = false;
        connect(&watcher, &QTimer::timeout, this, [&] {
            if (!stopped && sim->running(1)) {
                stopped = true;
                sim->command(QStringLiteral("estop"));
            }
        });
        watcher.start(5);
        r = ctl({"--tcp", target, "command", "motor1.home", "--wait"}, false);
        watcher.stop();
        QVERIFY(stopped);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(
            r.err.contains(QStringLiteral("Homing motor 1 ended without the home input at ")) &&
                r.err.contains(QStringLiteral(": not referenced")),
            qPrintable(r.err));
        QVERIFY(!r.out.contains(QStringLiteral("referenced at")));

        // Homing that reaches its switch is referenced.
        r = ctl({"--tcp", target, "--json", "command", "motor1.home", "--wait"}, false);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QCOMPARE(result(r).toObject().value(QStringLiteral("outcome")),
                 QJsonValue(QStringLiteral("referenced")));

        // Forward runs until stopped: nothing to wait for.
        r = ctl({"--tcp", target, "command", "motor1.forward", "--wait"}, false);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("no end to wait for")), qPrintable(r.err));
        QVERIFY(!sim->running(1));
    }

    void builtinSimulator()
    {
        const Run r = ctl({"--sim", "read", "motor1.step_angle", "device.baud"}, false);
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("motor1.step_angle = 1.80 °")));
        QVERIFY(r.out.contains(QStringLiteral("device.baud = 9600")));
    }

    // Writing the baud reopens the link at the new rate; that must not run the command again
    // (it did: the second run's read-back was cut off by the reopening, exit 1).
    void baudChangeFollowsAndVerifiesOnce()
    {
        const Run r =
            ctl({"--sim", "--verbose", "write", "device.baud=19200", "device.id=5"}, false);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(
            QStringLiteral("device.baud = 19200 (19200 baud)  (written, verified)")));
        QVERIFY(r.out.contains(QStringLiteral("device.id = 5  (written, verified)")));
        QCOMPARE(r.err.count(QStringLiteral("write 40213 (device.baud)")), 1);
    }

    void paramsJsonListsTheMap()
    {
        const Run r = ctl({QStringLiteral("--json"), QStringLiteral("params")}, false);
        QCOMPARE(r.exitCode, 0);
        const QJsonArray array = result(r).toArray();
        QCOMPARE(array.size(), 81);
        const QJsonObject first = array.at(0).toObject();
        for (const char *field : {"key", "kind", "plc", "address", "words", "signed", "scale",
                                  "unit", "access", "min", "max"})
            QVERIFY2(first.contains(QLatin1String(field)), field);
        QCOMPARE(first.value(QStringLiteral("key")).toString(),
                 QStringLiteral("motor1.step_angle"));
        QCOMPARE(first.value(QStringLiteral("max")).toDouble(), 360.0);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestStepcomctl, Guiless)
#include "tst_stepcomctl.moc"
