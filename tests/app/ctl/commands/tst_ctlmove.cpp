#include "map/registermap.h"
#include "profile/backupstore.h"
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

// stepcomctl move (by and to) against the simulator over TCP: where the axis ends, the frames
// that went out, the user's single-move registers restored; and the backups before
// save_to_flash, factory_reset and an id change.
class TestCtlMove : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    QTemporaryDir dir;

    SimDevice *sim() const { return host->device(); }
    ProgramRun ctl(const QStringList &args)
    {
        ProgramOptions options;
        options.environment = {QStringLiteral("XDG_DATA_HOME=") +
                               dir.filePath(QStringLiteral("data"))};
        const QStringList link{QStringLiteral("--tcp"),
                               QStringLiteral("127.0.0.1:%1").arg(host->tcpPort())};
        return runProgram(QStringLiteral("stepcomctl"), link + args, options);
    }
    QString backups() const
    {
        return dir.filePath(QStringLiteral("data")) + QStringLiteral("/StepCom/stepcom/backups");
    }
    void userValuesBack()
    {
        QCOMPARE(sim()->value(QStringLiteral("motor1.move_distance")).value_or(-1), 1234);
        QCOMPARE(sim()->value(QStringLiteral("motor1.direction")).value_or(-1), 1);
    }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        SimOptions options;
        options.tcp = true;
        QString error;
        QVERIFY2(host->start(options, &error), qPrintable(error));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.move_distance"), 1234));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.direction"), 1));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 600));
        QDir(backups()).removeRecursively();
    }
    void cleanup() { host.reset(); }

    void moveByEndsThereAndRestores()
    {
        const qint64 from = sim()->position(1);
        const ProgramRun r =
            ctl({QStringLiteral("--verbose"), QStringLiteral("move"), QStringLiteral("motor1"),
                 QStringLiteral("--by"), QStringLiteral("2.5")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QCOMPARE(sim()->position(1), from + 250);
        userValuesBack();
        // The frames: the step's distance (250) and direction (0), the move coil, the user's
        // distance (1234) and direction (1) back.
        QVERIFY2(r.err.contains(QStringLiteral("(motor1.move_distance) = 250, 0")),
                 qPrintable(r.err));
        QVERIFY(r.err.contains(QStringLiteral("write coil 00001 (motor1.move) ON")));
        QVERIFY(r.err.contains(QStringLiteral("(motor1.move_distance) = 1234, 0")));
        QVERIFY(r.err.contains(QStringLiteral("(motor1.direction) = 0")));
        QVERIFY(r.err.contains(QStringLiteral("(motor1.direction) = 1")));
        QVERIFY2(r.out.contains(QStringLiteral("done at 2.50 mm")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("back (verified)")));
    }

    void moveToEndsThereAndRestores()
    {
        const ProgramRun r =
            ctl({QStringLiteral("--json"), QStringLiteral("move"), QStringLiteral("motor1"),
                 QStringLiteral("--to"), QStringLiteral("-3.25")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QCOMPARE(sim()->position(1), -325);
        userValuesBack();
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8())
                                  .object()
                                  .value(QStringLiteral("result"))
                                  .toObject();
        QCOMPARE(o.value(QStringLiteral("outcome")).toString(), QStringLiteral("done"));
        QCOMPARE(o.value(QStringLiteral("position")).toDouble(), -3.25);
        QVERIFY(o.value(QStringLiteral("arrived")).toBool());
        QVERIFY(o.value(QStringLiteral("restored")).toBool());
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no motor") << QStringList{"move", "--by", "1"} << "move needs one motor";
        QTest::newRow("motor 3") << QStringList{"move", "motor3", "--by", "1"}
                                 << "there is no motor 3";
        QTest::newRow("both") << QStringList{"move", "motor1", "--by", "1", "--to", "2"}
                              << "exactly one of --by D and --to X";
        QTest::newRow("neither") << QStringList{"move", "motor1"}
                                 << "exactly one of --by D and --to X";
        // As write: a third decimal is refused, not rounded or taken for nothing to move.
        QTest::newRow("three decimals")
            << QStringList{"move", "motor1", "--by", "0.015"} << "--by: 0.015 has more decimals";
        QTest::newRow("too small")
            << QStringList{"move", "motor1", "--by", "0.001"} << "--by: 0.001 has more decimals";
        QTest::newRow("to, three decimals")
            << QStringList{"move", "motor1", "--to", "1.234"} << "--to: 1.234 has more decimals";
        QTest::newRow("not a number")
            << QStringList{"move", "motor1", "--by", "ten"} << "--by: 'ten' is not a number";
    }
    void usageErrors()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const ProgramRun r = ctl(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(sim()->position(1), 0);
    }

    void stoppedMoveExitsOne()
    {
        // A limit input ON in the move's direction: the controller refuses to run; not arrived.
        QVERIFY(sim()->setValue(QStringLiteral("motor1.limit_positive"), 1));
        sim()->setInput(1, SimDevice::InputForce::On);
        const ProgramRun r = ctl({QStringLiteral("move"), QStringLiteral("motor1"),
                                  QStringLiteral("--by"), QStringLiteral("5")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(!r.err.isEmpty(), qPrintable(r.out));
        userValuesBack();
    }

    void moveAndWaitNameTheSameLimit()
    {
        // The simulated controller over its pseudo-terminal (as stepcom-sim serves it), motor 1
        // on its positive limit: a step forward and the single move with --wait are one motion,
        // judged alike -- the limit named, before and after.
        SimHost pty;
        SimOptions options;
        options.rtu = true;
        QString error;
        QVERIFY2(pty.start(options, &error), qPrintable(error));
        SimDevice *d = pty.device();
        QVERIFY(d->setValue(QStringLiteral("motor1.limit_positive"), 1));
        QVERIFY(d->setValue(QStringLiteral("motor1.direction"), 0));
        d->setInput(1, SimDevice::InputForce::On);
        ProgramOptions env;
        env.environment = {QStringLiteral("XDG_DATA_HOME=") + dir.filePath(QStringLiteral("data"))};
        const QStringList link{QStringLiteral("--port"), pty.rtuPath()};
        const QString limit = QStringLiteral("positive limit (IN1)");
        const ProgramRun move = runProgram(QStringLiteral("stepcomctl"),
                                           link + QStringList{"move", "motor1", "--by", "10"}, env);
        QCOMPARE(move.exitCode, 1);
        QVERIFY2(move.err.contains(QStringLiteral("Motor 1's ") + limit + " is already ON"),
                 qPrintable(move.err));
        QVERIFY2(move.err.contains(QStringLiteral("(motor 1's ") + limit + " is ON)"),
                 qPrintable(move.err));
        QVERIFY(!move.err.contains(QStringLiteral("no stop, limit or E-STOP seen")));
        const ProgramRun wait =
            runProgram(QStringLiteral("stepcomctl"),
                       link + QStringList{"command", "motor1.move", "--wait"}, env);
        QCOMPARE(wait.exitCode, 1);
        QVERIFY2(wait.err.contains(QStringLiteral("(motor 1's ") + limit + " is ON)"),
                 qPrintable(wait.err));
        // --json: the same cause word from both.
        const ProgramRun json =
            runProgram(QStringLiteral("stepcomctl"),
                       link + QStringList{"--json", "move", "motor1", "--by", "10"}, env);
        QCOMPARE(json.exitCode, 1);
        const QJsonObject o = QJsonDocument::fromJson(json.out.toUtf8())
                                  .object()
                                  .value(QStringLiteral("result"))
                                  .toObject();
        QCOMPARE(o.value(QStringLiteral("cause")).toString(), QStringLiteral("limit"));
        QVERIFY(o.value(QStringLiteral("warning")).toString().contains(limit));
    }

    void backupsBeforeRiskyCommands()
    {
        ProgramRun r = ctl({QStringLiteral("command"), QStringLiteral("save_to_flash")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("backup of the controller's settings: ")));
        r = ctl(
            {QStringLiteral("command"), QStringLiteral("factory_reset"), QStringLiteral("--yes")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = ctl({QStringLiteral("write"), QStringLiteral("device.id=1")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = ctl({QStringLiteral("--no-backup"), QStringLiteral("command"),
                 QStringLiteral("save_to_flash")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(!r.out.contains(QStringLiteral("backup")));
        r = ctl({QStringLiteral("write"), QStringLiteral("motor1.speed=300")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QList<BackupEntry> list = BackupStore(backups()).list(RegisterMap::builtin());
        QStringList ops;
        for (const BackupEntry &e : list)
            ops.prepend(e.operation);
        QCOMPARE(ops, (QStringList{QStringLiteral("save-to-flash"), QStringLiteral("factory-reset"),
                                   QStringLiteral("device-id")}));
        // The backup holds what the controller held before the reset.
        const auto b = BackupStore::load(list.last().path, RegisterMap::builtin());
        QVERIFY(b.ok());
        QCOMPARE(b.profile->values.value(QStringLiteral("motor1.move_distance")), 1234);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlMove, Guiless)
#include "tst_ctlmove.moc"
