// stepcomctl --log and replay: a session recorded against the simulator, one
// stepcomctl run after another into one log (read-all, a write, a move, an E-STOP), replays to
// exactly what each run read and wrote; bad input gives a message and a non-zero exit.
#include "logbuilder.h"
#include "programrun.h"
#include "sim/host/simhost.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestCtlReplay : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    QString logPath;
    SimHost host;

    ProgramRun ctl(const QStringList &args)
    {
        ProgramOptions options;
        options.timeoutMs = 30000;
        return runProgram(
            QStringLiteral("stepcomctl"),
            QStringList{"--port", host.rtuPath(), "--timeout", "300", "--log", logPath} + args,
            options);
    }
    static ProgramRun replay(const QString &log, const QStringList &args)
    {
        return runProgram(QStringLiteral("stepcomctl"), QStringList{"replay", log} + args);
    }
    // The clock time of the log's last line: the moment the run just made ended.
    QString lastClock() const
    {
        QFile f(logPath);
        if (!f.open(QIODevice::ReadOnly))
            return {};
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        return QString::fromLatin1(lines.last().mid(11, 12));
    }
    // --json's result, once the object's exit is the program's.
    static QJsonValue result(const ProgramRun &r)
    {
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        if (o.value(QStringLiteral("exit")).toInt(-1) != r.exitCode)
            qWarning("not the envelope of exit %d: %s", r.exitCode, qPrintable(r.out));
        return o.value(QStringLiteral("result"));
    }
    QJsonObject deviceAt(const QString &time)
    {
        const ProgramRun r = replay(logPath, {"--at", time, "--json"});
        if (r.exitCode != 0)
            qWarning("replay --at %s: %s", qPrintable(time), qPrintable(r.err));
        return QJsonDocument::fromJson(r.out.toUtf8())
            .object()
            .value(QStringLiteral("result"))
            .toObject()
            .value(QStringLiteral("devices"))
            .toObject()
            .value(QStringLiteral("1"))
            .toObject();
    }

