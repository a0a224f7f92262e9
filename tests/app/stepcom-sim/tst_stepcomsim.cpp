#include "testpaths.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace stepcom;

// The stepcom-sim program, checked by independent clients: mbpoll (libmodbus) over the pty and
// TCP, and its own console and options.
class TstStepcomSim : public QObject
{
    Q_OBJECT

private:
    QString m_mbpoll;

    // Starts stepcom-sim and waits for its "pty:"/"tcp:" lines.
    static std::unique_ptr<QProcess> startSim(const QStringList &args, QString *banner)
    {
        auto p = std::make_unique<QProcess>();
        p->setProgram(test::programPath(QStringLiteral("stepcom-sim")));
        p->setArguments(args);
        p->start();
        if (!p->waitForStarted(5000))
            return nullptr;
        // The banner names what the arguments asked for, a line each, the tcp port last.
        const QByteArray last = args.contains(QStringLiteral("--tcp"))    ? "tcp: "
                                : args.contains(QStringLiteral("--link")) ? "link: "
                                                                          : "pty: ";
        QByteArray out;
        const bool told = QTest::qWaitFor(
            [&] {
                out += p->readAllStandardOutput();
                const qsizetype at = out.indexOf(last);
                return at >= 0 && out.indexOf('\n', at) > at;
            },
            10000);
        if (!told)
            return nullptr;
        if (banner)
            *banner = QString::fromUtf8(out);
        return p;
    }
    static void endSim(QProcess *p)
    {
        p->terminate(); // SIGTERM: must end cleanly
        QVERIFY(p->waitForFinished(5000));
        QCOMPARE(p->exitStatus(), QProcess::NormalExit);
        QCOMPARE(p->exitCode(), 0);
    }
    QString mbpoll(const QStringList &args)
    {
        QProcess p;
        p.start(m_mbpoll, args);
        p.waitForFinished(10000);
        return QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
    }
    // mbpoll [options] DEVICE [values to write]
    QStringList rtu(const QString &path, const QStringList &more, const QStringList &values = {})
    {
        return QStringList{QStringLiteral("-m"),   QStringLiteral("rtu"), QStringLiteral("-b"),
                           QStringLiteral("9600"), QStringLiteral("-P"),  QStringLiteral("none"),
                           QStringLiteral("-1")} +
               more + QStringList{path} + values;
    }
    static QStringList split(const char *args)
    {
        return QString::fromLatin1(args).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    }

private Q_SLOTS:
    void initTestCase()
    {
        m_mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
        QVERIFY(QFileInfo::exists(test::programPath(QStringLiteral("stepcom-sim"))));
    }

    void version()
    {
        QProcess p;
        p.start(test::programPath(QStringLiteral("stepcom-sim")), {QStringLiteral("--version")});
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(QString::fromUtf8(p.readAllStandardOutput()).trimmed(),
                 QStringLiteral("stepcom-sim " STEPCOM_VERSION));
    }

