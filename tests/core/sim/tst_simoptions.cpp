#include "sim/host/builtinsimulator.h"
#include "sim/host/simcommandline.h"
#include "sim/host/simconsole.h"
#include "sim/host/simhost.h"
#include "sim/model/machinefile.h"
#include "sim/model/simdevice.h"
#include "sim/serve/faultinjector.h"
#include "sim/serve/simresponder.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

// Option parsing, the fault dice, the wire-time model and the console interpreter.
class TstSimOptions : public QObject
{
    Q_OBJECT

private:
    static bool parse(const QStringList &args, SimOptions *o, QString *error)
    {
        QCommandLineParser p;
        SimCommandLine::addOptions(p);
        if (!p.parse(QStringList{QStringLiteral("stepcom-sim")} + args)) {
            *error = p.errorText();
            return false;
        }
        return SimCommandLine::toOptions(p, o, error);
    }

private Q_SLOTS:
    void commandLine()
    {
        SimOptions o;
        QString error;
        QVERIFY2(parse({QStringLiteral("--link"),         QStringLiteral("/tmp/x"),
                        QStringLiteral("--tcp"),          QStringLiteral("127.0.0.2:1502"),
                        QStringLiteral("--id"),           QStringLiteral("7"),
                        QStringLiteral("--drop"),         QStringLiteral("10%"),
                        QStringLiteral("--late"),         QStringLiteral("0.25:400"),
                        QStringLiteral("--exception"),    QStringLiteral("0.5:6"),
                        QStringLiteral("--corrupt-crc"),  QStringLiteral("0.1"),
                        QStringLiteral("--hangup-after"), QStringLiteral("20"),
                        QStringLiteral("--seed"),         QStringLiteral("42"),
                        QStringLiteral("--input"),        QStringLiteral("IN3=on"),
                        QStringLiteral("--input"),        QStringLiteral("4=pulse"),
                        QStringLiteral("--wire-baud"),    QStringLiteral("9600"),
                        QStringLiteral("--answer-delay"), QStringLiteral("50"),
                        QStringLiteral("--slow-coil"),    QStringLiteral("96:800"),
                        QStringLiteral("--slow-coil"),    QStringLiteral("00073:1500"),
                        QStringLiteral("--power-cycle"),  QStringLiteral("10:3"),
                        QStringLiteral("--power-cycle"),  QStringLiteral("2.5:0.25"),
                        QStringLiteral("--strict-reads")},
                       &o, &error),
                 qPrintable(error));
        QVERIFY(o.rtu); // --link implies --pty
        QCOMPARE(o.linkPath, QStringLiteral("/tmp/x"));
        QVERIFY(o.tcp);
        QCOMPARE(o.tcpAddress, QHostAddress(QStringLiteral("127.0.0.2")));
        QCOMPARE(o.tcpPort, 1502);
        QCOMPARE(o.deviceId, 7);
        QCOMPARE(o.faults.drop, 0.1);
        QCOMPARE(o.faults.late, 0.25);
        QCOMPARE(o.faults.lateMs, 400);
        QCOMPARE(o.faults.exception, 0.5);
        QCOMPARE(o.faults.exceptionCode, 6);
        QCOMPARE(o.faults.corruptCrc, 0.1);
        QCOMPARE(o.faults.hangupAfter, 20);
        QCOMPARE(o.faults.seed, 42u);
        QCOMPARE(o.wireBaud, 9600);
        QCOMPARE(o.answerDelayMs, 50);
        QVERIFY(o.strictReads);
        QCOMPARE(o.inputs.size(), 2);
        QCOMPARE(o.inputs.at(0).first, 3);
        QCOMPARE(o.inputs.at(1).second, SimMachine::InputForce::Pulse);
        QCOMPARE(o.slowCoils, (QHash<int, int>{{96, 800}, {73, 1500}}));
        QCOMPARE(o.powerCycles, (QList<std::pair<int, int>>{{10000, 3000}, {2500, 250}}));

        // The controller's answer time may be 0: firmware that answers as fast as it can.
        for (const char *ms : {"0", "2"}) {
            SimOptions fast;
            QVERIFY2(parse({QStringLiteral("--answer-delay"), QLatin1String(ms)}, &fast, &error),
                     qPrintable(error));
            QCOMPARE(fast.answerDelayMs, QByteArray(ms).toInt());
        }

        SimOptions any;
        QVERIFY(
            parse({QStringLiteral("--tcp"), QStringLiteral("502"), QStringLiteral("--listen-any")},
                  &any, &error));
        QCOMPARE(any.tcpAddress, QHostAddress(QHostAddress::Any));
        QVERIFY(!any.rtu);

        SimOptions line;
        QVERIFY2(parse({QStringLiteral("--line"), QStringLiteral("3"),
                        QStringLiteral("--line-echo"), QStringLiteral("1, 3")},
                       &line, &error),
                 qPrintable(error));
        QCOMPARE(line.line, 3);
        QCOMPARE(line.lineEcho, (QList<int>{1, 3}));
    }

