#include "replaywindowprobe.h"

#include "replayprobe.h" // writeReplayLog
#include "windowprobe.h" // statusMb

#include "pages/plotpage.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "support/replaylog.h"
#include "widgets/docks/trafficmodel.h"
#include "widgets/docks/trafficview.h"
#include "widgets/plots/positionplot.h"
#include "widgets/plots/xyplot.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTextStream>
#include <QTimer>

namespace stepcom::bench {

namespace {

constexpr int kOpenTimeoutMs = 120000;
constexpr int kChildTimeoutMs = 300000;

double median(QList<double> values)
{
    if (values.isEmpty())
        return 0;
    std::sort(values.begin(), values.end());
    const qsizetype n = values.size();
    return n % 2 ? values.at(n / 2) : (values.at(n / 2 - 1) + values.at(n / 2)) / 2.0;
}

} // namespace

int runReplayWindowChild(const QString &logPath, int seeks)
{
    QJsonObject result;
    const auto say = [&result](int code) {
        QTextStream(stdout) << QJsonDocument(result).toJson(QJsonDocument::Compact) << '\n';
        return code;
    };
    DeviceSession session;
    MainWindow window(&session);
    window.resize(1366, 768);
    window.show();
    // The heaviest views in sight: the Plots page (position plot and XY trace) and every dock
    // (the traffic view, the device list).
    const WindowProbe probe(window);
    for (int i = 0; i < probe.pages().size(); ++i) {
        if (probe.pages().at(i) == probe.plotPage())
            probe.showPage(i);
    }
    for (QDockWidget *dock : window.findChildren<QDockWidget *>())
        dock->show();
    QCoreApplication::processEvents();
    // What the user sees after a seek: the traffic rows batched, the plots redrawn (both on
    // timers of their own otherwise), everything posted done, the window painted.
    const auto everyViewUpdated = [&window, &probe] {
        probe.trafficView()->model()->flush();
        probe.plotPage()->positionPlot()->refresh();
        probe.plotPage()->xyPlot()->flush();
        QCoreApplication::processEvents();
        window.repaint();
    };

    ReplayMode *replay = probe.replayMode();
    QEventLoop loop;
    QString failure;
    QObject::connect(replay, &ReplayMode::opened, &loop, &QEventLoop::quit);
    QObject::connect(replay, &ReplayMode::failed, &loop, [&](const QString &why) {
        failure = why;
        loop.quit();
    });
    QTimer::singleShot(kOpenTimeoutMs, &loop, &QEventLoop::quit);
    QElapsedTimer timer;
    timer.start();
    if (replay->openPath(logPath))
        loop.exec();
    if (!replay->isActive()) {
        result.insert(QStringLiteral("error"),
                      failure.isEmpty() ? QStringLiteral("the log did not open") : failure);
        return say(1);
    }
    everyViewUpdated();
    result.insert(QStringLiteral("first_frame_ms"), double(timer.nsecsElapsed()) / 1e6);

    // Moments all over the log, the same every run; each one shown afresh (not played on to).
    QRandomGenerator random(26);
    QJsonArray times;
    const qint64 duration = replay->log().durationMs();
    for (int i = 0; i < seeks; ++i) {
        const qint64 at = qint64(random.bounded(double(duration)));
        timer.restart();
        replay->seek(at);
        everyViewUpdated();
        times.append(double(timer.nsecsElapsed()) / 1e6);
    }
    result.insert(QStringLiteral("seeks_ms"), times);
    result.insert(QStringLiteral("traffic_rows"), probe.trafficView()->model()->storedCount());
    result.insert(QStringLiteral("trace_points"), probe.plotPage()->xyPlot()->traceCount());
    result.insert(QStringLiteral("peak_rss_mb"),
                  statusMb(QCoreApplication::applicationPid(), QByteArrayLiteral("VmHWM")));
    return say(0);
}

ReplayWindowResult measureReplayWindow(int seconds, int hz, int seeks)
{
    ReplayWindowResult r;
    r.seconds = seconds;
    r.hz = hz;
    QTemporaryDir dir; // the log, and the window's settings kept out of the user's
    const QString path = dir.filePath(QStringLiteral("hour.log"));
    if (!writeReplayLog(path, seconds, hz, &r.error))
        return r;
    r.bytes = QFileInfo(path).size();
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("data")));
    QProcess child;
    child.setProcessEnvironment(env);
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    child.start(QCoreApplication::applicationFilePath(),
                {QStringLiteral("--replay-window-child"), path,
                 QStringLiteral("--replay-window-seeks"), QString::number(seeks)});
    if (!child.waitForFinished(kChildTimeoutMs)) {
        child.kill();
        child.waitForFinished();
        r.error = QStringLiteral("the window did not finish within %1 s (%2)")
                      .arg(kChildTimeoutMs / 1000)
                      .arg(child.errorString());
        return r;
    }
    const QList<QByteArray> lines = child.readAllStandardOutput().trimmed().split('\n');
    const QJsonObject o = QJsonDocument::fromJson(lines.last()).object();
    if (o.isEmpty()) {
        r.error =
            QStringLiteral("the window said nothing readable (exit code %1)").arg(child.exitCode());
        return r;
    }
    r.error = o.value(QStringLiteral("error")).toString();
    r.firstFrameMs = o.value(QStringLiteral("first_frame_ms")).toDouble();
    for (const QJsonValue v : o.value(QStringLiteral("seeks_ms")).toArray())
        r.seeksMs << v.toDouble();
    r.peakRssMb = o.value(QStringLiteral("peak_rss_mb")).toDouble();
    r.trafficRows = o.value(QStringLiteral("traffic_rows")).toInt();
    r.tracePoints = o.value(QStringLiteral("trace_points")).toInt();
    if (r.error.isEmpty() && r.seeksMs.size() != seeks)
        r.error = QStringLiteral("%1 seeks measured of %2").arg(r.seeksMs.size()).arg(seeks);
    return r;
}

