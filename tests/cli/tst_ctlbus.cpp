#include "programrun.h"
#include "sim/simdevice.h"
#include "sim/simhost.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

// stepcomctl on a line of several controllers: --id 1,2,3 runs a command for each (output
// keyed by id, the worst exit code), and assign-id gives the one controller a new id.
class TestCtlBus : public QObject
{
    Q_OBJECT

    static ProgramRun ctl(const QStringList &args)
    {
        return runProgram(QStringLiteral("stepcomctl"), args);
    }
    static QStringList tcp(const SimHost &host)
    {
        return {QStringLiteral("--tcp"),     QStringLiteral("127.0.0.1:%1").arg(host.tcpPort()),
                QStringLiteral("--timeout"), QStringLiteral("200"),
                QStringLiteral("--retries"), QStringLiteral("0")};
    }
    static QStringList rtu(const SimHost &host)
    {
        return {QStringLiteral("--port"),    host.rtuPath(),
                QStringLiteral("--timeout"), QStringLiteral("200"),
                QStringLiteral("--retries"), QStringLiteral("1")};
    }
    static bool start(SimHost &host, bool overTcp, const QList<int> &ids)
    {
        SimOptions o;
        o.tcp = overTcp;
        o.rtu = !overTcp;
        o.ids = ids;
        o.answerDelayMs = 5;
        QString error;
        const bool ok = host.start(o, &error);
        if (!ok)
            qWarning("%s", qPrintable(error));
        return ok;
    }

private Q_SLOTS:
    void readIsKeyedById()
    {
        ProgramRun r = ctl({"--sim", "--id", "1-3", "read", "device.id"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (int id : {1, 2, 3})
            QVERIFY2(r.out.contains(QStringLiteral("== device id %1 ==\ndevice.id = %1").arg(id)),
                     qPrintable(r.out));
        r = ctl({"--sim", "--id", "2,3", "--json", "read", "device.id"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject all = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(all.keys(), (QStringList{"2", "3"}));
        QCOMPARE(all.value("3").toObject().value("exit").toInt(), 0);
        QCOMPARE(all.value("3").toObject().value("result").toObject().value("device.id").toInt(),
                 3);
    }

    void theExitCodeIsTheWorst()
    {
        SimHost host;
        QVERIFY(start(host, true, {1, 2}));
        const ProgramRun r =
            ctl(tcp(host) + QStringList{"--id", "1,7,2", "--json", "read", "device.id"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject all = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(all.value("1").toObject().value("exit").toInt(), 0);
        QCOMPARE(all.value("7").toObject().value("exit").toInt(), 1);
        QCOMPARE(all.value("2").toObject().value("result").toObject().value("device.id").toInt(),
                 2);
        QVERIFY2(r.err.contains(QStringLiteral("id 7: ")), qPrintable(r.err));
    }

    void commandReachesOnlyTheIdsNamed()
    {
        SimHost host;
        QVERIFY(start(host, true, {1, 2, 3}));
        const ProgramRun r = ctl(tcp(host) + QStringList{"--id", "1,3", "command", "motor1.move"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(host.deviceAt(1)->running(1));
        QVERIFY(!host.deviceAt(2)->running(1));
        QVERIFY(host.deviceAt(3)->running(1));
    }

    void dumpWritesOneFilePerId()
    {
        QTemporaryDir dir;
        const ProgramRun r =
            ctl({"--sim", "--id", "1,2", "dump", dir.filePath(QStringLiteral("axis.json"))});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("axis-id1.json"))));
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("axis-id2.json"))));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("axis.json"))));
    }

    void severalIdsAreRefusedWhereTheyMakeNoSense()
    {
        const ProgramRun r = ctl({"--sim", "--id", "1,2", "write", "motor1.speed=200"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("write: give one device id")), qPrintable(r.err));
        QCOMPARE(ctl({"--sim", "--id", "1,x", "read"}).exitCode, 2);
        QCOMPARE(ctl({"--sim", "--id", "2,2", "read"}).exitCode, 2);
    }

    void assignIdGivesTheControllerItsNewId()
    {
        SimHost host;
        QVERIFY(start(host, false, {1}));
        const ProgramRun r = ctl(rtu(host) + QStringList{"assign-id", "--to", "4"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("answers at id 4")), qPrintable(r.out));
        QCOMPARE(host.device()->deviceId(), 4);
    }

    void assignIdRefusesATakenId()
    {
        SimHost host;
        QVERIFY(start(host, false, {4, 1}));
        const ProgramRun r = ctl(rtu(host) + QStringList{"assign-id", "--to", "4"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("id 4 is taken")), qPrintable(r.err));
        QCOMPARE(host.devices().at(1)->deviceId(), 1);
    }

    void assignIdRefusesACollision()
    {
        SimHost host;
        QVERIFY(start(host, false, {1, 1}));
        const ProgramRun r = ctl(rtu(host) + QStringList{"assign-id", "--to", "2"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("garbled answers at id 1")), qPrintable(r.err));
        QCOMPARE(host.devices().at(0)->deviceId(), 1);
        QCOMPARE(host.devices().at(1)->deviceId(), 1);
    }
};

QTEST_GUILESS_MAIN(TestCtlBus)
#include "tst_ctlbus.moc"
