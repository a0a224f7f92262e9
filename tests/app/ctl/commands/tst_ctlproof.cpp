#include "programrun.h"
#include "proofsim.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "testpaths.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <functional>
#include <signal.h>

using namespace stepcom;
using namespace stepcom::test;

// stepcomctl lost-steps, margin and backlash against the stalling simulator over TCP: their
// JSON and exit codes, the question before they move, a gauge answered from the simulator's
// truth, bad answers and the end of input, --apply through the write review, Ctrl-C.
class TestCtlProof : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    QTemporaryDir dir;

    SimDevice *sim() const { return host->device(); }
    qint64 held(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }
    double carriage() const { return sim()->truth().axes.at(0).carriageMm; }
    void boot(const AxisPhysics &physics)
    {
        host = std::make_unique<SimHost>();
        QVERIFY(startProofSim(*host, physics));
    }
    QStringList link() const
    {
        return {QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(host->tcpPort())};
    }
    ProgramRun ctl(const QStringList &args, const QByteArray &input = {})
    {
        ProgramOptions options;
        options.environment = {QStringLiteral("XDG_DATA_HOME=") +
                               dir.filePath(QStringLiteral("data"))};
        options.input = input;
        options.timeoutMs = 120000;
        return runProgram(QStringLiteral("stepcomctl"), link() + args, options);
    }
    static QJsonObject result(const ProgramRun &r)
    {
        return QJsonDocument::fromJson(r.out.toUtf8())
            .object()
            .value(QStringLiteral("result"))
            .toObject();
    }
    // Runs stepcomctl, calling `act` with its standard error so far until it ends.
    ProgramRun ctlWhile(const QStringList &args,
                        const std::function<void(const QString &err, QProcess &p)> &act)
    {
        return runProgramWhile(QStringLiteral("stepcomctl"), link() + args, act, 120000);
    }
    static const QStringList &quick()
    {
        static const QStringList args{QStringLiteral("--cycles"), QStringLiteral("1"),
                                      QStringLiteral("--distance"), QStringLiteral("5")};
        return args;
    }

