#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "testpaths.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <signal.h>

using namespace stepcom;
using namespace stepcom::test;

namespace {

// The example of docs/sequence.md.
const QByteArray kExample = R"({"format": "stepcom-sequence", "version": 1,
 "points": {"load": {"motor1": 30.0}, "unload": {"motor1": 10.0, "motor2": 0.0}},
 "limits": {"motor1": {"min": 0, "max": 300}},
 "on_stop": {"outputs": "leave"},
 "steps": [
   {"home": "order"},
   {"repeat": 3, "steps": [
     {"move_to": "load"},
     {"wait_input": 3, "on": true, "timeout_s": 20},
     {"output": 1, "on": true},
     {"dwell_ms": 50},
     {"move_to": "unload"},
     {"output": 1, "on": false}]}]})";

QByteArray sequence(const QByteArray &steps)
{
    return R"({"format": "stepcom-sequence", "version": 1,
 "points": {"far": {"motor1": 150.0}}, "steps": )" +
           steps + "}";
}

} // namespace

// stepcomctl run against the simulator over TCP: the example's cycles and its output frames,
// waits, Ctrl-C, an E-STOP from the simulator's side, a lost link, bad files refused with
// nothing sent, both motors in one step and nested repeats.
class TestCtlRun : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    QTemporaryDir dir;

    SimDevice *sim() const { return host->device(); }
    QString write(const QByteArray &content, const QString &name = QStringLiteral("t.stepseq"))
    {
        QFile f(dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly))
            return {};
        f.write(content);
        return f.fileName();
    }
    QStringList link() const
    {
        return {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(host->tcpPort())};
    }
    ProgramRun ctl(const QStringList &args)
    {
        ProgramOptions options;
        options.environment = {QStringLiteral("XDG_DATA_HOME=") +
                               dir.filePath(QStringLiteral("data"))};
        return runProgram(QStringLiteral("stepcomctl"), link() + args, options);
    }
    // Runs stepcomctl without blocking, calling `act` with its standard error so far until it
    // ends.
    ProgramRun ctlWhile(const QStringList &args,
                        const std::function<void(const QString &err, QProcess &p)> &act)
    {
        return runProgramWhile(QStringLiteral("stepcomctl"), link() + args, act);
    }
    // What stepcomctl said, without the traffic of --verbose.
    static QByteArray said(const ProgramRun &r)
    {
        QStringList lines;
        for (const QString &l : r.err.split(QLatin1Char('\n'))) {
            if (l.startsWith(QLatin1String("stepcomctl:")) ||
                l.startsWith(QLatin1String("cycle")) || l.startsWith(QLatin1String("{")) ||
                l.contains(QLatin1String("limit_")))
                lines << l;
        }
        return (lines.join(QLatin1Char('\n')) + QLatin1Char('\n') + r.out).toUtf8();
    }
    static QJsonObject result(const ProgramRun &r)
    {
        return QJsonDocument::fromJson(r.out.toUtf8())
            .object()
            .value(QStringLiteral("result"))
            .toObject();
    }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        SimOptions options;
        options.tcp = true;
        options.answerDelayMs = 0;
        options.startPosition = 5;
        QString error;
        QVERIFY2(host->start(options, &error), qPrintable(error));
        // The factory's switches (motor 1: IN1 +, IN2 − and home; motor 2: IN3 +, IN4 − and
        // home), but no positive limit on motor 2: IN3 is the part sensor.
        for (const auto &[key, value] : QList<std::pair<QString, qint64>>{
                 {"motor2.limit_positive", 0},
                 {"homing.first", 1},
                 {"homing.second", 2},
                 {"motor1.speed", 1500},
                 {"motor2.speed", 1500},
             })
            QVERIFY2(sim()->setValue(key, value), qPrintable(key));
    }
    void cleanup() { host.reset(); }

    void exampleRunsTwoCycles()
    {
        sim()->setInput(3, SimDevice::InputForce::On);
        const ProgramRun r =
            ctl({QStringLiteral("--verbose"), QStringLiteral("--json"), QStringLiteral("run"),
                 write(kExample), QStringLiteral("--cycles"), QStringLiteral("2"),
                 QStringLiteral("--yes")});
        QVERIFY2(r.exitCode == 0, said(r).constData());
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("outcome")).toString(), QStringLiteral("done"));
        QCOMPARE(o.value(QStringLiteral("cycles_done")).toInt(), 2);
        QVERIFY(o.value(QStringLiteral("restored")).toBool());
        QVERIFY(o.value(QStringLiteral("cycle_time_s")).toObject().value("min").toDouble() > 0);
        // 2 cycles × repeat 3: output 1 switched on and off six times each.
        QCOMPARE(r.err.count(QStringLiteral("write coil 00049 (output1_on) ON")), 6);
        QCOMPARE(r.err.count(QStringLiteral("write coil 00050 (output1_off) ON")), 6);
        QCOMPARE(r.err.count(QStringLiteral("write coil 00046 (home_all) ON")), 2);
        QCOMPARE(sim()->position(1), 1000);
        QVERIFY(!sim()->output(1));
        QCOMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 1500);
    }

    void waitWaitsForTheInput()
    {
        const QByteArray steps = R"([{"wait_input": 3, "on": true, "timeout_s": 15},
                                     {"output": 1, "on": true}])";
        bool forced = false;
        const ProgramRun r =
            ctlWhile({QStringLiteral("run"), write(sequence(steps)), QStringLiteral("--yes")},
                     [&](const QString &err, QProcess &) {
                         if (!forced && err.contains(QStringLiteral("wait for IN3"))) {
                             QVERIFY(!sim()->output(1)); // still waiting
                             sim()->setInput(3, SimDevice::InputForce::On);
                             forced = true;
                         }
                     });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QVERIFY(forced);
        QVERIFY(sim()->output(1));
    }

    void waitTimesOut()
    {
        const QByteArray steps = R"([{"wait_input": 3, "on": true, "timeout_s": 0.3},
                                     {"output": 1, "on": true}])";
        const ProgramRun r = ctl({QStringLiteral("--json"), QStringLiteral("run"),
                                  write(sequence(steps)), QStringLiteral("--yes")});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(result(r).value(QStringLiteral("outcome")).toString(), QStringLiteral("timeout"));
        QCOMPARE(result(r).value(QStringLiteral("step")).toString(), QStringLiteral("steps[0]"));
        QVERIFY(!sim()->output(1));
    }

    // A slow move to 150 mm, interrupted from outside once the motor runs.
    void stoppedDuringAMove_data()
    {
        QTest::addColumn<QString>("how");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("outcome");
        QTest::newRow("Ctrl-C") << "sigint" << 1 << "interrupted";
        QTest::newRow("E-STOP at the controller") << "estop" << 1 << "estop";
        QTest::newRow("link lost") << "link" << 3 << "link-lost";
    }
    void stoppedDuringAMove()
    {
        QFETCH(QString, how);
        QFETCH(int, exitCode);
        QFETCH(QString, outcome);
        const QByteArray steps = R"([{"home": "motor1"}, {"output": 1, "on": true},
                                     {"speed": {"motor1": 120}}, {"move_to": "far"},
                                     {"output": 1, "on": false}])";
        bool done = false;
        const ProgramRun r = ctlWhile({QStringLiteral("--json"), QStringLiteral("run"),
                                       write(sequence(steps)), QStringLiteral("--yes")},
                                      [&](const QString &err, QProcess &p) {
                                          if (done || !err.contains(QStringLiteral("steps[3]")) ||
                                              !sim()->running(1))
                                              return;
                                          done = true;
                                          if (how == QLatin1String("sigint"))
                                              ::kill(pid_t(p.processId()), SIGINT);
                                          else if (how == QLatin1String("estop"))
                                              QVERIFY(sim()->command(QStringLiteral("estop")));
                                          else
                                              host->stop();
                                      });
        QVERIFY2(done, said(r).constData());
        QVERIFY2(r.exitCode == exitCode, said(r).constData());
        QCOMPARE(result(r).value(QStringLiteral("outcome")).toString(), outcome);
        QCOMPARE(result(r).value(QStringLiteral("step")).toString(), QStringLiteral("steps[3]"));
        if (how == QLatin1String("link"))
            return; // the controller goes on: nothing can reach it
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(sim()->position(1) < 15000);
        if (how == QLatin1String("sigint")) {
            // Stopped, then the user's speed back; on_stop "leave" keeps output 1 on.
            QCOMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 1500);
            QVERIFY(sim()->output(1));
        }
    }

    void badFilesSendNothing_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("message");
        const QByteArray home = R"({"home": "order"}, )";
        QTest::newRow("unknown point") << sequence("[" + home + R"({"move_to": "near"}])")
                                       << "steps[1].move_to: unknown point \"near\"";
        QTest::newRow("outside the limits")
            << QByteArray(R"({"format": "stepcom-sequence", "version": 1,
                "limits": {"motor1": {"max": 100}}, "steps": [)" +
                          home + R"({"move_to": {"motor1": 120}}]})")
            << "steps[1]: motor 1 would go to 120.00 mm, outside the file's limits";
        QTest::newRow("unknown key") << sequence(R"([{"dwell_ms": 5, "speed_x": 1}])")
                                     << "steps[0]: unknown key \"speed_x\"";
        QTest::newRow("no such input") << sequence(R"([{"wait_input": 9, "on": true}])")
                                       << "steps[0].wait_input: the controller has no input 9";
        QTest::newRow("no such output") << sequence(R"([{"output": 7, "on": true}])")
                                        << "steps[0].output: the controller has no output 7";
        QTest::newRow("wrong type") << sequence(R"([{"repeat": "3", "steps": []}])")
                                    << "steps[0].repeat: must be a whole number, not a text";
        QTest::newRow("move_to before home")
            << sequence(R"([{"move_to": "far"}])") << "steps[0]: motor 1 is not referenced";
        QTest::newRow("invalid JSON") << QByteArray("{\"format\": \"stepcom-sequence\",\n\"x\" }")
                                      << "not valid JSON at line 2, column";
        QTest::newRow("wrong format")
            << QByteArray(R"({"format": "stepcom-profile", "version": 1})")
            << "format: not a sequence file";
        QTest::newRow("wrong version")
            << QByteArray(R"({"format": "stepcom-sequence", "version": 9, "steps": []})")
            << "version: version 9 is not known";
    }
    void badFilesSendNothing()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, message);
        const QString path = write(content, QStringLiteral("bad.stepseq"));
        const ProgramRun r = ctl({QStringLiteral("run"), path, QStringLiteral("--yes")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(path + QStringLiteral(": ")), qPrintable(r.err));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(host->stats().requests, 0);
    }

    void notConfirmedRunsNothing()
    {
        ProgramOptions options;
        options.input = "n\n";
        const ProgramRun r =
            runProgram(QStringLiteral("stepcomctl"),
                       link() + QStringList{QStringLiteral("run"), write(kExample)}, options);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.out.contains(QStringLiteral("point load: motor1 30.00 mm")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("cycles: 1")));
        QVERIFY(r.err.contains(QStringLiteral("not confirmed: nothing was sent")));
        QCOMPARE(host->stats().requests, 0);
    }

    void bothMotorsAndNestedRepeats()
    {
        const QByteArray steps = R"([{"home": "order"},
            {"move_to": {"motor1": 12.0, "motor2": 8.0}},
            {"repeat": 2, "steps": [{"repeat": 3, "steps": [{"move_by": {"motor1": 1.0}}]},
                                    {"move_by": {"motor2": -1.0}}]}])";
        const ProgramRun r = ctl({QStringLiteral("--verbose"), QStringLiteral("run"),
                                  write(sequence(steps)), QStringLiteral("--yes")});
        QVERIFY2(r.exitCode == 0, said(r).constData());
        QCOMPARE(sim()->position(1), 1800);
        QCOMPARE(sim()->position(2), 600);
        QCOMPARE(r.err.count(QStringLiteral(" steps[2].steps[0].steps[0]: ")), 6);
        QCOMPARE(r.err.count(QStringLiteral(" steps[2].steps[1]: ")), 2);
        // Both single moves of steps[1] went out before either axis was judged.
        const qsizetype first = r.err.indexOf(QStringLiteral("cycle 1 steps[1]:"));
        const qsizetype second = r.err.indexOf(QStringLiteral("cycle 1 steps[2].steps[0]"));
        const QString step1 = r.err.mid(first, second - first);
        QVERIFY2(step1.contains(QStringLiteral("write coil 00001 (motor1.move) ON")) &&
                     step1.contains(QStringLiteral("write coil 00006 (motor2.move) ON")),
                 qPrintable(step1));
    }
};

STEPCOM_TEST(TestCtlRun, Guiless)
#include "tst_ctlrun.moc"
