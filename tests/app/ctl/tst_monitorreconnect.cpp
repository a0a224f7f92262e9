// `stepcomctl monitor` when the cable is pulled and plugged back: it says "lost" and
// "back" (a JSON line with --json, a text line on stderr without) and goes on printing samples.
// The adapter's stable name (as /dev/serial/by-id gives it) stays while the pty behind changes.
#include "sim/host/simhost.h"
#include "testpaths.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;
using namespace stepcom::test;

namespace {

std::unique_ptr<SimHost> startSim(const QString &linkPath)
{
    auto host = std::make_unique<SimHost>();
    SimOptions options;
    options.rtu = true;
    options.linkPath = linkPath;
    QString error;
    if (!host->start(options, &error)) {
        qWarning("simulator: %s", qPrintable(error));
        return nullptr;
    }
    return host;
}

// Reads what the program printed so far, line by line, without blocking the event loop.
struct Lines
{
    QProcess *process;
    QStringList out;
    QString err;
    QByteArray partial;

    void take()
    {
        partial += process->readAllStandardOutput();
        qsizetype nl;
        while ((nl = partial.indexOf('\n')) >= 0) {
            out << QString::fromUtf8(partial.left(nl));
            partial.remove(0, nl + 1);
        }
        err += QString::fromUtf8(process->readAllStandardError());
    }
    int count(const std::function<bool(const QString &)> &what) const
    {
        return int(std::count_if(out.cbegin(), out.cend(), what));
    }
    bool waitFor(const std::function<bool()> &condition, int ms)
    {
        return QTest::qWaitFor(
            [&] {
                take();
                return condition();
            },
            ms);
    }
};

bool isSample(const QString &line)
{
    return line.startsWith(QLatin1String("{\"time\""));
}

QString eventOf(const QString &line)
{
    return QJsonDocument::fromJson(line.toUtf8())
        .object()
        .value(QStringLiteral("event"))
        .toString();
}

} // namespace

class TestMonitorReconnect : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void goesOnAfterThePortCameBack_data()
    {
        QTest::addColumn<bool>("json");
        QTest::newRow("json") << true;
        QTest::newRow("text") << false;
    }
    void goesOnAfterThePortCameBack()
    {
        QFETCH(bool, json);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString stable = dir.filePath(QStringLiteral("usb-FTDI_FT232R_A10K3B5Q-if00-port0"));
        std::unique_ptr<SimHost> host = startSim(stable);
        QVERIFY(host);

        QProcess p;
        QStringList args{QStringLiteral("--port"), stable, QStringLiteral("monitor"),
                         QStringLiteral("--count"), QStringLiteral("6")};
        if (json)
            args.prepend(QStringLiteral("--json"));
        p.start(programPath(QStringLiteral("stepcomctl")), args);
        QVERIFY(p.waitForStarted(10000));
        Lines lines{&p, {}, {}, {}};
        QVERIFY2(lines.waitFor([&] { return lines.count(isSample) >= 2; }, 20000),
                 qPrintable(lines.err));

        // Pulled: the pty and the name go away; plugged back: the same stable name, another pty.
        host.reset();
        if (json) {
            QVERIFY2(lines.waitFor(
                         [&] {
                             return lines.count([](const QString &l) {
                                 return eventOf(l) == QLatin1String("lost");
                             }) == 1;
                         },
                         10000),
                     qPrintable(lines.out.join(QLatin1Char('\n')) + lines.err));
        } else {
            QVERIFY2(lines.waitFor([&] { return lines.err.contains(QLatin1String("link lost")); },
                                   10000),
                     qPrintable(lines.err));
        }
        QCOMPARE(p.state(), QProcess::Running); // it waits for the port, it does not end
        const int before = lines.count(isSample);
        host = startSim(stable);
        QVERIFY(host);
        QVERIFY2(lines.waitFor([&] { return p.state() == QProcess::NotRunning; }, 30000),
                 qPrintable(lines.err));
        QCOMPARE(p.exitCode(), 0);
        lines.take();
        QCOMPARE(lines.count(isSample), 6);
        QVERIFY(lines.count(isSample) > before); // samples after the way back
        if (json) {
            // The last line is the envelope: the run's exit, samples and events, no error.
            const QJsonObject last = QJsonDocument::fromJson(lines.out.last().toUtf8()).object();
            QCOMPARE(last.value(QStringLiteral("exit")).toInt(-1), 0);
            QCOMPARE(last.value(QStringLiteral("result")).toObject().value("samples"),
                     QJsonValue(6));
            QCOMPARE(last.value(QStringLiteral("result")).toObject().value("events"),
                     QJsonValue(2));
            QStringList events;
            for (const QString &l : lines.out.first(lines.out.size() - 1)) {
                if (!isSample(l))
                    events << eventOf(l);
            }
            QCOMPARE(events, (QStringList{QStringLiteral("lost"), QStringLiteral("back")}));
            // "back" comes before the first sample after it
            qsizetype back = -1;
            for (qsizetype i = 0; i < lines.out.size(); ++i) {
                if (eventOf(lines.out.at(i)) == QLatin1String("back"))
                    back = i;
            }
            QVERIFY(back > 0 && back < lines.out.size() - 1);
            const QJsonObject o = QJsonDocument::fromJson(lines.out.at(back).toUtf8()).object();
            QCOMPARE(o.value(QStringLiteral("port")).toString(), stable);
        } else {
            QVERIFY2(lines.err.contains(QLatin1String("link back")), qPrintable(lines.err));
            QCOMPARE(lines.count([](const QString &l) { return !isSample(l); }), 0);
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestMonitorReconnect, Guiless)
#include "tst_monitorreconnect.moc"
