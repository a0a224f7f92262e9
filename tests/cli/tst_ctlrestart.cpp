// stepcomctl when the controller's 24 V is switched off and on (issue 24): `monitor --json`
// prints a "restarted" event and goes on; `command motor1.home --wait` cut by it ends with exit
// code 1 and the cause "silent" (the axis stands at 0 as a homing that ended would: whether it
// ended or the controller restarted is not known), not "done" and not "link lost".
#include "programrun.h"
#include "sim/simdevice.h"
#include "sim/simhost.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestCtlRestart : public QObject
{
    Q_OBJECT

    // A controller answering in 5 ms, switched off `offMs` at `atMs` after it started.
    static bool start(SimHost &host, int atMs, int offMs)
    {
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        o.powerCycles = {{atMs, offMs}};
        QString error;
        const bool ok = host.start(o, &error);
        if (!ok)
            qWarning("%s", qPrintable(error));
        return ok;
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
            else
                ++samples;
        }
        QCOMPARE(events, QStringList{QStringLiteral("restarted")});
        QCOMPARE(samples, 50);
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
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
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
