#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "testpaths.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

const QStringList kStatusKeys{
    "motor1.position", "motor2.position", "motor1.running", "motor2.running", "io.in1", "io.in2",
    "io.in3",          "io.in4",          "io.out1",        "io.out2",        "io.out3"};

struct MonitorRun
{
    int exitCode = -1;
    QList<QJsonObject> lines;
    QStringList raw;
    QJsonObject envelope; // --json: the last line, {"exit","result","errors"}
    QString err;
};

} // namespace

class TestMonitor : public QObject
{
    Q_OBJECT

    // Runs stepcomctl without blocking the event loop; stops it with SIGTERM after
    // `terminateAfter` lines when that is > 0.
    MonitorRun ctl(const QStringList &args, int terminateAfter = 0)
    {
        QProcess p;
        p.start(programPath(QStringLiteral("stepcomctl")), args);
        if (!p.waitForStarted(5000))
            return {};
        MonitorRun r;
        QByteArray out;
        bool terminated = false;
        const bool ended = QTest::qWaitFor(
            [&] {
                out += p.readAllStandardOutput();
                if (terminateAfter > 0 && !terminated && out.count('\n') >= terminateAfter) {
                    p.terminate();
                    terminated = true;
                }
                return p.state() == QProcess::NotRunning;
            },
            20000);
        if (!ended) {
            p.kill();
            p.waitForFinished(1000);
            return r;
        }
        out += p.readAllStandardOutput();
        r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
        r.err = QString::fromUtf8(p.readAllStandardError());
        for (const QByteArray &line : out.split('\n')) {
            if (line.isEmpty())
                continue;
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            if (o.contains(QStringLiteral("exit")) && r.envelope.isEmpty()) {
                r.envelope = o;
                continue;
            }
            if (!r.envelope.isEmpty()) // the envelope is the last line: fails every check
                r.exitCode = -3;
            r.raw << QString::fromUtf8(line);
            r.lines << o;
        }
        return r;
    }