private Q_SLOTS:
    void initTestCase()
    {
        logPath = dir.filePath(QStringLiteral("session.log"));
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
    }

    void aRecordedSessionReplaysToWhatWasReadAndWritten()
    {
        // 1. read-all
        const ProgramRun read = ctl({"--json", "read"});
        QVERIFY2(read.exitCode == 0, qPrintable(read.err));
        const QJsonObject readAll = result(read).toObject();
        const QString t1 = lastClock();
        const QJsonObject at1 = deviceAt(t1);
        QCOMPARE(at1.value(QStringLiteral("values")).toObject(), readAll);
        QVERIFY(at1.value(QStringLiteral("written")).toObject().isEmpty());

        // 2. a write
        const ProgramRun write = ctl({"write", "motor1.speed=450", "motor2.pitch=6"});
        QVERIFY2(write.exitCode == 0, qPrintable(write.err));
        const QString t2 = lastClock();
        const QJsonObject at2 = deviceAt(t2);
        QJsonObject expected = readAll;
        expected.insert(QStringLiteral("motor1.speed"), 450);
        expected.insert(QStringLiteral("motor2.pitch"), 6);
        QCOMPARE(at2.value(QStringLiteral("values")).toObject(), expected);
        QCOMPARE(at2.value(QStringLiteral("written")).toObject(),
                 (QJsonObject{{"motor1.speed", 450}, {"motor2.pitch", 6}}));
        QCOMPARE(deviceAt(t1), at1); // the earlier moment is still what it was

        // 3. a move, waited for, then where it ended
        const ProgramRun move = ctl({"command", "motor1.move", "--wait"});
        QVERIFY2(move.exitCode == 0, qPrintable(move.err + move.out));
        const ProgramRun where = ctl({"--json", "read", "motor1.position", "motor2.position",
                                      "motor1.running", "motor2.running", "io.in1", "io.out1"});
        QVERIFY2(where.exitCode == 0, qPrintable(where.err));
        const QJsonObject ended = result(where).toObject();
        QVERIFY(ended.value(QStringLiteral("motor1.position")).toDouble() != 0);
        const QString t4 = lastClock();
        const QJsonObject at4 = deviceAt(t4).value(QStringLiteral("values")).toObject();
        for (auto it = ended.begin(); it != ended.end(); ++it)
            QCOMPARE(at4.value(it.key()), it.value());

        // 4. the E-STOP
        const ProgramRun estop = ctl({"command", "estop"});
        QVERIFY2(estop.exitCode == 0, qPrintable(estop.err));
        // Past the end: the last state.
        QCOMPARE(deviceAt(QStringLiteral("999999")).value(QStringLiteral("values")).toObject(),
                 deviceAt(lastClock()).value(QStringLiteral("values")).toObject());

        // The markers: every run's link, the write with its values, the move, the E-STOP.
        const ProgramRun events = replay(logPath, {"--events", "--json"});
        QVERIFY2(events.exitCode == 0, qPrintable(events.err));
        QStringList seen;
        double last = 0;
        for (const QJsonValue &v : result(events).toArray()) {
            const QJsonObject e = v.toObject();
            QVERIFY(e.value(QStringLiteral("t_s")).toDouble() >= last);
            last = e.value(QStringLiteral("t_s")).toDouble();
            const QString kind = e.value(QStringLiteral("kind")).toString();
            if (kind != QLatin1String("link-up") && kind != QLatin1String("link-down"))
                seen << QStringLiteral("%1 %2: %3")
                            .arg(e.value(QStringLiteral("device")).toInt())
                            .arg(kind, e.value(QStringLiteral("text")).toString());
        }
        const QString speedBefore =
            QString::number(readAll.value(QStringLiteral("motor1.speed")).toDouble());
        const QString pitchBefore =
            QString::number(readAll.value(QStringLiteral("motor2.pitch")).toDouble(), 'f', 2);
        QCOMPARE(
            seen,
            (QStringList{QStringLiteral("1 write: motor1.speed %1 rpm → 450 rpm").arg(speedBefore),
                         QStringLiteral("1 write: motor2.pitch %1 mm → 6.00 mm").arg(pitchBefore),
                         "1 command: motor1.move", "1 estop: E-STOP acknowledged"}));
        const ProgramRun text = replay(logPath, {"--events"});
        QCOMPARE(text.out.count(QLatin1String("link-up")), 5); // one per run

        // What changed from the read-all to the write.
        const ProgramRun diff = replay(logPath, {"--diff", t1, t2});
        QVERIFY2(diff.exitCode == 0, qPrintable(diff.err));
        QVERIFY2(diff.out.contains(
                     QStringLiteral("id 1  motor1.speed  %1 rpm → 450 rpm").arg(speedBefore)),
                 qPrintable(diff.out));
        QVERIFY(diff.out.contains(QLatin1String("changes: 2")));
    }

    // Several controllers on the line: each one's state, keyed by its id.
    void everyDeviceOfTheLineHasItsState()
    {
        const QString log = dir.filePath(QStringLiteral("line.log"));
        ProgramOptions options;
        options.timeoutMs = 30000;
        const ProgramRun read = runProgram(QStringLiteral("stepcomctl"),
                                           {"--sim", "--id", "1,2", "--log", log, "--json", "read",
                                            "motor1.speed", "motor1.position", "device.id"},
                                           options);
        QVERIFY2(read.exitCode == 0, qPrintable(read.err));
        const QJsonObject byId = result(read).toObject();
        const ProgramRun r = replay(log, {"--at", "99999", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject devices =
            result(r).toObject().value(QStringLiteral("devices")).toObject();
        QCOMPARE(devices.keys(), (QStringList{"1", "2"}));
        for (const QString &id : {QStringLiteral("1"), QStringLiteral("2")}) {
            const QJsonObject values =
                devices.value(id).toObject().value(QStringLiteral("values")).toObject();
            QCOMPARE(values, byId.value(id).toObject().value(QStringLiteral("result")).toObject());
            QCOMPARE(values.value(QStringLiteral("device.id")).toInt(), id.toInt());
        }
        QFile f(log);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains("\n# ids: 1,2\n"));
    }

    void badInputSaysWhatIsWrong_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no such log") << QStringList{"replay", "/nonexistent.log", "--events"}
                                     << "/nonexistent.log: no such file";
        QTest::newRow("no mode") << QStringList{"replay", "LOG"}
                                 << "replay needs a log and one of --events, --at TIME";
        QTest::newRow("two modes") << QStringList{"replay", "LOG", "--events", "--at", "1"}
                                   << "replay needs a log and one of";
        QTest::newRow("bad time") << QStringList{"replay", "LOG", "--at", "soon"}
                                  << "'soon' is not a time";
        QTest::newRow("diff without T2")
            << QStringList{"replay", "LOG", "--diff", "1"} << "--diff T1 T2";
        QTest::newRow("not a log")
            << QStringList{"replay", "NOTALOG", "--events"} << "is not a StepCom session log";
        QTest::newRow("bundle without a file") << QStringList{"bundle"} << "bundle needs";
    }
    void badInputSaysWhatIsWrong()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QFile garbage(dir.filePath(QStringLiteral("garbage.txt")));
        QVERIFY(garbage.open(QIODevice::WriteOnly));
        garbage.write("not\na\nlog\n");
        garbage.close();
        LogBuilder b;
        b.header();
        b.read(1, 0, {180, 8});
        args.replaceInStrings(QStringLiteral("NOTALOG"), garbage.fileName());
        args.replaceInStrings(QStringLiteral("LOG"), b.save(dir, QStringLiteral("small.log")));
        const ProgramRun r = runProgram(QStringLiteral("stepcomctl"), args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    // A possible restart the session marked is listed as one, in its own kind and words.
    void aPossibleRestartIsListed()
    {
        LogBuilder b;
        b.header();
        b.read(1, 0, {180, 8});
        b.mark(SessionLog::kPossibleRestart,
               QStringLiteral("id 1 may have restarted: silent 2.5 s; zeroed motor2; stood still "
                              "motor1; moving motor2; before motor1=0.00, motor2=98.26"));
        const QString log = b.save(dir, QStringLiteral("possible.log"));
        const ProgramRun json = replay(log, {"--events", "--json"});
        QVERIFY2(json.exitCode == 0, qPrintable(json.err));
        QJsonObject found;
        for (const QJsonValue &v : result(json).toArray())
            if (v.toObject().value(QStringLiteral("kind")).toString() ==
                QLatin1String("possible-restart"))
                found = v.toObject();
        QCOMPARE(found.value(QStringLiteral("device")).toInt(), 1);
        QVERIFY2(found.value(QStringLiteral("text"))
                     .toString()
                     .startsWith(QLatin1String("id 1 may have restarted: silent 2.5 s")),
                 qPrintable(json.out));
        const ProgramRun text = replay(log, {"--events"});
        QVERIFY2(text.out.contains(QLatin1String("possible-restart  id 1 may have restarted")),
                 qPrintable(text.out));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlReplay, Guiless)
#include "tst_ctlreplay.moc"
