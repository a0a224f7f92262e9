// stepcomctl write asks what the window's write dialog asks (WriteReview, one review in the
// core): a home input on the positive limit, a change of the system mode, an arc whose start is
// its centre. Over the simulated controller's pseudo-terminal: without --yes the questions are
// printed, the exit code is 2 and no write frame goes out; with --yes it is written.
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestCtlReview : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    QTemporaryDir dir;

    SimDevice *sim() const { return host->device(); }
    ProgramRun ctl(const QStringList &args)
    {
        ProgramOptions options;
        options.environment = {QStringLiteral("XDG_DATA_HOME=") + dir.path()};
        return runProgram(
            QStringLiteral("stepcomctl"),
            QStringList{QStringLiteral("--port"), host->rtuPath(), QStringLiteral("--verbose")} +
                args,
            options);
    }
    // The write frames (FC05, FC06, FC10) that went out, from the traffic on standard error.
    static int writeFrames(const ProgramRun &r)
    {
        static const QRegularExpression sent(QStringLiteral("  TX  .*  write "));
        int n = 0;
        for (const QString &line : r.err.split(QLatin1Char('\n')))
            n += sent.match(line).hasMatch() ? 1 : 0;
        return n;
    }
    qint64 held(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        SimOptions options;
        options.rtu = true;
        QString error;
        QVERIFY2(host->start(options, &error), qPrintable(error));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.limit_positive"), 1));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.limit_negative"), 2));
        QVERIFY(sim()->setValue(QStringLiteral("motor1.home_input"), 2));
        QVERIFY(sim()->setValue(QStringLiteral("mode.system"), 0));
    }
    void cleanup() { host.reset(); }

    void homeInputOnThePositiveLimitIsAsked()
    {
        ProgramRun r = ctl({QStringLiteral("write"), QStringLiteral("motor1.home_input=1")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("the home input IN1 is the positive limit")),
                 qPrintable(r.err));
        QVERIFY(r.err.contains(QStringLiteral("--yes")));
        QCOMPARE(writeFrames(r), 0);
        QCOMPARE(held("motor1.home_input"), 2);
        r = ctl({QStringLiteral("--yes"), QStringLiteral("write"),
                 QStringLiteral("motor1.home_input=1")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(writeFrames(r), 1);
        QCOMPARE(held("motor1.home_input"), 1);
    }

    void aChangeOfSystemModeIsAsked()
    {
        ProgramRun r = ctl({QStringLiteral("write"), QStringLiteral("mode.system=4")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("ignores the limit settings")), qPrintable(r.err));
        QCOMPARE(writeFrames(r), 0);
        QCOMPARE(held("mode.system"), 0);
        r = ctl(
            {QStringLiteral("--yes"), QStringLiteral("write"), QStringLiteral("mode.system=4")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(held("mode.system"), 4);
    }

    void anArcStartingAtItsCentreIsAsked()
    {
        QVERIFY(sim()->setValue(QStringLiteral("arc.mode"), 0));
        QVERIFY(sim()->setValue(QStringLiteral("arc.center_x"), 1000));
        QVERIFY(sim()->setValue(QStringLiteral("arc.center_y"), 0));
        QVERIFY(sim()->setValue(QStringLiteral("arc.end_x"), 2000));
        QVERIFY(sim()->setValue(QStringLiteral("arc.end_y"), 0));
        const qint64 before = held("arc.start_x");
        QVERIFY(before != 1000);
        const ProgramRun r = ctl({QStringLiteral("write"), QStringLiteral("arc.start_x=10"),
                                  QStringLiteral("arc.start_y=0")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("Arc: ")), qPrintable(r.err));
        QCOMPARE(writeFrames(r), 0);
        QCOMPARE(held("arc.start_x"), before);
    }

    void applySaysTheQuestionsBeforeAsking()
    {
        const QString path = dir.filePath(QStringLiteral("machine.json"));
        ProgramRun r = ctl({QStringLiteral("dump"), path});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject profile = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QJsonObject values = profile.value(QStringLiteral("values")).toObject();
        values.insert(QStringLiteral("motor1.home_input"), 1);
        profile.insert(QStringLiteral("values"), values);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QJsonDocument(profile).toJson());
        f.close();
        r = ctl({QStringLiteral("apply"), path});
        QCOMPARE(r.exitCode, 2);
        const qsizetype check = r.out.indexOf(QStringLiteral("check: Motor 1: the home input IN1"));
        QVERIFY2(check >= 0, qPrintable(r.out));
        QVERIFY(check < r.out.indexOf(QStringLiteral("[y/N]")));
        QCOMPARE(writeFrames(r), 0);
        QCOMPARE(held("motor1.home_input"), 2);
    }

    void anUnquestionedWriteGoesOut()
    {
        const ProgramRun r = ctl({QStringLiteral("write"), QStringLiteral("motor1.home_input=2"),
                                  QStringLiteral("motor1.speed=250")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(!r.err.contains(QStringLiteral("check:")));
        QCOMPARE(held("motor1.speed"), 250);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlReview, Guiless)
#include "tst_ctlreview.moc"
