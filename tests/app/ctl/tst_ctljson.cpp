// stepcomctl --json: every command the help lists, run once for its data and once failing,
// prints the one envelope -- `exit` (the process's exit code), `result` (the command's data),
// `errors` (naming what went wrong) -- as one object, or, for monitor and listen, as the last
// of its lines. A usage error before any command is chosen prints it too.
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

using namespace stepcom;
using namespace stepcom::test;

class TestCtlJson : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    std::unique_ptr<SimHost> host; // a controller whose motions end quickly, over TCP
    int ptyMaster = -1;            // a line nobody drives, for listen
    QString ptyPath;

    QString path(const QString &name) const { return dir.filePath(name); }

    // An argument "@STDIN:text" is not passed on: `text` is the program's standard input.
    ProgramRun ctl(QStringList args) const
    {
        ProgramOptions options;
        for (qsizetype i = args.size() - 1; i >= 0; --i) {
            if (args.at(i).startsWith(QLatin1String("@STDIN:")))
                options.input = args.takeAt(i).mid(7).toUtf8();
        }
        options.cleanLocale = true;
        options.timeoutMs = 60000;
        // The simulator's flash, the backups and the session logs stay in this test's folder.
        options.environment = {QStringLiteral("XDG_DATA_HOME=") + path(QStringLiteral("data"))};
        return runProgram(QStringLiteral("stepcomctl"), args, options);
    }

    // The usages of the help's "Commands:" list, each a row of the table below.
    QStringList usages() const
    {
        const ProgramRun r =
            ctl({QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--help")});
        QStringList out;
        static const QRegularExpression row(QStringLiteral("^  (\\S.*?)(  +\\S|$)"));
        const QString help = r.out.section(QStringLiteral("Commands:\n"), 1);
        for (const QString &line : help.split(QLatin1Char('\n'))) {
            if (line.trimmed().isEmpty())
                break;
            if (const auto m = row.match(line); m.hasMatch())
                out << m.captured(1);
        }
        return out;
    }

    // Replaces the placeholders of a row by this run's paths.
    QStringList expand(QStringList args) const
    {
        const QString tcp = QStringLiteral("127.0.0.1:%1").arg(host->tcpPort());
        args.replaceInStrings(QStringLiteral("@TCP"), tcp);
        args.replaceInStrings(QStringLiteral("@SRC"), qEnvironmentVariable("STEPCOM_SOURCE_DIR"));
        args.replaceInStrings(QStringLiteral("@PTY"), ptyPath);
        args.replaceInStrings(QStringLiteral("@DIR/"), dir.path() + QLatin1Char('/'));
        return args;
    }

    // A row: the usage (a line of the help, or "" for an error before any command), the
    // arguments, the exit code, and what the result holds (a key of its object, "[]" an array,
    // "[1]" an array of at least one) or, for a failure, a word the errors hold.
    struct Row
    {
        const char *name;
        QString usage;
        QStringList args;
        int code;
        QString expect;
        bool fails; // diff's 1 is an answer ("different"), not a failure
    };
    static QList<Row> rows()
    {
        const QStringList dead{"--tcp", "127.0.0.1:1", "--timeout", "200"};
        const QString missing = QStringLiteral("@DIR/nope.json");
        const QString profile = QStringLiteral("@DIR/machine.json");
        QList<Row> rows;
        const auto add = [&rows](const char *name, const QString &usage, const QStringList &args,
                                 int code, const QString &expect, bool failing) {
            rows << Row{name, usage, args, code, expect, failing};
        };
        const bool ok = false;
        const bool fails = true;
        add("params", "params", {"params"}, 0, "[1]", ok);
        add("params bad map", "params", {"--map", missing, "params"}, 2, "nope.json", fails);
        add("read", "read [KEY...]", {"--sim", "read", "motor1.speed"}, 0, "motor1.speed", ok);
        add("read unknown", "read [KEY...]", {"--sim", "read", "nope"}, 2, "nope", fails);
        add("read dead", "read [KEY...]", dead + QStringList{"read"}, 1, "cannot connect", fails);
        // The no-answer message says the timeout asked for, on the built-in simulator too.
        add("read silent id", "read [KEY...]",
            {"--sim", "--timeout", "200", "--retries", "0", "--id", "5", "read", "device.id"}, 1,
            "no answer within 200 ms", fails);
        add("write", "write KEY=VALUE...", {"--sim", "write", "motor1.speed=250"}, 0, "written",
            ok);
        add("write bad", "write KEY=VALUE...", {"--sim", "write", "motor1.speed=x"}, 2,
            "motor1.speed", fails);
        add("command", "command NAME", {"--sim", "command", "output1_on"}, 0, "command", ok);
        add("command unknown", "command NAME", {"--sim", "command", "nope"}, 2, "nope", fails);
        add("command --wait", "command NAME --wait",
            {"--tcp", "@TCP", "command", "motor1.move", "--wait"}, 0, "outcome", ok);
        add("command --wait estop", "command NAME --wait", {"--sim", "command", "estop", "--wait"},
            2, "estop", fails);
        add("move", "move MOTOR --by D|--to X", {"--tcp", "@TCP", "move", "motor2", "--by", "1"}, 0,
            "arrived", ok);
        add("move no motor", "move MOTOR --by D|--to X", {"--sim", "move", "motor9", "--by", "1"},
            2, "motor 9", fails);
        add("run", "run FILE", {"--sim", "run", "@SRC/tests/app/ctl/dwell.stepseq", "--yes"}, 0,
            "outcome", ok);
        add("run no file", "run FILE", {"--sim", "run", "@SRC/none.stepseq", "--yes"}, 2,
            "none.stepseq", fails);
        // The gauge's three readings on standard input; before the proofs, which end with the
        // carriage on the switch, 1 mm below which it cannot go.
        add("backlash", "backlash motorN",
            {"--tcp", "@TCP", "backlash", "motor1", "--cycles", "1", "--yes", "@STDIN:0\n1\n0\n"},
            0, "backlash_mm", ok);
        add("backlash no motor", "backlash motorN", {"--sim", "backlash"}, 2, "motorN", fails);
        add("lost-steps", "lost-steps motorN",
            {"--tcp", "@TCP", "lost-steps", "motor1", "--cycles", "1", "--distance", "1", "--yes"},
            0, "verdict", ok);
        add("lost-steps no motor", "lost-steps motorN", {"--sim", "lost-steps", "motor9"}, 2,
            "motorN", fails);
        add("margin", "margin motorN",
            {"--tcp", "@TCP", "margin", "motor1", "--from", "100", "--to", "100", "--cycles", "1",
             "--distance", "1", "--yes"},
            0, "kept_rpm", ok);
        add("margin bad step", "margin motorN", {"--sim", "margin", "motor1", "--step", "0"}, 2,
            "--step", fails);
        add("monitor", "monitor", {"--sim", "monitor", "--count", "2"}, 0, "samples", ok);
        add("monitor ids", "monitor", {"--sim", "--id", "1,2", "monitor", "--count", "1"}, 0,
            "failed", ok);
        add("monitor dead", "monitor", dead + QStringList{"monitor", "--count", "1"}, 1,
            "cannot connect", fails);
        add("listen", "listen", {"--port", "@PTY", "listen", "--seconds", "1"}, 0, "frames", ok);
        add("listen no port", "listen", {"--port", "@DIR/no-tty", "listen", "--seconds", "1"}, 1,
            "no-tty", fails);
        add("dump", "dump FILE|FOLDER/", {"--sim", "dump", "@DIR/d.json"}, 0, "file", ok);
        add("dump dead", "dump FILE|FOLDER/", dead + QStringList{"dump", "@DIR/x.json"}, 1,
            "cannot connect", fails);
        add("diff", "diff FILE", {"--sim", "diff", profile}, 1, "differences", ok);
        add("diff dead", "diff FILE", dead + QStringList{"diff", profile}, 3, "cannot connect",
            fails);
        add("diff files", "diff A.json B.json", {"diff", profile, profile}, 0, "same", ok);
        add("diff files missing", "diff A.json B.json", {"diff", missing, profile}, 2, "nope.json",
            fails);
        add("apply", "apply FILE", {"--sim", "--yes", "--no-backup", "apply", profile}, 0,
            "to_write", ok);
        add("apply missing", "apply FILE", {"--sim", "--yes", "apply", missing}, 2, "nope.json",
            fails);
        add("assign-id", "assign-id --to N", {"--sim", "assign-id", "--to", "3"}, 0, "to", ok);
        add("assign-id same", "assign-id --to N", {"--sim", "assign-id", "--to", "1"}, 2,
            "already has id 1", fails);
        add("scan", "scan", {"--sim", "scan", "--ids", "1-2", "--bauds", "9600"}, 0, "[1]", ok);
        add("scan dead", "scan", {"--rtu-tcp", "127.0.0.1:1", "scan", "--ids", "1-2"}, 3,
            "scan stopped", fails);
        add("ports", "ports", {"ports"}, 0, "[]", ok);
        add("ports argument", "ports", {"ports", "extra"}, 2, "extra", fails);
        add("report", "report FILE.pdf|.html", {"report", "--from", profile, "@DIR/r.html"}, 0,
            "file", ok);
        add("report missing", "report FILE.pdf|.html", {"report", "--from", missing, "@DIR/r.html"},
            2, "nope.json", fails);
        add("replay events", "replay LOG|BUNDLE.zip", {"replay", "@DIR/session.log", "--events"}, 0,
            "[1]", ok);
        add("replay at", "replay LOG|BUNDLE.zip", {"replay", "@DIR/session.log", "--at", "99999"},
            0, "devices", ok);
        add("replay missing", "replay LOG|BUNDLE.zip", {"replay", missing, "--events"}, 2,
            "nope.json", fails);
        add("bundle", "bundle OUT.zip", {"bundle", "@DIR/support.zip"}, 0, "contents", ok);
        add("bundle no profile", "bundle OUT.zip", {"bundle", "@DIR/s2.zip", "--profile", missing},
            2, "nope.json", fails);

        // Before any command is chosen.
        add("unknown option", "", {"--frobnicate", "read"}, 2, "frobnicate", fails);
        add("no command", "", {"--sim"}, 2, "monitor, listen", fails);
        add("bad id list", "", {"--sim", "--id", "1,x", "read"}, 2, "--id", fails);
        add("unknown command", "", {"--sim", "frobnicate"}, 2, "frobnicate", fails);
        add("unknown language", "", {"--lang", "xx", "--sim", "read"}, 2, "xx", fails);
        add("no link", "", {"read"}, 2, "--port", fails);
        add("one id only", "", {"--sim", "--id", "1,2", "scan"}, 2, "one device id", fails);
        return rows;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(dir.isValid());
        host = std::make_unique<SimHost>();
        SimOptions options;
        options.tcp = true;
        // The proofs reference on motor 1's home switch: its carriage 1 mm off it, answers at
        // once, the references at 60 rpm.
        options.answerDelayMs = 0;
        MachineSettings machine = MachineSettings::ideal();
        AxisPhysics motor1 = AxisPhysics::ideal();
        motor1.startMm = 1.0;
        machine.axes.insert(1, motor1);
        options.machine = machine;
        QString error;
        QVERIFY2(host->start(options, &error), qPrintable(error));
        QVERIFY(host->device()->setValue(QStringLiteral("motor1.start_frequency"), 1600));
        // A single move of 0.5 mm at speed: over in a moment.
        QVERIFY(host->device()->setValue(QStringLiteral("motor1.speed"), 1200));
        QVERIFY(host->device()->setValue(QStringLiteral("motor1.move_distance"), 50));
        ptyMaster = posix_openpt(O_RDWR | O_NOCTTY);
        QVERIFY(ptyMaster >= 0);
        QVERIFY(grantpt(ptyMaster) == 0 && unlockpt(ptyMaster) == 0);
        ptyPath = QString::fromLocal8Bit(ptsname(ptyMaster));

        // A profile the built-in controller does not hold (diff: different), and a session log.
        ProgramRun r = ctl({"--sim", "--log", path("session.log"), "dump", path("machine.json")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile f(path("machine.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QJsonObject values = o.value(QStringLiteral("values")).toObject();
        values.insert(QStringLiteral("motor1.speed"), 123);
        o.insert(QStringLiteral("values"), values);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QJsonDocument(o).toJson());
    }

    void cleanupTestCase()
    {
        if (ptyMaster >= 0)
            ::close(ptyMaster);
    }

    void everyCommandPrintsTheEnvelope_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("expect");
        QTest::addColumn<bool>("fails");
        for (const Row &row : rows())
            QTest::newRow(row.name) << row.args << row.code << row.expect << row.fails;
    }
    void everyCommandPrintsTheEnvelope()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, expect);
        QFETCH(bool, fails);
        const ProgramRun r = ctl(QStringList{QStringLiteral("--json")} + expand(args));
        QVERIFY2(r.exitCode == code,
                 qPrintable(QStringLiteral("exit %1: %2%3").arg(r.exitCode).arg(r.out, r.err)));
        // monitor and listen: a JSON object a line, the envelope the last; else one object.
        const bool streams =
            args.contains(QStringLiteral("monitor")) || args.contains(QStringLiteral("listen"));
        QJsonObject envelope;
        if (streams) {
            const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
            QVERIFY2(!lines.isEmpty(), qPrintable(r.err));
            for (const QString &line : lines) {
                const QJsonDocument doc = QJsonDocument::fromJson(line.toUtf8());
                QVERIFY2(doc.isObject(), qPrintable(line));
                QVERIFY2(envelope.isEmpty(), "a line after the envelope");
                if (doc.object().contains(QStringLiteral("exit")))
                    envelope = doc.object();
            }
        } else {
            const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8());
            QVERIFY2(doc.isObject(), qPrintable(r.out + r.err));
            envelope = doc.object();
        }
        QVERIFY2(envelope.contains(QStringLiteral("exit")), qPrintable(r.out));
        QCOMPARE(envelope.value(QStringLiteral("exit")).toInt(-1), r.exitCode);
        QVERIFY2(envelope.value(QStringLiteral("errors")).isArray(), qPrintable(r.out));
        const QJsonValue result = envelope.value(QStringLiteral("result"));
        QVERIFY2(result.isObject() || result.isArray(), qPrintable(r.out));
        if (fails) {
            // A failure is named in the errors, without the program's name before it.
            QStringList said;
            for (const QJsonValue &e : envelope.value(QStringLiteral("errors")).toArray())
                said << e.toString();
            QVERIFY2(!said.isEmpty() && !said.first().startsWith(QLatin1String("stepcomctl:")),
                     qPrintable(r.out));
            QVERIFY2(said.join(QLatin1Char('\n')).contains(expect), qPrintable(r.out));
            return;
        }
        if (expect.startsWith(QLatin1Char('['))) {
            QVERIFY2(result.isArray(), qPrintable(r.out));
            QVERIFY2(result.toArray().size() >= (expect == QLatin1String("[1]") ? 1 : 0),
                     qPrintable(r.out));
        } else {
            QVERIFY2(result.toObject().contains(expect), qPrintable(r.out));
        }
    }

    // --sim takes the link options as a port does: the no-answer message says the timeout
    // asked for, not the default.
    void theBuiltInSimulatorWaitsTheTimeoutAsked()
    {
        const ProgramRun r =
            ctl({"--sim", "--timeout", "200", "--retries", "0", "--id", "5", "read", "device.id"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("no answer within 200 ms")), qPrintable(r.err));
        QVERIFY2(!r.err.contains(QLatin1String("500 ms")), qPrintable(r.err));
    }

    // Each usage the help lists has a row that checks its data and one that fails: a command
    // added without them fails here, and with them fails above until it prints the envelope.
    void theTableCoversEveryCommand()
    {
        const QStringList listed = usages();
        QVERIFY2(listed.size() >= 18, qPrintable(listed.join(QLatin1Char('\n'))));
        const QList<Row> table = rows();
        for (const QString &usage : listed) {
            bool data = false;
            bool failure = false;
            for (const Row &row : table) {
                if (row.usage == usage) {
                    data = data || !row.fails;
                    failure = failure || row.fails;
                }
            }
            QVERIFY2(data && failure, qPrintable(QStringLiteral("no --json row for the data and "
                                                                "one for a failure of '%1'")
                                                     .arg(usage)));
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlJson, Guiless)
#include "tst_ctljson.moc"
