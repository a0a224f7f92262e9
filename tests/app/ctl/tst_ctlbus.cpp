#include "map/registermap.h"
#include "profile/profilefile.h"
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QDate>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
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
    // The simulated controllers answer after 5 ms (start()): a write's answer repeats the
    // request, so with the manual's 35 ms it would arrive too soon to be one.
    static QStringList rtu(const SimHost &host)
    {
        return {QStringLiteral("--port"),         host.rtuPath(),
                QStringLiteral("--timeout"),      QStringLiteral("200"),
                QStringLiteral("--retries"),      QStringLiteral("1"),
                QStringLiteral("--answer-delay"), QStringLiteral("5")};
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
        // The envelope of every --json run; its result holds each id's.
        const QJsonObject top = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(top.value("exit").toInt(-1), 0);
        const QJsonObject all = top.value("result").toObject();
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
        const QJsonObject top = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(top.value("exit").toInt(), 1);
        QVERIFY(top.value("errors").toArray().first().toString().startsWith("id 7: "));
        const QJsonObject all = top.value("result").toObject();
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

    void dumpIntoAFolderWritesOneFilePerDevice()
    {
        QTemporaryDir dir;
        const ProgramRun r = ctl({"--sim", "--id", "1-3", "--name", "Mill", "dump", dir.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString day = QDate::currentDate().toString(Qt::ISODate);
        QStringList files = QDir(dir.path()).entryList(QDir::Files, QDir::Name);
        QCOMPARE(files, (QStringList{QStringLiteral("id1 Mill %1.json").arg(day),
                                     QStringLiteral("id2 Mill %1.json").arg(day),
                                     QStringLiteral("id3 Mill %1.json").arg(day)}));
        // Each file is that device's: its id is in it.
        const ProfileParseResult p =
            ProfileFile::load(dir.filePath(files.at(1)), RegisterMap::builtin());
        QVERIFY(p.ok());
        QCOMPARE(p.profile->deviceId, 2);
        QCOMPARE(p.profile->values.value(QStringLiteral("device.id")), 2);
        // A folder that is not there: nothing is saved anywhere.
        const ProgramRun missing =
            ctl({"--sim", "--id", "1,2", "dump", dir.filePath(QStringLiteral("nope/"))});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY2(missing.err.contains(QStringLiteral("no such folder")), qPrintable(missing.err));
    }

    void aFolderDumpSavesEveryDeviceThatAnswers()
    {
        SimHost host;
        QVERIFY(start(host, true, {1, 2}));
        QTemporaryDir dir;
        const ProgramRun r =
            ctl(tcp(host) + QStringList{"--id", "1,7,2", "dump", dir.path() + "/"});
        QCOMPARE(r.exitCode, 1); // the worst: id 7 does not answer
        QVERIFY2(r.err.contains(QStringLiteral("id 7: ")), qPrintable(r.err));
        const QString day = QDate::currentDate().toString(Qt::ISODate);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files, QDir::Name),
                 (QStringList{QStringLiteral("id1 %1.json").arg(day),
                              QStringLiteral("id2 %1.json").arg(day)}));
    }

    void applyWritesOnlyTheIdsNamed()
    {
        SimHost host;
        QVERIFY(start(host, true, {1, 2, 3}));
        const qint64 speed = host.deviceAt(1)->value(QStringLiteral("motor1.speed")).value_or(0);
        QTemporaryDir dir;
        QVERIFY(
            ctl(tcp(host) + QStringList{"--id", "1", "dump", dir.filePath("one.json")}).exitCode ==
            0);
        // The profile: device 1's settings with a faster motor 1.
        Profile profile =
            *ProfileFile::load(dir.filePath("one.json"), RegisterMap::builtin()).profile;
        profile.values[QStringLiteral("motor1.speed")] = speed + 11;
        QVERIFY(ProfileFile::save(dir.filePath("fast.json"), profile, RegisterMap::builtin())
                    .isEmpty());
        const ProgramRun r = ctl(tcp(host) + QStringList{"--id", "2,3", "--yes", "--no-backup",
                                                         "apply", dir.filePath("fast.json")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("== device id 3 ==")), qPrintable(r.out));
        QCOMPARE(host.deviceAt(1)->value(QStringLiteral("motor1.speed")).value_or(0), speed);
        QCOMPARE(host.deviceAt(2)->value(QStringLiteral("motor1.speed")).value_or(0), speed + 11);
        QCOMPARE(host.deviceAt(3)->value(QStringLiteral("motor1.speed")).value_or(0), speed + 11);
        // Asked on standard input: each id's question comes after what it is about.
        profile.values[QStringLiteral("motor1.speed")] = speed + 22;
        QVERIFY(ProfileFile::save(dir.filePath("faster.json"), profile, RegisterMap::builtin())
                    .isEmpty());
        ProgramOptions answers;
        answers.input = QByteArray("y\nn\n");
        const ProgramRun asked =
            runProgram(QStringLiteral("stepcomctl"),
                       tcp(host) + QStringList{"--id", "1,2", "--no-backup", "apply",
                                               dir.filePath("faster.json")},
                       answers);
        QCOMPARE(asked.exitCode, 2); // the worst: id 2 was not confirmed
        const qsizetype question = asked.out.indexOf(QStringLiteral("to id 1? [y/N]"));
        QVERIFY2(question > asked.out.indexOf(QStringLiteral("will write motor1.speed")),
                 qPrintable(asked.out));
        QVERIFY2(asked.out.contains(QStringLiteral("to id 2? [y/N]")), qPrintable(asked.out));
        QCOMPARE(host.deviceAt(1)->value(QStringLiteral("motor1.speed")).value_or(0), speed + 22);
        QCOMPARE(host.deviceAt(2)->value(QStringLiteral("motor1.speed")).value_or(0), speed + 11);
    }

    void reportCoversEveryDevice()
    {
        QTemporaryDir dir;
        const QString html = dir.filePath(QStringLiteral("machine.html"));
        const ProgramRun r = ctl({"--sim", "--id", "1-3", "--name", "Mill 7", "report", html});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile f(html);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY(text.contains(QStringLiteral("3 controllers")));
        QVERIFY(text.contains(QStringLiteral("Mill 7")));
        for (int id : {1, 2, 3})
            QVERIFY2(text.contains(QStringLiteral(">Controller id %1</h1>").arg(id)),
                     qPrintable(QString::number(id)));
        QCOMPARE(text.count(QStringLiteral("data:image/png;base64,")), 3);
        // A PDF too.
        const QString pdf = dir.filePath(QStringLiteral("machine.pdf"));
        QCOMPARE(ctl({"--sim", "--id", "1,2", "report", pdf}).exitCode, 0);
        QVERIFY(QFileInfo(pdf).size() > 1000);
    }

    void reportRefusesALineWithADeviceMissing()
    {
        SimHost host;
        QVERIFY(start(host, true, {1, 2}));
        QTemporaryDir dir;
        const QString html = dir.filePath(QStringLiteral("machine.html"));
        const ProgramRun r = ctl(tcp(host) + QStringList{"--id", "1,7,2", "report", html});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("id 7: ")), qPrintable(r.err));
        QVERIFY(!QFileInfo::exists(html));
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

#include "testregistry.h"
STEPCOM_TEST(TestCtlBus, Guiless)
#include "tst_ctlbus.moc"