    void badOptionsAreRefused()
    {
        QProcess p;
        p.start(test::programPath(QStringLiteral("stepcom-sim")),
                {QStringLiteral("--drop"), QStringLiteral("2")});
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().contains("--drop"));
    }

    void badMachineFileIsRefused()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("machine.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "stepcom-sim-machine", "version": 1,
                    "axes": {"motor1": {"backlash_mm": -1}}})");
        f.close();
        QProcess p;
        p.start(test::programPath(QStringLiteral("stepcom-sim")),
                {QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--machine"), path});
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitCode(), 2);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains(path + QStringLiteral(": axes.motor1.backlash_mm: ")),
                 qPrintable(err));
    }

    // --truth-out: what really happened, for a test in another process.
    void truthOutShowsAStall()
    {
        QTemporaryDir dir;
        const QString machine = dir.filePath(QStringLiteral("machine.json"));
        const QString truth = dir.filePath(QStringLiteral("truth.json"));
        QFile f(machine);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "stepcom-sim-machine", "version": 1, "axes": {"motor1":
                    {"pull_out_rpm": 100, "pull_in_rpm": 30, "start_mm": 30}}})");
        f.close();
        auto read = [&truth] {
            QFile file(truth);
            if (!file.open(QIODevice::ReadOnly))
                return QJsonObject();
            const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
            return root.value(QStringLiteral("axes")).toArray().at(0).toObject();
        };
        auto sim =
            startSim({QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--console"),
                      QStringLiteral("--machine"), machine, QStringLiteral("--truth-out"), truth},
                     nullptr);
        QVERIFY(sim);
        QTRY_COMPARE(read().value(QStringLiteral("carriage_mm")).toDouble(), 30.0);
        QCOMPARE(read().value(QStringLiteral("stalled")).toBool(), false);
        sim->write("set motor1.speed 300\ndo motor1.forward\n");
        QTRY_VERIFY_WITH_TIMEOUT(read().value(QStringLiteral("stalled")).toBool(), 10000);
        sim->write("do motor1.stop\nquit\n");
        QVERIFY(sim->waitForFinished(5000));
        QCOMPARE(sim->exitCode(), 0);
        const QJsonObject last = read(); // written at exit
        QCOMPARE(last.value(QStringLiteral("stalled")).toBool(), false);
        const qint64 lost = qint64(last.value(QStringLiteral("lost_pulses")).toDouble());
        QVERIFY(lost > 0);
        QCOMPARE(lost % 32, 0);
        QVERIFY(std::abs(last.value(QStringLiteral("lost_mm")).toDouble() + double(lost) / 320.0) <
                1e-9);
    }

    void mbpollOverThePty()
    {
        if (m_mbpoll.isEmpty())
            QSKIP("mbpoll is not installed (Debian package mbpoll)");
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("stepcom0"));
        QString banner;
        auto sim = startSim({QStringLiteral("--pty"), QStringLiteral("--link"), link}, &banner);
        QVERIFY(sim);
        QVERIFY2(banner.contains(QStringLiteral("link: ") + link), qPrintable(banner));
        QVERIFY(QFileInfo(link).isSymLink());

        QString out = mbpoll(rtu(link, split("-a 1 -r 1 -c 2")));
        QVERIFY2(out.contains(QStringLiteral("[1]: \t180")) &&
                     out.contains(QStringLiteral("[2]: \t8")),
                 qPrintable(out));
        out = mbpoll(rtu(link, split("-a 1 -t 3 -r 1 -c 2")));
        QVERIFY2(out.contains(QStringLiteral("Illegal function")), qPrintable(out));
        out = mbpoll(rtu(link, split("-a 1 -r 1 -c 50")));
        QVERIFY2(out.contains(QStringLiteral("Illegal data value")), qPrintable(out));
        out = mbpoll(rtu(link, split("-a 2 -o 0.3 -r 1 -c 2")));
        QVERIFY2(out.contains(QStringLiteral("timed out"), Qt::CaseInsensitive), qPrintable(out));

        // A reverse single move of 10 mm: the 32-bit position reads -10.00 (low word first).
        out = mbpoll(
            rtu(link, split("-a 1 -r 5"), {QStringLiteral("1")})); // 40005 direction = reverse
        QVERIFY2(out.contains(QStringLiteral("Written 1 references")), qPrintable(out));
        out = mbpoll(rtu(link, split("-a 1 -t 0 -r 1"),
                         {QStringLiteral("1")})); // coil 00001: motor 1 single move
        QVERIFY2(out.contains(QStringLiteral("Written 1 references")), qPrintable(out));
        const bool arrived = QTest::qWaitFor(
            [&] {
                out = mbpoll(rtu(link, split("-a 1 -t 4:int -r 108 -c 1")));
                return out.contains(QStringLiteral("[108]: \t-1000"));
            },
            20000);
        QVERIFY2(arrived, qPrintable(out));
        endSim(sim.get());
        QVERIFY(!QFileInfo::exists(link)); // removed on a clean exit
    }

    void mbpollOverTcp()
    {
        if (m_mbpoll.isEmpty())
            QSKIP("mbpoll is not installed (Debian package mbpoll)");
        QString banner;
        auto sim = startSim({QStringLiteral("--tcp"), QStringLiteral("0")}, &banner);
        QVERIFY(sim);
        const auto m =
            QRegularExpression(QStringLiteral("tcp: 127\\.0\\.0\\.1:(\\d+)")).match(banner);
        QVERIFY2(m.hasMatch(), qPrintable(banner));
        const QString out =
            mbpoll({QStringLiteral("-m"), QStringLiteral("tcp"), QStringLiteral("-p"),
                    m.captured(1), QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-r"),
                    QStringLiteral("1"), QStringLiteral("-c"), QStringLiteral("2"),
                    QStringLiteral("-1"), QStringLiteral("127.0.0.1")});
        QVERIFY2(out.contains(QStringLiteral("[1]: \t180")), qPrintable(out));
        endSim(sim.get());
    }

    void stateSurvivesARestart()
    {
        if (m_mbpoll.isEmpty())
            QSKIP("mbpoll is not installed (Debian package mbpoll)");
        QTemporaryDir dir;
        const QString link = dir.filePath(QStringLiteral("stepcom0"));
        const QString state = dir.filePath(QStringLiteral("flash.json"));
        const QStringList args{QStringLiteral("--link"), link, QStringLiteral("--state"), state};
        auto sim = startSim(args, nullptr);
        QVERIFY(sim);
        QVERIFY(mbpoll(rtu(link, split("-a 1 -r 2"), {QStringLiteral("16")}))
                    .contains(QStringLiteral("Written")));
        QVERIFY(mbpoll(rtu(link, split("-a 1 -t 0 -r 96"), {QStringLiteral("1")}))
                    .contains(QStringLiteral("Written")));
        endSim(sim.get());
        QVERIFY(QFileInfo::exists(state));
        sim = startSim(args, nullptr);
        QVERIFY(sim);
        const QString out = mbpoll(rtu(link, split("-a 1 -r 2 -c 1")));
        QVERIFY2(out.contains(QStringLiteral("[2]: \t16")), qPrintable(out));
        endSim(sim.get());
    }

    void consoleDrivesInputs()
    {
        QString banner;
        auto sim =
            startSim({QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--console"),
                      QStringLiteral("--input"), QStringLiteral("IN2=on")},
                     &banner);
        QVERIFY(sim);
        sim->write("in 3 on\nstatus\nbogus\nset motor1.speed 600\nget motor1.speed\nquit\n");
        QVERIFY(sim->waitForFinished(5000));
        QCOMPARE(sim->exitCode(), 0);
        const QString out = QString::fromUtf8(sim->readAllStandardOutput());
        const QString err = QString::fromUtf8(sim->readAllStandardError());
        QVERIFY2(out.contains(QStringLiteral("IN3 is on")), qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("IN1=0 IN2=1 IN3=1 IN4=0")), qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("motor1.speed = 600 rpm")), qPrintable(out));
        QVERIFY2(err.contains(QStringLiteral("unknown command 'bogus'")), qPrintable(err));
    }

    void powerCycleFromTheConsoleAndTheCommandLine()
    {
        QString banner;
        auto sim =
            startSim({QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--console"),
                      QStringLiteral("--power-cycle"), QStringLiteral("0.2:0.3"),
                      QStringLiteral("--answer-delay"), QStringLiteral("0")},
                     &banner);
        QVERIFY(sim);
        QByteArray err;
        for (int i = 0; i < 50 && !err.contains("back on"); ++i) {
            sim->waitForReadyRead(100);
            err += sim->readAllStandardError();
        }
        sim->write("power-cycle 2.5\nstatus\npower-cycle 1 id 4\npower-cycle x\nquit\n");
        QVERIFY(sim->waitForFinished(5000));
        QCOMPARE(sim->exitCode(), 0);
        const QString out = QString::fromUtf8(sim->readAllStandardOutput());
        err += sim->readAllStandardError();
        const QString errText = QString::fromUtf8(err);
        QVERIFY2(errText.contains(QStringLiteral("power cycle: 24 V off for 0.3 s")),
                 qPrintable(errText));
        QVERIFY2(errText.contains(QStringLiteral("power cycle: 24 V back on")),
                 qPrintable(errText));
        QVERIFY2(out.contains(QStringLiteral("24 V off for 2.5 s")), qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("24 V off: power returns in")), qPrintable(out));
        QVERIFY2(errText.contains(QStringLiteral("no controller has id 4")), qPrintable(errText));
        QVERIFY2(errText.contains(QStringLiteral("usage: power-cycle")), qPrintable(errText));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstStepcomSim, Guiless)
#include "tst_stepcomsim.moc"
