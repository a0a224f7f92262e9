// stepcomctl when the controller's 24 V is switched off and on: `monitor --json` prints a
// "restarted" event and goes on, also when the other axis was moving (the one that stood still
// proves it), and a "possible_restart" with what it saw when only a moving axis went to 0; `command
// motor1.home --wait` cut by it ends with exit code 1 and the cause "silent" (the axis stands at 0
// as a homing that ended would: whether it ended or the controller restarted is not known), not
// "done" and not "link lost". `monitor --id 1,2` says both per device: the one whose standing
// axis went to 0 restarted, the other one whose only moving axis went there may have.
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "testpaths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestCtlRestart : public QObject
{
    Q_OBJECT

    // A controller answering in 5 ms, switched off `offMs` at `atMs` after it started (< 0:
    // only when the test says).
    static bool start(SimHost &host, int atMs, int offMs)
    {
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        if (atMs >= 0)
            o.powerCycles = {{atMs, offMs}};
        QString error;
        const bool ok = host.start(o, &error);
        if (!ok)
            qWarning("%s", qPrintable(error));
        return ok;
    }

    // `stepcomctl monitor --json` until it printed an event (or 150 samples): the power goes
    // off for 1.5 s once it printed 3 samples. Returns the events.
    static QList<QJsonObject> monitorAPowerCycle(SimHost &host, QString *err)
    {
        QProcess p;
        p.start(programPath(QStringLiteral("stepcomctl")),
                {"--port", host.rtuPath(), "--timeout", "200", "--json", "monitor", "--count",
                 "150", "--interval", "100"});
        if (!p.waitForStarted(10000))
            return {};
        QByteArray out;
        QList<QJsonObject> events;
        int samples = 0;
        bool cut = false;
        // Whatever ends it, what follows looks at the events it printed.
        (void)QTest::qWaitFor(
            [&] {
                out += p.readAllStandardOutput();
                qsizetype end = 0;
                while ((end = out.indexOf('\n')) >= 0) {
                    const QJsonObject o = QJsonDocument::fromJson(out.left(end)).object();
                    out.remove(0, end + 1);
                    if (o.contains(QStringLiteral("event")))
                        events << o;
                    else if (!o.contains(QStringLiteral("exit"))) // not the envelope at the end
                        ++samples;
                }
                if (samples >= 3 && !cut)
                    cut = host.powerCycle(1500);
                return p.state() == QProcess::NotRunning || !events.isEmpty();
            },
            60000);
        p.terminate();
        p.waitForFinished(10000);
        *err = QString::fromUtf8(p.readAllStandardError());
        return events;
    }
    static QStringList strings(const QJsonValue &v)
    {
        QStringList out;
        for (const QJsonValue &s : v.toArray())
            out << s.toString();
        return out;
    }

private Q_SLOTS:
    void monitorSaysTheRestartAndGoesOn()
    {
        SimHost host;
        QVERIFY(start(host, 3500, 1500));
        // Away from 0, so the restart shows in the positions.
        QVERIFY(host.device()->command(QStringLiteral("motor1.move")));
        QTRY_VERIFY_WITH_TIMEOUT(!host.device()->running(1), 5000);
        QVERIFY(host.device()->position(1) != 0);
        ProgramOptions options;
        options.timeoutMs = 30000;
        const ProgramRun r = runProgram(QStringLiteral("stepcomctl"),
                                        {"--port", host.rtuPath(), "--timeout", "200", "--json",
                                         "monitor", "--count", "50", "--interval", "100"},
                                        options);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QStringList events;
        int samples = 0;
        for (const QString &line : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
            const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
            if (o.contains(QStringLiteral("event")))
                events << o.value(QStringLiteral("event")).toString();
            else if (!o.contains(QStringLiteral("exit"))) // the envelope, the last line
                ++samples;
        }
        QCOMPARE(events, QStringList{QStringLiteral("restarted")});
        QCOMPARE(samples, 50);
    }

    // Motor 1 stands away from 0, motor 2 runs on: cut off, both read 0. Motor 1 proves it.
    void aRestartWhileTheOtherAxisMoves()
    {
        SimHost host;
        QVERIFY(start(host, -1, 0));
        QVERIFY(host.device()->command(QStringLiteral("motor1.move")));
        QTRY_VERIFY_WITH_TIMEOUT(!host.device()->running(1), 10000);
        QVERIFY(host.device()->position(1) != 0);
        QVERIFY(host.device()->command(QStringLiteral("motor2.forward")));
        QString err;
        const QList<QJsonObject> events = monitorAPowerCycle(host, &err);
        QVERIFY2(events.size() == 1, qPrintable(err));
        const QJsonObject o = events.first();
        QCOMPARE(o.value(QStringLiteral("event")).toString(), QStringLiteral("restarted"));
        QCOMPARE(o.value(QStringLiteral("id")).toInt(), 1);
        QVERIFY(o.value(QStringLiteral("silent_ms")).toInt() >= 1000);
        QCOMPARE(strings(o.value(QStringLiteral("zeroed"))), (QStringList{"motor1", "motor2"}));
        QCOMPARE(strings(o.value(QStringLiteral("stood_still"))), QStringList{"motor1"});
        QCOMPARE(strings(o.value(QStringLiteral("moving"))), QStringList{"motor2"});
        QVERIFY(o.value(QStringLiteral("before")).toObject().value("motor1").toDouble() != 0);
    }

    // Motor 1 stands at 0, motor 2 runs on: after the cut only motor 2 went to 0, as a motion
    // may end. Not claimed, but said, with what was seen.
    void aPossibleRestartIsSaid()
    {
        SimHost host;
        QVERIFY(start(host, -1, 0));
        QCOMPARE(host.device()->position(1), 0);
        QVERIFY(host.device()->command(QStringLiteral("motor2.forward")));
        QString err;
        const QList<QJsonObject> events = monitorAPowerCycle(host, &err);
        QVERIFY2(events.size() == 1, qPrintable(err));
        const QJsonObject o = events.first();
        QCOMPARE(o.value(QStringLiteral("event")).toString(), QStringLiteral("possible_restart"));
        QVERIFY(o.value(QStringLiteral("silent_ms")).toInt() >= 1000);
        QCOMPARE(strings(o.value(QStringLiteral("zeroed"))), QStringList{"motor2"});
        QCOMPARE(strings(o.value(QStringLiteral("stood_still"))), QStringList{"motor1"});
        QCOMPARE(strings(o.value(QStringLiteral("moving"))), QStringList{"motor2"});
    }

    // Two controllers on the line: device 2's motor 1 stands away from 0, device 1's motor 2
    // runs on. `stepcomctl --id 1,2 monitor` (--json when `json`) until both were said (or 100
    // samples each), both cut off for 1.5 s at once after 6 samples. Its standard output lines
    // and standard error.
    static QPair<QList<QByteArray>, QString> monitorALine(bool json)
    {
        SimHost host;
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        o.ids = {1, 2};
        QString error;
        if (!host.start(o, &error)) {
            qWarning("%s", qPrintable(error));
            return {};
        }
        SimDevice *one = host.devices().at(0);
        SimDevice *two = host.devices().at(1);
        two->command(QStringLiteral("motor1.move"));
        if (!QTest::qWaitFor([two] { return !two->running(1); }, 10000) || two->position(1) == 0 ||
            one->position(1) != 0)
            return {};
        one->command(QStringLiteral("motor2.forward"));
        QProcess p;
        QStringList args{"--port", host.rtuPath(), "--id", "1,2", "--timeout", "200"};
        if (json)
            args << "--json";
        p.start(programPath(QStringLiteral("stepcomctl")),
                args + QStringList{"monitor", "--count", "100", "--interval", "100"});
        if (!p.waitForStarted(10000))
            return {};
        QByteArray out;
        QList<QByteArray> lines;
        QString err;
        int samples = 0;
        bool cut = false;
        const auto said = [&] {
            if (json)
                return out.count("\"event\"") >= 2;
            return err.contains(QLatin1String("controller 2")) &&
                   err.contains(QLatin1String("controller 1"));
        };
        // Whatever ends it, the callers look at what it printed.
        (void)QTest::qWaitFor(
            [&] {
                out += p.readAllStandardOutput();
                err += QString::fromUtf8(p.readAllStandardError());
                samples = int(out.count('\n'));
                if (samples >= 6 && !cut)
                    cut = host.powerCycle(1500);
                return p.state() == QProcess::NotRunning || said();
            },
            60000);
        p.terminate();
        p.waitForFinished(10000);
        out += p.readAllStandardOutput();
        err += QString::fromUtf8(p.readAllStandardError());
        for (const QByteArray &line : out.split('\n'))
            if (!line.isEmpty())
                lines << line;
        return {lines, err};
    }

    // Both cut at once: device 2's motor 1 stood away from 0 (a restart), device 1's only
    // moving axis went to 0 (a possible one). Each said with its id and what was seen.
    void aLineOfSeveralSaysEachRestart()
    {
        const auto [lines, err] = monitorALine(true);
        QHash<int, QJsonObject> events;
        for (const QByteArray &line : lines) {
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            if (o.contains(QStringLiteral("event")))
                events.insert(o.value(QStringLiteral("id")).toInt(), o);
        }
        QVERIFY2(events.size() == 2, qPrintable(err));
        const QJsonObject restarted = events.value(2);
        QCOMPARE(restarted.value(QStringLiteral("event")).toString(), QStringLiteral("restarted"));
        // Its standing axis at 0 is the proof, whether a read fell into the silence or not.
        QVERIFY(restarted.contains(QStringLiteral("silent_ms")));
        QCOMPARE(strings(restarted.value(QStringLiteral("zeroed"))), QStringList{"motor1"});
        QCOMPARE(strings(restarted.value(QStringLiteral("stood_still"))),
                 (QStringList{"motor1", "motor2"}));
        QVERIFY(restarted.contains(QStringLiteral("lost")));
        QVERIFY(restarted.value(QStringLiteral("before")).toObject().value("motor1").toDouble() !=
                0);
        const QJsonObject possible = events.value(1);
        QCOMPARE(possible.value(QStringLiteral("event")).toString(),
                 QStringLiteral("possible_restart"));
        QVERIFY(possible.value(QStringLiteral("silent_ms")).toInt() >= 1000);
        QCOMPARE(strings(possible.value(QStringLiteral("zeroed"))), QStringList{"motor2"});
        QCOMPARE(strings(possible.value(QStringLiteral("moving"))), QStringList{"motor2"});
    }

    // Without --json the same two are said in words on standard error, each with its device.
    void aLineOfSeveralSaysEachRestartInWords()
    {
        const auto [lines, err] = monitorALine(false);
        QVERIFY(!lines.isEmpty());
        QVERIFY2(err.contains(QLatin1String("controller 2 restarted")), qPrintable(err));
        QVERIFY2(err.contains(QLatin1String("controller 1 may have restarted")), qPrintable(err));
    }

    void aHomingCutByAPowerCycleEndsUnknown()
    {
        SimHost host;
        // Homing from the carriage's start takes a few seconds: the power goes off during it.
        QVERIFY(start(host, 1800, 1500));
        ProgramOptions options;
        options.timeoutMs = 30000;
        const ProgramRun r = runProgram(QStringLiteral("stepcomctl"),
                                        {"--port", host.rtuPath(), "--timeout", "200", "--json",
                                         "command", "motor1.home", "--wait"},
                                        options);
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8())
                                  .object()
                                  .value(QStringLiteral("result"))
                                  .toObject();
        QCOMPARE(o.value(QStringLiteral("cause")).toString(), QStringLiteral("silent"));
        QCOMPARE(o.value(QStringLiteral("outcome")).toString(), QStringLiteral("not_known"));
        QCOMPARE(o.value(QStringLiteral("ok")).toBool(), false);
        QVERIFY2(o.value(QStringLiteral("message"))
                     .toString()
                     .contains(QLatin1String("how it ended is not known")),
                 qPrintable(r.out));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlRestart, Guiless)
#include "tst_ctlrestart.moc"
