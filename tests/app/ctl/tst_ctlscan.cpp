#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

// stepcomctl scan against the simulator: controllers at chosen ids and bauds over a pty and
// over RTU over TCP, slow controllers found by their late answers or a longer probe timeout,
// the JSON, the exit codes, and bad arguments named.
class TestCtlScan : public QObject
{
    Q_OBJECT

    static ProgramRun ctl(const QStringList &args)
    {
        ProgramOptions o;
        o.timeoutMs = 60000;
        return runProgram(QStringLiteral("stepcomctl"), args, o);
    }
    static bool start(SimHost &host, const QList<int> &ids, bool rtuTcp, int answerDelayMs = -1)
    {
        SimOptions o;
        o.rtu = !rtuTcp;
        o.rtuTcp = rtuTcp;
        o.ids = ids;
        o.answerDelayMs = answerDelayMs;
        QString error;
        const bool ok = host.start(o, &error);
        if (!ok)
            qWarning("%s", qPrintable(error));
        return ok;
    }
    static QStringList rtuTcp(const SimHost &host)
    {
        return {QStringLiteral("--rtu-tcp"), QStringLiteral("127.0.0.1:%1").arg(host.rtuTcpPort())};
    }
    // The rows of a table: id -> the row's words.
    static QHash<int, QStringList> rows(const QString &out)
    {
        QHash<int, QStringList> table;
        for (const QString &line : out.split(QLatin1Char('\n'))) {
            const QStringList words = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
            bool ok = false;
            const int id = words.value(0).toInt(&ok);
            if (ok && words.size() > 3)
                table.insert(id, words);
        }
        return table;
    }
    // The found controllers: the result of --json's object, whose exit is the program's.
    static QJsonArray json(const ProgramRun &r)
    {
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &error);
        const QJsonValue result = doc.object().value(QStringLiteral("result"));
        if (error.error != QJsonParseError::NoError || !result.isArray() ||
            doc.object().value(QStringLiteral("exit")).toInt(-1) != r.exitCode)
            qWarning("not an object with the exit code and an array: %s", qPrintable(r.out));
        return result.toArray();
    }