    static void checkLines(const MonitorRun &r)
    {
        qint64 lastT = -1;
        for (int i = 0; i < r.lines.size(); ++i) {
            const QJsonObject &o = r.lines.at(i);
            QVERIFY2(!o.isEmpty(), qPrintable(r.raw.at(i))); // valid JSON, an object
            QVERIFY2(!r.raw.at(i).contains(QLatin1Char(' ')), "compact, one line");
            QStringList keys = o.keys();
            keys.sort();
            QStringList expected = kStatusKeys + QStringList{"time", "t_ms"};
            expected.sort();
            QCOMPARE(keys, expected);
            const QDateTime time =
                QDateTime::fromString(o.value("time").toString(), Qt::ISODateWithMs);
            QVERIFY2(time.isValid(), qPrintable(o.value("time").toString()));
            QVERIFY(o.value("time").toString().contains(QLatin1Char('.'))); // milliseconds
            QVERIFY(qAbs(time.secsTo(QDateTime::currentDateTime())) < 60);
            const qint64 t = qint64(o.value("t_ms").toDouble());
            QVERIFY2(t > lastT, qPrintable(r.raw.at(i)));
            lastT = t;
            for (const QString &key : kStatusKeys)
                QVERIFY2(o.value(key).isDouble(), qPrintable(key)); // numbers, not text
        }
    }

private Q_SLOTS:
    void fiveSamplesFromTheBuiltInSimulator()
    {
        const MonitorRun r = ctl({"--sim", "monitor", "--count", "5"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.lines.size(), 5);
        checkLines(r);
        // the simulator's carriages stand at their start, in engineering units
        QCOMPARE(r.lines.first().value("motor1.running").toInt(), 0);
        QCOMPARE(r.lines.first().value("io.out1").toInt(), 0);
        // At the end, on stderr: the line's counts, what it learnt and the timeout fitted to it.
        const QRegularExpression summary(
            QStringLiteral("link: (\\d+) requests, (\\d+) answers; 0 timeouts.*line: answers in "
                           "\\d+-\\d+ ms \\(median \\d+ ms\\), no echo, timeout \\d+ ms"));
        const QRegularExpressionMatch m = summary.match(r.err);
        QVERIFY2(m.hasMatch(), qPrintable(r.err));
        QVERIFY(m.captured(2).toInt() >= 10); // five samples, two reads each
    }

    void positionsFollowAMovingMotor_data()
    {
        QTest::addColumn<bool>("tcp");
        QTest::newRow("rtu") << false;
        QTest::newRow("tcp") << true;
    }
    void positionsFollowAMovingMotor()
    {
        QFETCH(bool, tcp);
        SimHost host;
        SimOptions options;
        options.rtu = !tcp;
        options.tcp = tcp;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        QVERIFY(host.device()->command(QStringLiteral("motor1.forward")));
        QVERIFY(host.device()->running(1));
        const QStringList target =
            tcp ? QStringList{"--tcp", QStringLiteral("127.0.0.1:%1").arg(host.tcpPort())}
                : QStringList{"--port", host.rtuPath()};
        const MonitorRun r = ctl(target + QStringList{"monitor", "--count", "6"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.lines.size(), 6);
        checkLines(r);
        double last = -1e9;
        for (const QJsonObject &o : r.lines) {
            QCOMPARE(o.value("motor1.running").toInt(), 1);
            const double position = o.value("motor1.position").toDouble();
            QVERIFY2(position > last, qPrintable(QString::number(position)));
            last = position;
            QCOMPARE(o.value("motor2.running").toInt(), 0);
        }
        QVERIFY(host.device()->command(QStringLiteral("motor1.stop")));
    }

    void intervalSpacesTheSamples()
    {
        const MonitorRun r = ctl({"--sim", "monitor", "--count", "3", "--interval", "300"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.lines.size(), 3);
        checkLines(r);
        for (int i = 1; i < r.lines.size(); ++i) {
            const double gap =
                r.lines.at(i).value("t_ms").toDouble() - r.lines.at(i - 1).value("t_ms").toDouble();
            QVERIFY2(gap >= 250, qPrintable(QString::number(gap)));
        }
    }

    void sigtermEndsCleanlyAfterAWholeLine()
    {
        const MonitorRun r = ctl({"--sim", "monitor"}, 2);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.lines.size() >= 2);
        checkLines(r);
    }

    // --id 1,2,3: each device in turn, one line a sample keyed by its id, --count of each.
    void severalDevicesInTurnAsJson()
    {
        const MonitorRun r = ctl({"--sim", "--id", "1,2,3", "monitor", "--count", "2", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.lines.size(), 6);
        QList<int> ids;
        qint64 lastT = -1;
        for (int i = 0; i < r.lines.size(); ++i) {
            const QJsonObject &o = r.lines.at(i);
            QVERIFY2(!o.isEmpty() && !r.raw.at(i).contains(QLatin1Char(' ')),
                     qPrintable(r.raw.at(i)));
            ids << o.value("id").toInt();
            QVERIFY(o.value("time").isString());
            QVERIFY(qint64(o.value("t_ms").toDouble()) >= lastT);
            lastT = qint64(o.value("t_ms").toDouble());
            for (const QString &key : kStatusKeys)
                QVERIFY2(o.value(key).isDouble(), qPrintable(key));
        }
        QCOMPARE(ids, (QList<int>{1, 2, 3, 1, 2, 3})); // fair: round robin in the order given
        // The last line: the envelope, its result what was watched.
        QCOMPARE(r.envelope.value("exit").toInt(-1), 0);
        QCOMPARE(r.envelope.value("result").toObject().value("samples").toObject().value("3"),
                 QJsonValue(2));
        QVERIFY(r.envelope.value("errors").toArray().isEmpty());
    }

    void severalDevicesAsText()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.ids = {1, 2, 3};
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        QVERIFY(host.deviceAt(2)->command(QStringLiteral("motor1.forward")));
        const MonitorRun r =
            ctl({"--port", host.rtuPath(), "--id", "1-3", "monitor", "--count", "1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.raw.size(), 3);
        for (int i = 0; i < 3; ++i) {
            QVERIFY2(r.raw.at(i).startsWith(QStringLiteral("id %1  t_ms=").arg(i + 1)),
                     qPrintable(r.raw.at(i)));
            // Each device's own status: only device 2's motor 1 runs.
            QVERIFY2(r.raw.at(i).contains(QStringLiteral("motor1.running=%1").arg(i == 1 ? 1 : 0)),
                     qPrintable(r.raw.at(i)));
        }
        QVERIFY(host.deviceAt(2)->command(QStringLiteral("motor1.stop")));
    }

    // A device that does not answer: the others are still watched, the exit code is the worst.
    void theExitCodeIsTheWorstOfTheDevices()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.ids = {1, 2};
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        const MonitorRun r =
            ctl({"--port", host.rtuPath(), "--id", "1,5,2", "monitor", "--count", "1", "--json"});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.lines.size(), 2);
        QCOMPARE(r.lines.at(0).value("id").toInt(), 1);
        QCOMPARE(r.lines.at(1).value("id").toInt(), 2);
        QVERIFY2(r.err.contains(QLatin1String("id 5: ")), qPrintable(r.err));
        QCOMPARE(r.envelope.value("exit").toInt(-1), 1);
        QCOMPARE(r.envelope.value("result").toObject().value("failed").toObject().value("5"),
                 QJsonValue(1));
        QVERIFY(r.envelope.value("errors").toArray().first().toString().startsWith("id 5: "));
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("argument") << QStringList{"--sim", "monitor", "motor1.position"};
        QTest::newRow("count 0") << QStringList{"--sim", "monitor", "--count", "0"};
        QTest::newRow("negative interval") << QStringList{"--sim", "monitor", "--interval", "-1"};
    }
    void usageErrors()
    {
        QFETCH(QStringList, args);
        const MonitorRun r = ctl(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.lines.isEmpty());
    }

    void helpListsMonitor()
    {
        QProcess p;
        p.start(programPath(QStringLiteral("stepcomctl")), {"--help"});
        QVERIFY(p.waitForFinished(5000));
        QVERIFY(QString::fromUtf8(p.readAllStandardOutput()).contains("monitor"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestMonitor, Guiless)
#include "tst_monitor.moc"
