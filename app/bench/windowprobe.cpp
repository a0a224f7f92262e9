#include "windowprobe.h"

#include "benchrunner.h"

#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace stepcom::bench {

namespace {

// utime + stime of a process, in seconds; -1 when it cannot be read (Linux /proc only).
double cpuSeconds(qint64 pid)
{
#ifndef Q_OS_UNIX
    Q_UNUSED(pid)
    return -1;
#else
    QFile file(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray text = file.readAll();
    // The command name may hold spaces and parentheses: fields count from the last ')'.
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return -1;
    const double ticks = double(fields.at(11).toLongLong() + fields.at(12).toLongLong());
    return ticks / double(sysconf(_SC_CLK_TCK));
#endif
}

} // namespace

double statusMb(qint64 pid, const QByteArray &field)
{
    QFile file(QStringLiteral("/proc/%1/status").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith(field + ':'))
            return line.mid(field.size() + 1).trimmed().split(' ').first().toDouble() / 1024.0;
    }
    return -1;
}

WindowResult measureWindow(const BenchConfig &config, SimHost *host, int baud)
{
    WindowResult w;
    if (!QFile::exists(config.stepcomPath)) {
        w.note =
            QStringLiteral("skipped: no %1 (build the stepcom target)").arg(config.stepcomPath);
        return w;
    }
    QTemporaryDir home; // the window's settings stay out of the user's
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("STEPCOM_POLL_INTERVAL_MS"), QStringLiteral("0"));
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.path());
    QProcess window;
    window.setProcessEnvironment(env);
    window.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    window.setStandardOutputFile(QProcess::nullDevice());
    QStringList args;
    if (host)
        args << QStringLiteral("--port") << host->rtuPath() << QStringLiteral("--baud")
             << QString::number(baud);
    else
        args << QStringLiteral("--sim");
    window.start(config.stepcomPath, args);
    if (!window.waitForStarted(5000)) {
        w.note = QStringLiteral("cannot start %1").arg(config.stepcomPath);
        return w;
    }
    const qint64 pid = window.processId();
    // Connected, read everything and polling: then a moment more for the first paint.
    const int requestsAtStart = host ? host->stats().requests : 0;
    const bool polling =
        !host || waitUntil([&] { return host->stats().requests >= requestsAtStart + 10; }, 15000);
    waitUntil([] { return false; }, host ? 2000 : 4000);
    if (!polling || window.state() != QProcess::Running) {
        w.note = QStringLiteral("the window did not start polling");
        window.kill();
        window.waitForFinished(3000);
        return w;
    }
    SimDevice *device = host ? host->device() : nullptr;
    if (device) {
        device->setMachinePosition(1, 30.0);
        device->command(QStringLiteral("motor1.forward"));
    }
    const int requestsBefore = host ? host->stats().requests : 0;
    const double cpuBefore = cpuSeconds(pid);
    QElapsedTimer wall;
    wall.start();
    const int halfMs = config.windowSeconds * 500;
    waitUntil([] { return false; }, halfMs);
    if (device) { // turn round so it never reaches the end of its travel
        device->command(QStringLiteral("motor1.stop"));
        device->command(QStringLiteral("motor1.reverse"));
    }
    waitUntil([] { return false; }, halfMs);
    const double cpuAfter = cpuSeconds(pid);
    w.seconds = double(wall.nsecsElapsed()) / 1e9;
    w.peakRssMb = statusMb(pid, QByteArrayLiteral("VmHWM"));
    if (device)
        device->command(QStringLiteral("motor1.stop"));
    if (host)
        w.pollsPerSec = (host->stats().requests - requestsBefore) / w.seconds;
    window.terminate();
    if (!window.waitForFinished(3000)) {
        window.kill();
        window.waitForFinished(3000);
    }
    if (cpuBefore < 0 || cpuAfter < 0 || w.peakRssMb < 0) {
        w.note = QStringLiteral("cannot read /proc/%1").arg(pid);
        return w;
    }
    w.cpuPercent = 100.0 * (cpuAfter - cpuBefore) / w.seconds;
    w.measured = true;
    w.note = host ? QStringLiteral("window alone; simulator in the benchmark's process")
                  : QStringLiteral("window with its built-in simulator in the same process");
    return w;
}

} // namespace stepcom::bench