QList<Verdict> replayWindowVerdicts(const ReplayWindowResult &r)
{
    const QString what = QStringLiteral("%1 s at %2 Hz").arg(r.seconds).arg(r.hz);
    if (!r.error.isEmpty())
        return {Verdict{QStringLiteral("log"),
                        QStringLiteral("(m) replay in the window of %1").arg(what),
                        r.error,
                        {},
                        {},
                        Verdict::Result::Error}};
    const auto judge = [](double value, double bound) {
        return value <= bound ? Verdict::Result::Pass : Verdict::Result::Fail;
    };
    const double worst =
        r.seeksMs.isEmpty() ? 0 : *std::max_element(r.seeksMs.cbegin(), r.seeksMs.cend());
    return {
        Verdict{QStringLiteral("log"),
                QStringLiteral("(m) replay in the window: open a log of %1 to the first frame "
                               "shown")
                    .arg(what),
                QStringLiteral("%1 ms (%2 MB)")
                    .arg(QString::number(r.firstFrameMs, 'f', 0),
                         QString::number(double(r.bytes) / 1e6, 'f', 1)),
                QStringLiteral("< 2000 ms"), QString::number(r.firstFrameMs / 2000.0, 'f', 2),
                judge(r.firstFrameMs, 2000)},
        Verdict{QStringLiteral("log"),
                QStringLiteral("(m) replay in the window: seek, every view updated and painted"),
                QStringLiteral("median %1 ms, max %2 ms (%3 seeks; %4 traffic rows, %5 trace "
                               "points at the last)")
                    .arg(QString::number(median(r.seeksMs), 'f', 1), QString::number(worst, 'f', 1))
                    .arg(r.seeksMs.size())
                    .arg(r.trafficRows)
                    .arg(r.tracePoints),
                QStringLiteral("< 200 ms"), QString::number(worst / 200.0, 'f', 2),
                judge(worst, 200)},
        Verdict{QStringLiteral("log"), QStringLiteral("(m) replay in the window: memory"),
                QStringLiteral("VmHWM %1 MB (the window's process)")
                    .arg(QString::number(r.peakRssMb, 'f', 1)),
                QStringLiteral("< 200 MB"), QString::number(r.peakRssMb / 200.0, 'f', 2),
                judge(r.peakRssMb, 200)},
    };
}

} // namespace stepcom::bench