private Q_SLOTS:
    void cleanup() { host.reset(); }

    void lostStepsKept()
    {
        boot(proofAxis());
        const ProgramRun r = ctl(QStringList{QStringLiteral("lost-steps"), QStringLiteral("motor1"),
                                             QStringLiteral("--yes"), QStringLiteral("--json")} +
                                 quick());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("kept"));
        QCOMPARE(o.value(QStringLiteral("cycles")).toInt(), 1);
        QCOMPARE(o.value(QStringLiteral("speed_rpm")).toInt(), 300);
        QVERIFY(o.value(QStringLiteral("restored")).toBool());
        QVERIFY(std::abs(o.value(QStringLiteral("lost_mm")).toDouble()) <= 0.02);
        QVERIFY(r.err.contains(QLatin1String("\"event\":\"progress\"")));
        QCOMPARE(held("motor1.speed"), 300);
    }

    void lostStepsLost()
    {
        AxisPhysics p = proofAxis();
        p.pullOutRpm = 200;
        p.pullInRpm = 100;
        boot(p);
        const ProgramRun r = ctl(QStringList{QStringLiteral("lost-steps"), QStringLiteral("motor1"),
                                             QStringLiteral("--yes"), QStringLiteral("--json")} +
                                 quick());
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("lost"));
        const double lost = o.value(QStringLiteral("lost_out_mm")).toDouble() +
                            o.value(QStringLiteral("lost_back_mm")).toDouble();
        QVERIFY2(std::abs(lost - sim()->truth().axes.at(0).lostMm) <= 0.03, qPrintable(r.out));
        QVERIFY(o.value(QStringLiteral("restored")).toBool());
        QCOMPARE(held("motor1.speed"), 300);
    }

    void lostStepsAsksFirst()
    {
        boot(proofAxis());
        const double before = carriage();
        const ProgramRun r = ctl({QStringLiteral("lost-steps"), QStringLiteral("motor1")}, "n\n");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.out.contains(QLatin1String("home switch on IN2")), qPrintable(r.out));
        QVERIFY(r.out.contains(QLatin1String("[y/N]")));
        QVERIFY(r.err.contains(QLatin1String("not confirmed")));
        QCOMPARE(carriage(), before);
    }

    void lostStepsRefused_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<qint64>("value");
        QTest::addColumn<QString>("said");
        QTest::newRow("no home input") << "motor1.home_input" << 0LL << "home input";
    }
    void lostStepsRefused()
    {
        QFETCH(QString, key);
        QFETCH(qint64, value);
        QFETCH(QString, said);
        boot(proofAxis());
        QVERIFY(sim()->setValue(key, value));
        const double before = carriage();
        const ProgramRun r = ctl({QStringLiteral("lost-steps"), QStringLiteral("motor1"),
                                  QStringLiteral("--yes"), QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(result(r).value(QStringLiteral("outcome")).toString(), QStringLiteral("refused"));
        QVERIFY2(r.err.contains(said), qPrintable(r.err));
        QCOMPARE(carriage(), before);
    }

    void usage_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("said");
        QTest::newRow("no motor") << QStringList{"lost-steps"} << "motorN";
        QTest::newRow("motor 3") << QStringList{"margin", "motor3"} << "motorN";
        QTest::newRow("bad distance")
            << QStringList{"backlash", "motor1", "--distance", "-1"} << "--distance";
        QTest::newRow("bad step") << QStringList{"margin", "motor1", "--step", "x"} << "--step";
    }
    void usage()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, said);
        boot(proofAxis());
        const ProgramRun r = ctl(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(said), qPrintable(r.err));
    }

    void marginFindsTheStallAndApplies()
    {
        AxisPhysics p = proofAxis();
        p.pullOutRpm = 250;
        p.pullInRpm = 100;
        boot(p);
        const ProgramRun r =
            ctl(QStringList{QStringLiteral("margin"), QStringLiteral("motor1"),
                            QStringLiteral("--from"), QStringLiteral("200"), QStringLiteral("--to"),
                            QStringLiteral("300"), QStringLiteral("--step"), QStringLiteral("100"),
                            QStringLiteral("--apply"), QStringLiteral("--yes"),
                            QStringLiteral("--json")} +
                quick());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("kept_rpm")).toInt(), 200);
        QCOMPARE(o.value(QStringLiteral("stall_rpm")).toInt(), 300);
        QCOMPARE(o.value(QStringLiteral("recommended_rpm")).toInt(), 150);
        QCOMPARE(o.value(QStringLiteral("steps")).toArray().size(), 2);
        QCOMPARE(
            o.value(QStringLiteral("written")).toObject().value(QStringLiteral("motor1.speed")),
            QJsonValue(150));
        QCOMPARE(held("motor1.speed"), 150);
    }

    void backlashFromTheGauge()
    {
        AxisPhysics p = proofAxis();
        p.startMm = 20;
        p.backlashMm = 0.1;
        boot(p);
        int answered = 0;
        const ProgramRun r =
            ctlWhile({QStringLiteral("backlash"), QStringLiteral("motor1"),
                      QStringLiteral("--cycles"), QStringLiteral("2"), QStringLiteral("--json")},
                     [this, &answered](const QString &err, QProcess &proc) {
                         if (err.count(QLatin1String("[y/N]")) == 1 && answered == 0) {
                             proc.write("y\n");
                             answered = 1;
                         }
                         // Each question answered once (`answered` counts the confirmation too),
                         // with where the carriage really is.
                         if (answered > 0 && err.count(QLatin1String("gauge (mm)?")) == answered) {
                             proc.write(QByteArray::number(carriage(), 'f', 4) + '\n');
                             ++answered;
                         }
                     });
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("readings")).toArray().size(), 5);
        QVERIFY2(std::abs(o.value(QStringLiteral("backlash_mm")).toDouble() - 0.1) <= 0.02,
                 qPrintable(r.out));
        QVERIFY(o.value(QStringLiteral("approach_from_one_side")).toBool());
        QCOMPARE(held("motor1.speed"), 300);
    }

    void backlashAsksAgainThenStopsAtTheEnd()
    {
        AxisPhysics p = proofAxis();
        p.startMm = 20;
        boot(p);
        const ProgramRun r =
            ctl({QStringLiteral("backlash"), QStringLiteral("motor1"), QStringLiteral("--json")},
                "y\nabc\n0.000\n");
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("'abc' is not a number")), qPrintable(r.err));
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("outcome")).toString(), QStringLiteral("stopped"));
        QCOMPARE(o.value(QStringLiteral("readings")).toArray().size(), 1);
        QVERIFY(o.value(QStringLiteral("restored")).toBool());
        QCOMPARE(held("motor1.speed"), 300);
    }

    void runChecksTheStepsAfterTheCycles()
    {
        AxisPhysics p = proofAxis();
        p.pullOutRpm = 200;
        p.pullInRpm = 100;
        boot(p);
        QFile f(dir.filePath(QStringLiteral("cycle.stepseq")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "stepcom-sequence", "version": 1,
                  "steps": [{"move_by": {"motor1": 2}}, {"move_by": {"motor1": -1}}]})");
        f.close();
        const ProgramRun r =
            ctl({QStringLiteral("run"), f.fileName(), QStringLiteral("--check-steps"),
                 QStringLiteral("--yes"), QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1); // the cycle ran, the axis lost steps at its speed
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("outcome")).toString(), QStringLiteral("done"));
        QCOMPARE(o.value(QStringLiteral("check_steps_verdict")).toString(), QStringLiteral("lost"));
        const QJsonArray checks = o.value(QStringLiteral("check_steps")).toArray();
        QCOMPARE(checks.size(), 1);
        QCOMPARE(checks.first().toObject().value(QStringLiteral("motor")).toInt(), 1);
        QVERIFY(checks.first().toObject().value(QStringLiteral("restored")).toBool());
        QVERIFY2(r.out.contains(QLatin1String("lost-step test")) ||
                     r.err.contains(QLatin1String("check_steps")),
                 qPrintable(r.err));
        QCOMPARE(held("motor1.speed"), 300);
    }

    void runCheckKeepsToTheFilesLimits()
    {
        boot(proofAxis());
        QFile f(dir.filePath(QStringLiteral("narrow.stepseq")));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "stepcom-sequence", "version": 1,
                  "limits": {"motor1": {"min": -5, "max": 5}},
                  "steps": [{"move_by": {"motor1": 2}}, {"move_by": {"motor1": -1}}]})");
        f.close();
        const ProgramRun r =
            ctl({QStringLiteral("run"), f.fileName(), QStringLiteral("--check-steps"),
                 QStringLiteral("--yes"), QStringLiteral("--json")});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = result(r);
        QCOMPARE(o.value(QStringLiteral("outcome")).toString(), QStringLiteral("done"));
        QCOMPARE(o.value(QStringLiteral("check_steps_verdict")).toString(),
                 QStringLiteral("unknown"));
        const QJsonObject check =
            o.value(QStringLiteral("check_steps")).toArray().first().toObject();
        QCOMPARE(check.value(QStringLiteral("outcome")).toString(), QStringLiteral("refused"));
        QVERIFY2(check.value(QStringLiteral("message")).toString().contains(QLatin1String("5.00")),
                 qPrintable(r.out));
    }

    void ctrlCStopsAndRestores()
    {
        boot(proofAxis());
        bool sent = false;
        const ProgramRun r =
            ctlWhile(QStringList{QStringLiteral("lost-steps"), QStringLiteral("motor1"),
                                 QStringLiteral("--yes")} +
                         quick(),
                     [&sent](const QString &err, QProcess &proc) {
                         if (!sent && err.contains(QLatin1String("cycle"))) {
                             sent = true;
                             ::kill(pid_t(proc.processId()), SIGINT);
                         }
                     });
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("Stopped")), qPrintable(r.err));
        QCOMPARE(held("motor1.speed"), 300);
        QVERIFY(!sim()->running(1));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlProof, Guiless)
#include "tst_ctlproof.moc"