    void badCommandLines_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("id 0") << QStringList{QStringLiteral("--id"), QStringLiteral("0")} << "--id";
        QTest::newRow("id 256") << QStringList{QStringLiteral("--id"), QStringLiteral("256")}
                                << "--id";
        QTest::newRow("drop 1.5") << QStringList{QStringLiteral("--drop"), QStringLiteral("1.5")}
                                  << "--drop";
        QTest::newRow("late without ms")
            << QStringList{QStringLiteral("--late"), QStringLiteral("0.5")} << "--late";
        QTest::newRow("tcp port") << QStringList{QStringLiteral("--tcp"), QStringLiteral("70000")}
                                  << "--tcp";
        QTest::newRow("tcp host") << QStringList{QStringLiteral("--tcp"),
                                                 QStringLiteral("nohost:1")}
                                  << "--tcp";
        QTest::newRow("input") << QStringList{QStringLiteral("--input"),
                                              QStringLiteral("IN3=maybe")}
                               << "--input";
        QTest::newRow("exception code")
            << QStringList{QStringLiteral("--exception"), QStringLiteral("0.5:0")} << "--exception";
        QTest::newRow("answer delay -1")
            << QStringList{QStringLiteral("--answer-delay"), QStringLiteral("-1")}
            << "--answer-delay: '-1'";
        const auto slow = [](const char *v) {
            return QStringList{QStringLiteral("--slow-coil"), QLatin1String(v)};
        };
        QTest::newRow("slow coil without ms") << slow("96") << "--slow-coil: '96'";
        QTest::newRow("slow coil, negative ms") << slow("96:-5") << "--slow-coil: '96:-5'";
        QTest::newRow("slow coil, words") << slow("save:800") << "--slow-coil: 'save:800'";
        QTest::newRow("slow coil, no coil") << slow("200:800") << "200 is no coil of the map";
        QTest::newRow("slow coil, a register") << slow("40001:5") << "--slow-coil: '40001:5'";
        QTest::newRow("slow coil 0") << slow("0:800") << "--slow-coil: '0:800'";
        const auto cycle = [](const char *v) {
            return QStringList{QStringLiteral("--power-cycle"), QLatin1String(v)};
        };
        QTest::newRow("power cycle without off") << cycle("3") << "--power-cycle: '3'";
        QTest::newRow("power cycle, 0 s off") << cycle("3:0") << "--power-cycle: '3:0'";
        QTest::newRow("power cycle, negative") << cycle("-1:3") << "--power-cycle: '-1:3'";
        QTest::newRow("power cycle, words") << cycle("soon:3") << "--power-cycle: 'soon:3'";
        QTest::newRow("power cycle, three") << cycle("1:2:3") << "--power-cycle: '1:2:3'";
        QTest::newRow("line echo without a line")
            << QStringList{QStringLiteral("--line-echo"), QStringLiteral("1")} << "--line N";
        QTest::newRow("line echo past the line")
            << QStringList{QStringLiteral("--line"), QStringLiteral("2"),
                           QStringLiteral("--line-echo"), QStringLiteral("3")}
            << "--line-echo: '3' is not a party of the line (1 to 2)";
        QTest::newRow("machine file missing")
            << QStringList{QStringLiteral("--machine"), QStringLiteral("/nonexistent/m.json")}
            << "/nonexistent/m.json: cannot read the machine file";
        QTest::newRow("truth-out empty")
            << QStringList{QStringLiteral("--truth-out=")} << "--truth-out";
        QTest::newRow("map") << QStringList{QStringLiteral("--map"),
                                            QStringLiteral("/nonexistent.json")}
                             << "nonexistent";
    }
    void badCommandLines()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        SimOptions o;
        QString error;
        QVERIFY(!parse(args, &o, &error));
        QVERIFY2(error.contains(mentions), qPrintable(error));
    }

    // --machine FILE reaches every controller of the host; a bad one stops the start.
    void machineFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("machine.json"));
        auto write = [&path](const QByteArray &axis) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(R"({"format": "stepcom-sim-machine", "version": 1, "homing_zeroes_count":
                        false, "axes": {)" +
                    axis + "}}");
        };
        write(R"("motor2": {"start_mm": 12.5, "backlash_mm": 0.03})");
        SimOptions o;
        QString error;
        QVERIFY2(parse({QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--machine"),
                        path, QStringLiteral("--truth-out"), dir.filePath(QStringLiteral("t"))},
                       &o, &error),
                 qPrintable(error));
        QVERIFY(o.machine);
        QCOMPARE(o.machine->source, path);
        QCOMPARE(o.truthOut, dir.filePath(QStringLiteral("t")));
        o.manualClock = true;
        o.ids = {1, 2};
        SimHost host;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        for (SimDevice *d : host.devices()) {
            QCOMPARE(d->machinePosition(2), 12.5);
            QCOMPARE(d->machinePosition(1), 50.0);
            QCOMPARE(d->machine().axis(2).backlashMm, 0.03);
            QVERIFY(!d->machine().homingZeroesCount);
        }
        host.stop();
        write(R"("motor3": {})"); // the built-in map has two motors
        o.machine = MachineFile::load(path, &error);
        QVERIFY(o.machine);
        QVERIFY(!host.start(o, &error));
        QVERIFY2(error.contains(path + QStringLiteral(": axes.motor3")), qPrintable(error));

        // The window's simulator says a bad file and runs as the ideal machine.
        write(R"("motor1": {"pull_in_rpm": "fast"})");
        BuiltinSimulator sim;
        QVERIFY(!sim.setMachineFile(path, &error));
        QVERIFY2(error.contains(path + QStringLiteral(": axes.motor1.pull_in_rpm: ")),
                 qPrintable(error));
        QVERIFY(!sim.machine());
        write(R"("motor1": {"backlash_mm": 0.1})");
        QVERIFY2(sim.setMachineFile(path, &error), qPrintable(error));
        QVERIFY(sim.machine());
        const auto link = sim.start(RegisterMap::builtin(), &error);
        QVERIFY2(link, qPrintable(error));
        QCOMPARE(sim.host()->device()->machine().axis(1).backlashMm, 0.1);
        sim.stop();
    }

    void faultDiceAreSeeded()
    {
        FaultOptions f;
        f.drop = 0.3;
        f.late = 0.5;
        f.lateMs = 100;
        f.seed = 5;
        FaultInjector a(f);
        FaultInjector b(f);
        int drops = 0;
        for (int i = 0; i < 1000; ++i) {
            const auto x = a.next();
            const auto y = b.next();
            QCOMPARE(x.drop, y.drop);
            QCOMPARE(x.extraDelayMs, y.extraDelayMs);
            drops += x.drop ? 1 : 0;
        }
        QVERIFY2(drops > 240 && drops < 360, qPrintable(QString::number(drops)));
        FaultOptions h;
        h.hangupAfter = 3;
        FaultInjector c(h);
        QList<bool> hangs;
        for (int i = 0; i < 6; ++i)
            hangs << c.next().hangUp;
        QCOMPARE(hangs, (QList<bool>{false, false, true, false, false, true}));
    }

    void wireTime()
    {
        // Read 2 registers at 9600: request 8 bytes, answer 9 bytes, 7 characters of silence.
        QCOMPARE(SimResponder::wireTimeMs(5, 6, 9600), 25);
        QCOMPARE(SimResponder::wireTimeMs(5, 6, 0), 0);
        SimDevice d;
        SimResponder r({&d}, 35, 9600, {});
        const auto out = r.respond(
            d.deviceId(), QModbusRequest(QModbusPdu::ReadHoldingRegisters, quint16(0), quint16(2)));
        QCOMPARE(out.delayMs, 35 + 25);
    }

    void console()
    {
        SimOptions o;
        o.tcp = true;
        o.manualClock = true;
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        SimConsole c(&host);
        QVERIFY(c.execute(QStringLiteral("help")).text.contains(QStringLiteral("hangup")));
        QCOMPARE(c.execute(QStringLiteral("in 2 on")).text, QStringLiteral("IN2 is on"));
        QVERIFY(host.device()->input(2));
        QVERIFY(!c.execute(QStringLiteral("in 9 on")).ok);
        QCOMPARE(c.execute(QStringLiteral("set motor1.step_angle 0.9")).text,
                 QStringLiteral("motor1.step_angle = 0.90 °"));
        QVERIFY(!c.execute(QStringLiteral("set motor1.position 3")).ok);
        QVERIFY(!c.execute(QStringLiteral("set motor1.microsteps 0")).ok);
        QVERIFY(c.execute(QStringLiteral("do motor1.forward")).ok);
        host.device()->advance(100);
        QVERIFY(host.device()->running(1));
        QVERIFY(c.execute(QStringLiteral("do estop")).ok);
        QVERIFY(!host.device()->running(1));
        QVERIFY(!c.execute(QStringLiteral("do nothing.here")).ok);
        QVERIFY(c.execute(QStringLiteral("place 2 12.5")).text.contains(QStringLiteral("12.50")));
        QCOMPARE(host.device()->machinePosition(2), 12.5);
        const QString status = c.execute(QStringLiteral("status")).text;
        QVERIFY2(status.contains(QStringLiteral("IN2=1")), qPrintable(status));
        QVERIFY2(status.contains(QStringLiteral("tcp: 127.0.0.1:")), qPrintable(status));
        QVERIFY(c.execute(QStringLiteral("get io.in2")).text.contains(QStringLiteral("io.in2")));
        QVERIFY(!c.execute(QStringLiteral("frobnicate")).ok);
        QVERIFY(c.execute(QStringLiteral("quit")).quit);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimOptions, Guiless)
#include "tst_simoptions.moc"