private Q_SLOTS:
    // Two controllers on one pty line, one at 9600 and one at 19200: each found at its baud,
    // nothing found at the other.
    void ptyFindsIdsAndBauds()
    {
        SimHost sim;
        QVERIFY(start(sim, {3, 12}, false));
        QVERIFY(sim.deviceAt(12)->setValue(QStringLiteral("device.baud"), 19200));
        const ProgramRun r =
            ctl({"--port", sim.rtuPath(), "scan", "--ids", "1-14", "--bauds", "9600,19200"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QHash<int, QStringList> table = rows(r.out);
        QCOMPARE(table.size(), 2);
        QCOMPARE(table.value(3).mid(1, 2), (QStringList{"9600", "none"}));
        QCOMPARE(table.value(12).mid(1, 2), (QStringList{"19200", "none"}));
        QVERIFY2(r.out.contains(QStringLiteral("a 2-axis controller, step angle 1.80°")),
                 qPrintable(r.out));
        // Progress and what was found go to standard error.
        QVERIFY2(r.err.contains(QStringLiteral("scanning 19200 8N1: 14 id")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("found id 12 at 19200 8N1")), qPrintable(r.err));
    }

    void rtuOverTcpJson()
    {
        SimHost sim;
        QVERIFY(start(sim, {2, 9}, true));
        const ProgramRun r = ctl(rtuTcp(sim) + QStringList{"scan", "--ids", "1-10", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QJsonArray found = json(r);
        QCOMPARE(found.size(), 2);
        QList<int> ids;
        for (const QJsonValue &v : found) {
            const QJsonObject o = v.toObject();
            ids << o.value(QStringLiteral("id")).toInt();
            // The converter's baud is its own: not guessed.
            QVERIFY(o.value(QStringLiteral("baud")).isNull());
            QVERIFY(o.value(QStringLiteral("parity")).isNull());
            QCOMPARE(o.value(QStringLiteral("where")).toString(),
                     QStringLiteral("127.0.0.1:%1").arg(sim.rtuTcpPort()));
            QCOMPARE(o.value(QStringLiteral("controller")).toString(),
                     QStringLiteral("a 2-axis controller, step angle 1.80°"));
            QCOMPARE(o.value(QStringLiteral("step_angles_raw")).toArray().size(), 2);
        }
        QCOMPARE(ids, (QList<int>{2, 9}));
        QVERIFY2(r.err.contains(QStringLiteral("only the ids are scanned")), qPrintable(r.err));
    }

    // Controllers that answer after 150 and 400 ms: found with the fitted probe timeout (their
    // late answers, which come while later ids are probed, name their ids, with a --timeout to
    // connect with) and with a longer one.
    void slowControllers_data()
    {
        QTest::addColumn<int>("delay");
        QTest::addColumn<bool>("overTcp");
        QTest::addColumn<QString>("probeTimeout");
        QTest::newRow("150 ms, fitted") << 150 << false << QString();
        QTest::newRow("150 ms, --probe-timeout 300") << 150 << false << QStringLiteral("300");
        QTest::newRow("400 ms, fitted") << 400 << false << QString();
        QTest::newRow("400 ms, --probe-timeout 600") << 400 << false << QStringLiteral("600");
        QTest::newRow("400 ms over RTU-TCP, fitted") << 400 << true << QString();
    }
    void slowControllers()
    {
        QFETCH(int, delay);
        QFETCH(bool, overTcp);
        QFETCH(QString, probeTimeout);
        SimHost sim;
        QVERIFY(start(sim, {3}, overTcp, delay));
        QStringList args = overTcp ? rtuTcp(sim) : QStringList{"--port", sim.rtuPath()};
        args << "scan"
             << "--ids"
             << "1-12"
             << "--json";
        if (!overTcp)
            args << "--bauds"
                 << "9600";
        if (!probeTimeout.isEmpty())
            args << "--probe-timeout" << probeTimeout;
        const ProgramRun r = ctl(args);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QJsonArray found = json(r);
        QCOMPARE(found.size(), 1);
        const QJsonObject o = found.first().toObject();
        QCOMPARE(o.value(QStringLiteral("id")).toInt(), 3);
        QCOMPARE(o.value(QStringLiteral("controller")).toString(),
                 QStringLiteral("a 2-axis controller, step angle 1.80°"));
        // The answer cannot come sooner than the controller's delay; the suggestion covers it.
        QVERIFY(o.value(QStringLiteral("answer_ms")).toInt() >= delay);
        QVERIFY(o.value(QStringLiteral("suggested_timeout_ms")).toInt() > delay);
        QCOMPARE(o.value(QStringLiteral("late")).toBool(), probeTimeout.isEmpty());
    }

    void lateAnswerInTheTable()
    {
        SimHost sim;
        QVERIFY(start(sim, {4}, false, 400));
        const ProgramRun r =
            ctl({"--port", sim.rtuPath(), "scan", "--ids", "3-12", "--bauds", "9600"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QCOMPARE(rows(r.out).keys(), QList<int>{4});
        // "connect with --timeout N", N enough for the 400 ms it took.
        const QString hint = QStringLiteral("later than the probe waited: connect with --timeout ");
        const qsizetype at = r.out.indexOf(hint);
        QVERIFY2(at > 0, qPrintable(r.out));
        QVERIFY(r.out.mid(at + hint.size()).section(QLatin1Char('\n'), 0, 0).toInt() > 400);
    }

    void noneFound()
    {
        SimHost sim;
        QVERIFY(start(sim, {30}, false));
        ProgramRun r = ctl({"--port", sim.rtuPath(), "scan", "--ids", "1-4", "--bauds", "9600"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QStringLiteral("No controller answered")), qPrintable(r.out));
        r = ctl({"--port", sim.rtuPath(), "scan", "--ids", "1-4", "--bauds", "9600", "--json"});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(json(r).size(), 0);
    }

    void linkError()
    {
        const ProgramRun r =
            ctl({"--rtu-tcp", "127.0.0.1:1", "scan", "--ids", "1-2"}); // nobody listens on 1
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains(QStringLiteral("scan stopped:")), qPrintable(r.err));
    }

    void badArguments_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QStringList port{"--port", "/dev/null"};
        QTest::newRow("baud") << (port + QStringList{"scan", "--bauds", "9600,1200"})
                              << "--bauds: '1200' is not one of 4800, 9600, 19200, 38400";
        QTest::newRow("baud twice") << (port + QStringList{"scan", "--bauds", "9600,9600"})
                                    << "--bauds: 9600 is given twice";
        QTest::newRow("ids") << (port + QStringList{"scan", "--ids", "0-5"}) << "--ids: ";
        QTest::newRow("parity") << (port + QStringList{"scan", "--parity", "none,mark"})
                                << "--parity: 'mark' is not none, even or odd";
        QTest::newRow("probe timeout") << (port + QStringList{"scan", "--probe-timeout", "fast"})
                                       << "--probe-timeout: 'fast' is not a number of ms";
        QTest::newRow("bauds over rtu-tcp")
            << QStringList{"--rtu-tcp", "127.0.0.1:1", "scan", "--bauds", "9600"}
            << "--bauds: over --tcp and --rtu-tcp the converter's serial line has its own";
        QTest::newRow("ids without scan")
            << (port + QStringList{"read", "--ids", "1-3"}) << "--ids is an option of scan";
        QTest::newRow("parities without scan")
            << (port + QStringList{"read", "--parity", "none,even"})
            << "--parity: give one parity; several are for scan";
        QTest::newRow("no line") << QStringList{"scan"} << "scan: give the line to scan";
        QTest::newRow("argument") << (port + QStringList{"scan", "7"}) << "scan takes no arguments";
    }
    void badArguments()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const ProgramRun r = ctl(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlScan, Guiless)
#include "tst_ctlscan.moc"
