#include "replayprobe.h"

#include "windowprobe.h" // statusMb

#include "bus/rtuframe.h"
#include "session/sessionlog.h"
#include "support/replaylog.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QModbusPdu>
#include <QRandomGenerator>
#include <QTemporaryDir>

namespace stepcom::bench {

namespace {

QByteArray words(const QList<quint16> &values)
{
    QByteArray b;
    for (const quint16 v : values)
        b.append(char(v >> 8)).append(char(v & 0xFF));
    return b;
}

} // namespace

bool writeReplayLog(const QString &path, int seconds, int hz, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        *error = file.errorString();
        return false;
    }
    const RegisterMap &map = RegisterMap::builtin();
    QTextStream out(&file);
    out << "# StepCom " STEPCOM_VERSION " session log, part 1: /dev/ttyUSB0 · 9600 8N1 · id 1\n"
        << "# program: StepCom " STEPCOM_VERSION "\n# map: " << map.identity()
        << "\n# line: transport=rtu port=/dev/ttyUSB0 baud=9600 parity=none stop=1 id=1\n"
           "# ids: 1\n";
    QDateTime t(QDate(2026, 11, 24), QTime(9, 0));
    const auto line = [&](bool sent, TrafficEntry::Kind kind, const QByteArray &raw) {
        TrafficEntry e;
        e.time = t;
        e.direction = sent ? TrafficEntry::Direction::Sent : TrafficEntry::Direction::Received;
        e.kind = kind;
        e.bytes = raw;
        e.summary = TrafficLog::describePdu(e.direction, raw.mid(1, raw.size() - 3), nullptr, &map);
        out << SessionLog::formatLine(e);
    };
    const auto read = [&](quint16 address, const QList<quint16> &values, bool answered) {
        line(true, TrafficEntry::Kind::Poll,
             RtuFrame::adu(1, QModbusRequest(QModbusPdu::ReadHoldingRegisters,
                                             words({address, quint16(values.size())}))));
        t = t.addMSecs(20);
        if (answered)
            line(false, TrafficEntry::Kind::Poll,
                 RtuFrame::adu(1, QModbusResponse(QModbusPdu::ReadHoldingRegisters,
                                                  char(2 * values.size()) + words(values))));
        t = t.addMSecs(20);
    };
    out << SessionLog::formatMark(t, SessionLog::kLinkUp, QStringLiteral("/dev/ttyUSB0"));
    const int cycles = seconds * hz;
    const qint64 cycleMs = 1000 / hz;
    for (int i = 0; i < cycles; ++i) {
        const QDateTime start = t;
        QList<quint16> status(20, 0);
        status[0] = quint16(i); // motor1.position, low word
        status[2] = quint16(i / 2);
        read(107, status, i % 997 != 5); // now and then no answer
        read(147, QList<quint16>(22, quint16(i % 2)), true);
        if (i % (60 * hz) == 0) {
            const QByteArray head = words({5, 1});
            line(
                true, TrafficEntry::Kind::Write,
                RtuFrame::adu(1, QModbusRequest(QModbusPdu::WriteMultipleRegisters,
                                                head + char(2) + words({quint16(100 + i % 500)}))));
            line(false, TrafficEntry::Kind::Write,
                 RtuFrame::adu(1, QModbusResponse(QModbusPdu::WriteMultipleRegisters, head)));
        }
        t = start.addMSecs(cycleMs);
    }
    out.flush();
    return file.error() == QFile::NoError;
}

ReplayResult measureReplay(int seconds, int hz)
{
    ReplayResult r;
    r.seconds = seconds;
    r.hz = hz;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("hour.log"));
    if (!writeReplayLog(path, seconds, hz, &r.error))
        return r;
    r.bytes = QFileInfo(path).size();
    const qint64 pid = QCoreApplication::applicationPid();
    const double before = statusMb(pid, QByteArrayLiteral("VmRSS"));
    QElapsedTimer timer;
    timer.start();
    ReplayLog log;
    if (!log.open(path)) {
        r.error = log.errorString();
        return r;
    }
    const ReplayState first = log.stateAt(0);
    r.firstStateMs = double(timer.nsecsElapsed()) / 1e6;
    Q_UNUSED(first);
    r.lines = log.lineCount();
    r.snapshots = log.snapshotCount();
    r.events = log.events().size();
    // Moments all over the log, the same every run.
    QRandomGenerator random(26);
    double total = 0;
    for (int i = 0; i < 50; ++i) {
        const qint64 at = qint64(random.bounded(double(log.durationMs())));
        timer.restart();
        const ReplayState s = log.stateAt(at);
        const double ms = double(timer.nsecsElapsed()) / 1e6;
        if (s.devices.isEmpty() && at > 1000)
            r.error = QStringLiteral("no state at %1 ms").arg(at);
        total += ms;
        r.seekMaxMs = std::max(r.seekMaxMs, ms);
        ++r.seeks;
    }
    r.seekMeanMs = total / r.seeks;
    r.residentGrowthMb = statusMb(pid, QByteArrayLiteral("VmRSS")) - before;
    r.peakRssMb = statusMb(pid, QByteArrayLiteral("VmHWM"));
    return r;
}

QList<Verdict> replayVerdicts(const ReplayResult &r)
{
    const QString what = QStringLiteral("%1 s at %2 Hz").arg(r.seconds).arg(r.hz);
    if (!r.error.isEmpty())
        return {Verdict{QStringLiteral("log"),
                        QStringLiteral("(l) replay of %1").arg(what),
                        r.error,
                        {},
                        {},
                        Verdict::Result::Error}};
    const auto judge = [](double value, double bound) {
        return value <= bound ? Verdict::Result::Pass : Verdict::Result::Fail;
    };
    const QString size = QStringLiteral("%1 MB, %2 lines, %3 snapshots, %4 events")
                             .arg(QString::number(double(r.bytes) / 1e6, 'f', 1))
                             .arg(r.lines)
                             .arg(r.snapshots)
                             .arg(r.events);
    return {
        Verdict{QStringLiteral("log"),
                QStringLiteral("(l) replay: open a log of %1 to the first state").arg(what),
                QStringLiteral("%1 ms (%2)").arg(QString::number(r.firstStateMs, 'f', 0), size),
                QStringLiteral("< 2000 ms"), QString::number(r.firstStateMs / 2000.0, 'f', 2),
                judge(r.firstStateMs, 2000)},
        Verdict{
            QStringLiteral("log"), QStringLiteral("(l) replay: seek anywhere"),
            QStringLiteral("mean %1 ms, max %2 ms (%3 seeks)")
                .arg(QString::number(r.seekMeanMs, 'f', 1), QString::number(r.seekMaxMs, 'f', 1))
                .arg(r.seeks),
            QStringLiteral("< 200 ms"), QString::number(r.seekMaxMs / 200.0, 'f', 2),
            judge(r.seekMaxMs, 200)},
        Verdict{QStringLiteral("log"), QStringLiteral("(l) replay: memory"),
                QStringLiteral("%1 MB resident growth, VmHWM %2 MB")
                    .arg(QString::number(r.residentGrowthMb, 'f', 1),
                         QString::number(r.peakRssMb, 'f', 1)),
                QStringLiteral("< 200 MB"), QString::number(r.peakRssMb / 200.0, 'f', 2),
                judge(r.peakRssMb, 200)},
    };
}

} // namespace stepcom::bench
