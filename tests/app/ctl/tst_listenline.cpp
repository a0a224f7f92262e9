// `stepcomctl listen` on a line of three (LineHub, as `stepcom-sim --line 3` makes it): a PLC
// (pymodbus's RTU client) polls and writes the simulated controller, stepcomctl listens on the
// third pty. Every write is decoded with its key and value, every read paired, no frame lost
// or damaged, and the listener put not one byte on the line.
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/serve/linehub.h"
#include "testpaths.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestListenLine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        if (QProcess::execute(QStringLiteral("/usr/bin/python3"),
                              {QStringLiteral("-c"), QStringLiteral("import pymodbus.client")}) !=
            0)
            QSKIP("python3-pymodbus is missing (scripts/deps.sh --test)");
    }

    void listensBesideAPlc()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.checkBaud = false; // the line's ptys carry no baud; the listener's is checked
        options.answerDelayMs = 5;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        LineHub hub;
        QVERIFY2(hub.open(3, &error), qPrintable(error));
        QVERIFY2(hub.attach(host.ptyPath(), &error), qPrintable(error));
        const QStringList paths = hub.paths();
        QCOMPARE(paths.size(), 3);

        QTemporaryDir dir;
        const QString logPath = dir.filePath(QStringLiteral("listen.log"));
        QProcess listener;
        listener.start(programPath(QStringLiteral("stepcomctl")),
                       {QStringLiteral("listen"), QStringLiteral("--port"), paths.at(2),
                        QStringLiteral("--baud"), QStringLiteral("38400"), QStringLiteral("--json"),
                        QStringLiteral("--log"), logPath, QStringLiteral("--seconds"),
                        QStringLiteral("120")});
        QByteArray listenErr;
        QTRY_VERIFY_WITH_TIMEOUT(
            (listenErr += listener.readAllStandardError()).contains("listening on"), 20000);

        ProgramOptions plc;
        plc.timeoutMs = 60000;
        const QString master = sourcePath(QStringLiteral("tests/fixtures/plc_master.py"));
        QProcess python;
        python.start(QStringLiteral("/usr/bin/python3"),
                     {master, paths.at(0), QStringLiteral("38400"), QStringLiteral("6")});
        QVERIFY(python.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(python.state() == QProcess::NotRunning, 60000);
        const QStringList sent =
            QString::fromUtf8(python.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
        QVERIFY2(!sent.isEmpty() && sent.last().startsWith(u"done "), qPrintable(sent.join(u'\n')));
        QVERIFY2(sent.filter(QStringLiteral("error")).isEmpty(), qPrintable(sent.join(u'\n')));

        // The last answer reaches the listener; then Ctrl-C (SIGTERM alike) ends it.
        const int requests = sent.last().section(u' ', 1).toInt();
        QVERIFY(requests >= 12);
        QByteArray out;
        auto jsonLines = [&] {
            out += listener.readAllStandardOutput();
            return int(out.count('\n'));
        };
        // A request of several values is a line each; every request is at least one.
        QTRY_VERIFY_WITH_TIMEOUT(jsonLines() >= requests, 20000);
        listener.terminate();
        QVERIFY(listener.waitForFinished(20000));
        out += listener.readAllStandardOutput();
        listenErr += listener.readAllStandardError();
        QCOMPARE(listener.exitCode(), 0);

        QList<QJsonObject> heard;
        for (const QByteArray &line : out.split('\n')) {
            if (line.isEmpty())
                continue;
            QJsonParseError parseError;
            const QJsonDocument doc = QJsonDocument::fromJson(line, &parseError);
            QVERIFY2(doc.isObject(), line.constData());
            heard << doc.object();
        }
        // The last line is --json's envelope: the exit code and the summary of what was heard.
        QVERIFY(!heard.isEmpty());
        const QJsonObject envelope = heard.takeLast();
        QCOMPARE(envelope.value(u"exit"), QJsonValue(0));
        QCOMPARE(envelope.value(u"result").toObject().value(u"crc_errors"), QJsonValue(0));
        // Every write the PLC made, in order, with its key and engineering value.
        QStringList writes;
        for (const QString &s : sent) {
            if (s.startsWith(u"write "))
                writes << QStringLiteral("motor1.speed=%1").arg(s.section(u' ', 2).toInt());
            else if (s.startsWith(u"write32 "))
                writes << QStringLiteral("motor2.pitch=%1").arg(s.section(u' ', 2).toInt() / 100.0);
        }
        QStringList heardWrites;
        int reads = 0;
        int commands = 0;
        for (const QJsonObject &o : heard) {
            const QString kind = o.value(u"kind").toString();
            QCOMPARE(o.value(u"from").toString(), QStringLiteral("other master"));
            if (kind == u"write")
                heardWrites << QStringLiteral("%1=%2")
                                   .arg(o.value(u"key").toString())
                                   .arg(o.value(u"value").toDouble());
            else if (kind == u"read" && o.value(u"values").toObject().size() > 0)
                ++reads;
            else if (kind == u"command" && o.value(u"key").toString() == u"motor1.stop")
                ++commands;
            else
                QFAIL(qPrintable(QStringLiteral("unexpected: ") +
                                 QString::fromUtf8(QJsonDocument(o).toJson())));
        }
        QCOMPARE(heardWrites, writes);
        QCOMPARE(reads, int(sent.filter(QStringLiteral("read ")).size()));
        QCOMPARE(commands, int(sent.filter(QStringLiteral("coil ")).size()));
        // The summary: nothing damaged, nothing unanswered.
        QVERIFY2(listenErr.contains(" 0 unanswered, 0 exceptions, 0 CRC errors"),
                 listenErr.constData());
        // The listener's pty sent nothing; the PLC and the controller did.
        QCOMPARE(hub.bytesSent(2), 0);
        QVERIFY(hub.bytesSent(0) > 0);
        QVERIFY(hub.bytesSent(3) > 0);
        // What was heard is a session log stepcomctl replays like any other.
        const ProgramRun replay =
            runProgram(QStringLiteral("stepcomctl"),
                       {QStringLiteral("replay"), logPath, QStringLiteral("--events")});
        QVERIFY2(replay.exitCode == 0, qPrintable(replay.err));
        QVERIFY2(replay.out.contains(QStringLiteral("motor1.speed")), qPrintable(replay.out));
        hub.close();
        host.stop();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestListenLine, Guiless)
#include "tst_listenline.moc"
