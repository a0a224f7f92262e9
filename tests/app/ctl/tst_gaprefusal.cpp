// stepcomctl against a simulated controller that refuses reads covering reserved registers
// (--refuse-gaps) and one that also lacks listed registers (--lacks 40110 --lacks motor2.speed):
// read, monitor, dump, diff, apply and report go on.
#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestGapRefusal : public QObject
{
    Q_OBJECT
    SimHost *m_host = nullptr;
    QTemporaryDir m_dir;

    ProgramRun ctl(const QStringList &args)
    {
        return runProgram(QStringLiteral("stepcomctl"),
                          QStringList{QStringLiteral("--port"), m_host->rtuPath()} + args);
    }
    QString file(const QString &name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void init()
    {
        QFETCH(bool, lacks);
        m_host = new SimHost(this);
        SimOptions options;
        options.rtu = true;
        options.strictReads = true;
        if (lacks)
            options.lacks = {QStringLiteral("40110"), QStringLiteral("motor2.speed")};
        QString error;
        QVERIFY2(m_host->start(options, &error), qPrintable(error));
    }
    void cleanup()
    {
        delete m_host;
        m_host = nullptr;
    }

    void readGoesOn_data() { rows(); }
    void readGoesOn()
    {
        QFETCH(bool, lacks);
        const ProgramRun some = ctl(
            {QStringLiteral("read"), QStringLiteral("motor1.position"), QStringLiteral("io.in1")});
        QVERIFY2(some.exitCode == 0, qPrintable(some.err));
        QVERIFY(some.out.contains(QStringLiteral("motor1.position = ")));
        QVERIFY(some.out.contains(QStringLiteral("io.in1 = ")));
        QVERIFY2(some.err.contains(QStringLiteral("reserved registers")), qPrintable(some.err));

        const ProgramRun all = ctl({QStringLiteral("--json"), QStringLiteral("read")});
        QVERIFY2(all.exitCode == 0, qPrintable(all.err));
        const QJsonObject o = QJsonDocument::fromJson(all.out.toUtf8())
                                  .object()
                                  .value(QStringLiteral("result"))
                                  .toObject();
        QVERIFY(o.contains(QStringLiteral("motor1.speed")));
        QVERIFY(o.contains(QStringLiteral("io.out3")));
        QCOMPARE(o.contains(QStringLiteral("motor2.position")), !lacks);
        QCOMPARE(
            all.err.contains(QStringLiteral("motor2.position is not supported by this controller")),
            lacks);
    }

    void monitorPrintsSamples_data() { rows(); }
    void monitorPrintsSamples()
    {
        QFETCH(bool, lacks);
        const ProgramRun r =
            ctl({QStringLiteral("monitor"), QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        for (const QString &line : lines) {
            const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
            QVERIFY2(o.value(QStringLiteral("motor1.position")).isDouble(), qPrintable(line));
            QVERIFY(o.value(QStringLiteral("io.in4")).isDouble());
            QCOMPARE(o.value(QStringLiteral("motor2.position")).isNull(), lacks);
        }
    }

    void profileCommandsGoOn_data() { rows(); }
    void profileCommandsGoOn()
    {
        QFETCH(bool, lacks);
        const ProgramRun dump = ctl({QStringLiteral("dump"), file(QStringLiteral("p.json"))});
        QVERIFY2(dump.exitCode == 0, qPrintable(dump.err));
        QCOMPARE(dump.out.contains(QStringLiteral("not supported by this controller")), lacks);
        QFile saved(file(QStringLiteral("p.json")));
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const QJsonObject top = QJsonDocument::fromJson(saved.readAll()).object();
        QCOMPARE(
            top.value(QStringLiteral("values")).toObject().contains(QStringLiteral("motor2.speed")),
            !lacks);
        QCOMPARE(top.value(QStringLiteral("metadata"))
                     .toObject()
                     .value(QStringLiteral("unsupported"))
                     .toArray()
                     .contains(QStringLiteral("motor2.speed")),
                 lacks);

        const ProgramRun same = ctl({QStringLiteral("diff"), file(QStringLiteral("p.json"))});
        QVERIFY2(same.exitCode == 0, qPrintable(same.out + same.err));

        QVERIFY(m_host->device()->setValue(QStringLiteral("motor1.speed"), 777));
        const ProgramRun differs = ctl({QStringLiteral("diff"), file(QStringLiteral("p.json"))});
        QCOMPARE(differs.exitCode, 1);
        QVERIFY2(differs.out.contains(QStringLiteral("motor1.speed")), qPrintable(differs.out));

        const ProgramRun apply =
            ctl({QStringLiteral("apply"), QStringLiteral("--yes"), file(QStringLiteral("p.json"))});
        QVERIFY2(apply.exitCode == 0, qPrintable(apply.out + apply.err));
        QVERIFY(m_host->device()->value(QStringLiteral("motor1.speed")) != 777);

        const ProgramRun report = ctl({QStringLiteral("report"), file(QStringLiteral("r.html"))});
        QVERIFY2(report.exitCode == 0, qPrintable(report.out + report.err));
        QFile html(file(QStringLiteral("r.html")));
        QVERIFY(html.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(html.readAll())
                     .contains(QStringLiteral("not supported by this controller")),
                 lacks);
    }

private:
    static void rows()
    {
        QTest::addColumn<bool>("lacks");
        QTest::newRow("refuses gaps") << false;
        QTest::newRow("lacks two registers") << true;
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestGapRefusal, Guiless)
#include "tst_gaprefusal.moc"
