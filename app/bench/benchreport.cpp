#include "benchreport.h"

#include <QDateTime>
#include <QFile>
#include <QSaveFile>
#include <QSysInfo>
#include <QThread>

namespace stepcom::bench {

namespace {

constexpr double kCycleTarget = 1.10;
constexpr double kCpuTargetPercent = 3.0;
constexpr double kRssTargetMb = 150.0;
constexpr double kTrafficBatchTargetMs = 10.0; // a tenth of the 100 ms batch interval
constexpr double kTrafficMemoryTargetMb = 100.0;
constexpr double kFirstStatusTargetMs = 350.0;

QString ms(double v)
{
    return QString::number(v, 'f', 1);
}

QString spanText(const Span &s, const QString &what)
{
    return QStringLiteral("mean %1 ms (min %2, max %3; %4 %5)")
        .arg(ms(s.mean), ms(s.min), ms(s.max))
        .arg(s.count)
        .arg(what);
}

Verdict::Result judge(bool pass)
{
    return pass ? Verdict::Result::Pass : Verdict::Result::Fail;
}

void addWindow(QList<Verdict> &rows, const QString &baud, const WindowResult &w, bool info)
{
    const QString suffix =
        info ? QStringLiteral(" (built-in simulator, for information)") : QString();
    if (!w.measured && w.note.isEmpty())
        return; // not asked for (--no-window)
    if (!w.measured) {
        rows.append({baud, QStringLiteral("(d) window") + suffix, w.note, QString(), QString(),
                     Verdict::Result::Error});
        return;
    }
    QString measured = QStringLiteral("%1 % of one core over %2 s")
                           .arg(QString::number(w.cpuPercent, 'f', 2))
                           .arg(QString::number(w.seconds, 'f', 1));
    if (w.pollsPerSec > 0)
        measured += QStringLiteral(" (%1 requests/s)").arg(QString::number(w.pollsPerSec, 'f', 1));
    rows.append({baud, QStringLiteral("(d) window CPU") + suffix, measured,
                 QStringLiteral("< 3 % of one core"),
                 QString::number(w.cpuPercent / kCpuTargetPercent, 'f', 2),
                 info ? Verdict::Result::Info : judge(w.cpuPercent < kCpuTargetPercent)});
    rows.append({baud, QStringLiteral("(d) window peak memory") + suffix,
                 QStringLiteral("VmHWM %1 MB").arg(QString::number(w.peakRssMb, 'f', 1)),
                 QStringLiteral("< 150 MB"), QString::number(w.peakRssMb / kRssTargetMb, 'f', 2),
                 info ? Verdict::Result::Info : judge(w.peakRssMb < kRssTargetMb)});
}

// The live status cycle and read-all of `r` against their optima: rows (a)/(b), and (i).
void cycleRows(const BaudResult &r, QList<Verdict> *rows, const QString &cycleTarget,
               const QString &readAllTarget, const QString &optimum, const QString &sameReads)
{
    const QString baud = QString::number(r.baud);
    const double cycleRatio = r.cycleMs.mean / r.statusOptimumMs;
    rows->append({baud, cycleTarget,
                  spanText(r.cycleMs, QStringLiteral("cycles")) +
                      QStringLiteral(", %1 reads").arg(r.readsPerCycle, 0, 'f', 0),
                  QStringLiteral("%1 %2 ms, %3 reads; within 1.10×%4")
                      .arg(optimum, ms(r.statusOptimumMs))
                      .arg(r.statusOptimumReads)
                      .arg(sameReads),
                  QStringLiteral("%1×").arg(QString::number(cycleRatio, 'f', 3)),
                  judge(cycleRatio <= kCycleTarget &&
                        int(r.readsPerCycle) == r.statusOptimumReads && r.fastCycles == 0)});
    const double allRatio = r.readAllMs.mean / r.readAllOptimumMs;
    rows->append({baud, readAllTarget,
                  spanText(r.readAllMs, QStringLiteral("runs")) +
                      QStringLiteral(", %1 reads").arg(r.readAllReads),
                  QStringLiteral("%1 %2 ms, %3 reads; within 1.10×, same reads")
                      .arg(optimum, ms(r.readAllOptimumMs))
                      .arg(r.readAllOptimumReads),
                  QStringLiteral("%1×").arg(QString::number(allRatio, 'f', 3)),
                  judge(allRatio <= kCycleTarget && r.readAllReads == r.readAllOptimumReads)});
}

} // namespace

QList<Verdict> verdicts(const BaudResult &r)
{
    QList<Verdict> rows;
    const QString baud = QString::number(r.baud);
    if (!r.error.isEmpty()) {
        rows.append({baud, QStringLiteral("measurement"), r.error, QString(), QString(),
                     Verdict::Result::Error});
        return rows;
    }
    cycleRows(r, &rows, QStringLiteral("(a) live status cycle at full rate"),
              QStringLiteral("(b) read-all"), QStringLiteral("optimum"), QString());
    rows.append({baud, QStringLiteral("(c) E-STOP dispatched, polling at full rate"),
                 QStringLiteral("mean %1 ms, max %2 ms after the request (%3 stops); "
                                "next on the wire every time: %4")
                     .arg(ms(r.estopDispatchMs.mean), ms(r.estopDispatchMs.max))
                     .arg(r.estopDispatchMs.count)
                     .arg(r.estopAlwaysNext ? QStringLiteral("yes") : QStringLiteral("NO")),
                 QStringLiteral("≤ the longest poll transaction, %1 ms").arg(ms(r.longestPollMs)),
                 QString::number(r.estopDispatchMs.max / r.longestPollMs, 'f', 2),
                 judge(r.estopAlwaysNext && r.estopDispatchMs.max <= r.longestPollMs)});
    const double stopBound = r.longestPollMs + r.estopFrameMs;
    rows.append({baud, QStringLiteral("(c) simulator stopped"),
                 QStringLiteral("mean %1 ms, max %2 ms after the request")
                     .arg(ms(r.estopStoppedMs.mean), ms(r.estopStoppedMs.max)),
                 QStringLiteral("≤ %1 ms + its own request frame %2 ms")
                     .arg(ms(r.longestPollMs), ms(r.estopFrameMs)),
                 QString::number(r.estopStoppedMs.max / stopBound, 'f', 2),
                 judge(r.estopStoppedMs.max <= stopBound)});
    addWindow(rows, baud, r.window, false);
    return rows;
}

QList<Verdict> busVerdicts(const BusResult &b)
{
    QList<Verdict> rows;
    const QString baud = QString::number(b.baud);
    if (!b.error.isEmpty()) {
        rows.append({baud, QStringLiteral("(f)/(g) several controllers"), b.error, QString(),
                     QString(), Verdict::Result::Error});
        return rows;
    }
    const double roundRatio = b.roundMs.mean / b.cycleOptimumMs;
    rows.append({baud,
                 QStringLiteral("(f) status of %1 controllers in turn at full rate").arg(b.devices),
                 spanText(b.roundMs, QStringLiteral("rounds")) +
                     QStringLiteral(", %1 reads").arg(b.readsPerRound),
                 QStringLiteral("sum of their optima %1 ms, %2 reads; within 1.10×")
                     .arg(ms(b.cycleOptimumMs))
                     .arg(b.cycleOptimumReads),
                 QStringLiteral("%1×").arg(QString::number(roundRatio, 'f', 3)),
                 judge(roundRatio <= kCycleTarget && b.readsPerRound == b.cycleOptimumReads)});
    for (const EstopAllResult &e : b.estops) {
        const int before = e.devices - 1; // E-STOP transactions before the last one's
        const double bound = e.longestPollMs + before * e.longestEstopMs;
        const double model = e.longestPollMs + before * e.modelEstopMs;
        rows.append(
            {baud, QStringLiteral("(g) E-STOP to all %1, the last one dispatched").arg(e.devices),
             QStringLiteral("mean %1 ms, max %2 ms after the request (%3 stops); next on the "
                            "wire in the order of the list: %4; all acknowledged: %5")
                 .arg(ms(e.lastDispatchMs.mean), ms(e.lastDispatchMs.max))
                 .arg(e.lastDispatchMs.count)
                 .arg(e.inOrderNext ? QStringLiteral("yes") : QStringLiteral("NO"),
                      e.allAcknowledged ? QStringLiteral("yes") : QStringLiteral("NO")),
             QStringLiteral("≤ one transaction in flight (the longest poll, %1 ms) + %2 E-STOP "
                            "transaction(s) of %3 ms (longest seen; model %4 ms) = %5 ms "
                            "(model %6 ms)")
                 .arg(ms(e.longestPollMs))
                 .arg(before)
                 .arg(ms(e.longestEstopMs), ms(e.modelEstopMs), ms(bound), ms(model)),
             QString::number(e.lastDispatchMs.max / bound, 'f', 2),
             judge(e.inOrderNext && e.allAcknowledged && e.lastDispatchMs.max <= bound)});
        rows.append({baud, QStringLiteral("(g) every one of %1 simulators stopped").arg(e.devices),
                     QStringLiteral("mean %1 ms, max %2 ms after the request")
                         .arg(ms(e.allStoppedMs.mean), ms(e.allStoppedMs.max)),
                     QStringLiteral("≤ %1 ms + the last one's request frame %2 ms")
                         .arg(ms(bound), ms(e.frameMs)),
                     QString::number(e.allStoppedMs.max / (bound + e.frameMs), 'f', 2),
                     judge(e.allStoppedMs.max <= bound + e.frameMs)});
    }
    return rows;
}

QList<Verdict> builtinWindowVerdicts(const WindowResult &w)
{
    QList<Verdict> rows;
    addWindow(rows, QStringLiteral("--sim"), w, true);
    return rows;
}

QList<Verdict> trafficVerdicts(const TrafficResult &t)
{
    QList<Verdict> rows;
    if (!t.measured)
        return rows;
    const QString baud = QString::number(t.baud);
    const qint64 hour = qint64(t.framesPerSecond * t.seconds);
    rows.append({baud, QStringLiteral("(e) traffic view keeps the last %1 s").arg(t.seconds),
                 QStringLiteral("%1 of %2 frames kept (%3 frames/s; capacity %4)")
                     .arg(t.kept)
                     .arg(hour)
                     .arg(QString::number(t.framesPerSecond, 'f', 1))
                     .arg(t.capacity),
                 QStringLiteral("all of them"),
                 QString::number(double(t.kept) / double(std::max<qint64>(1, hour)), 'f', 2),
                 judge(t.kept >= hour)});
    rows.append({baud, QStringLiteral("(e) traffic view update, full"),
                 spanText(t.batchMs, QStringLiteral("batches of 100 ms, painted")),
                 QStringLiteral("mean < 10 ms"),
                 QString::number(t.batchMs.mean / kTrafficBatchTargetMs, 'f', 2),
                 judge(t.batchMs.mean < kTrafficBatchTargetMs)});
    rows.append({baud, QStringLiteral("(e) traffic view memory for them"),
                 QStringLiteral("%1 MB resident").arg(QString::number(t.memoryMb, 'f', 1)),
                 QStringLiteral("< 100 MB"),
                 QString::number(t.memoryMb / kTrafficMemoryTargetMb, 'f', 2),
                 judge(t.memoryMb < kTrafficMemoryTargetMb)});
    rows.append({baud, QStringLiteral("(e) traffic view filter over all of them"),
                 QStringLiteral("show polls %1 ms, search %2 ms (%3 rows)")
                     .arg(ms(t.showPollsMs), ms(t.searchMs))
                     .arg(t.rowsShown),
                 QString(), QString(), Verdict::Result::Info});
    return rows;
}

QList<Verdict> scanVerdicts(const ScanResult &s)
{
    const QString baud = QString::number(s.baud);
    const QString target = QStringLiteral("(h) scan of ids 1-%1, nobody answers").arg(s.ids);
    if (!s.measured)
        return {{baud, target, s.error, QString(), QString(), Verdict::Result::Error}};
    // Within 1.5x of the wire's limit, and a silent line must not "find" anything.
    const double bound = 1.5 * s.limitMs;
    return {
        {baud, target,
         QStringLiteral("%1 s (%2 ms an id, probe timeout %3 ms)%4")
             .arg(QString::number(s.elapsedMs / 1000.0, 'f', 2),
                  QString::number(s.elapsedMs / s.ids, 'f', 1))
             .arg(s.probeTimeoutMs)
             .arg(s.found ? QStringLiteral(", %1 found on a silent line").arg(s.found) : QString()),
         QStringLiteral("< 1.5 x %1 s = %2 s")
             .arg(QString::number(s.limitMs / 1000.0, 'f', 2),
                  QString::number(bound / 1000.0, 'f', 2)),
         QString::number(s.elapsedMs / s.limitMs, 'f', 2),
         judge(s.elapsedMs < bound && s.found == 0)}};
}

QList<Verdict> gapVerdicts(const GapResult &g)
{
    const BaudResult &r = g.r;
    const QString baud = QString::number(r.baud);
    if (!r.error.isEmpty())
        return {{baud, QStringLiteral("(i) gap-refusing controller"), r.error, QString(), QString(),
                 Verdict::Result::Error}};
    QList<Verdict> rows;
    cycleRows(r, &rows,
              QStringLiteral("(i) gap-refusing controller: live status cycle at full rate"),
              QStringLiteral("(i) gap-refusing controller: read-all"),
              QStringLiteral("gap-free optimum"), QStringLiteral(", same reads"));
    return rows;
}

QList<Verdict> answerTimeVerdicts(const BaudResult &r)
{
    const QString who = QStringLiteral("(k) controller answering in %1 ms").arg(r.answerDelayMs);
    if (!r.error.isEmpty())
        return {
            {QString::number(r.baud), who, r.error, QString(), QString(), Verdict::Result::Error}};
    QList<Verdict> rows;
    cycleRows(r, &rows, who + QStringLiteral(": live status cycle at full rate"),
              who + QStringLiteral(": read-all"),
              QStringLiteral("optimum at %1 ms").arg(r.answerDelayMs), QString());
    return rows;
}

QList<Verdict> firstStatusVerdicts(const FirstStatusResult &f)
{
    const QString baud = QString::number(f.baud);
    const QString target = QStringLiteral("(j) first status after the port opened");
    if (!f.error.isEmpty())
        return {{baud, target, f.error, QString(), QString(), Verdict::Result::Error}};
    // Every connect must show the positions in time: the max is judged.
    return {{baud, target,
             spanText(f.ms, QStringLiteral("connects")) +
                 QStringLiteral("; before the read-all: %1")
                     .arg(f.beforeReadAll ? QStringLiteral("yes") : QStringLiteral("NO")),
             QStringLiteral("max < 350 ms"),
             QString::number(f.ms.max / kFirstStatusTargetMs, 'f', 2),
             judge(f.beforeReadAll && f.ms.max < kFirstStatusTargetMs)}};
}

QString table(const QList<Verdict> &rows, bool judged)
{
    QString out = QStringLiteral("| baud | target | measured | model / bound | ratio | result |\n"
                                 "|---|---|---|---|---|---|\n");
    for (const Verdict &v : rows) {
        QString result;
        switch (v.result) {
        case Verdict::Result::Pass:
            result = QStringLiteral("PASS");
            break;
        case Verdict::Result::Fail:
            result = QStringLiteral("FAIL");
            break;
        case Verdict::Result::Info:
            result = QStringLiteral("info");
            break;
        case Verdict::Result::Error:
            result = QStringLiteral("ERROR");
            break;
        }
        if (!judged && (v.result == Verdict::Result::Pass || v.result == Verdict::Result::Fail))
            result += QStringLiteral(" (not judged)");
        out += QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 |\n")
                   .arg(v.baud, v.target, v.measured, v.bound, v.ratio, result);
    }
    return out;
}

QString machineLine()
{
    QString cpu;
    QFile info(QStringLiteral("/proc/cpuinfo"));
    if (info.open(QIODevice::ReadOnly)) {
        for (const QByteArray &line : info.readAll().split('\n')) {
            if (line.startsWith("model name")) {
                cpu = QString::fromUtf8(line.mid(line.indexOf(':') + 1).trimmed());
                break;
            }
        }
    }
    // Other work on the machine shows up in every number: say how busy it was.
    QString load;
    QFile loadavg(QStringLiteral("/proc/loadavg"));
    if (loadavg.open(QIODevice::ReadOnly))
        load = QString::fromLatin1(loadavg.readAll().split(' ').value(0));
    return QStringLiteral("Measured %1 on %2, %3 logical CPU(s), load average %4 at the end, "
                          "%5, Qt %6.")
        .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")),
             cpu.isEmpty() ? QSysInfo::currentCpuArchitecture() : cpu)
        .arg(QThread::idealThreadCount())
        .arg(load.isEmpty() ? QStringLiteral("unknown") : load, QSysInfo::prettyProductName(),
             QString::fromLatin1(qVersion()));
}

bool replaceResults(const QString &path, const QString &block, QString *error)
{
    const QByteArray begin = "<!-- bench:begin -->";
    const QByteArray end = "<!-- bench:end -->";
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly)) {
        *error = in.errorString();
        return false;
    }
    const QByteArray text = in.readAll();
    in.close();
    const qsizetype from = text.indexOf(begin);
    const qsizetype to = text.indexOf(end);
    if (from < 0 || to < from) {
        *error = QStringLiteral("%1 has no %2 ... %3 block")
                     .arg(path, QString::fromLatin1(begin), QString::fromLatin1(end));
        return false;
    }
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly)) {
        *error = out.errorString();
        return false;
    }
    out.write(text.left(from + begin.size()) + '\n' + block.toUtf8() + text.mid(to));
    if (!out.commit()) {
        *error = out.errorString();
        return false;
    }
    return true;
}

} // namespace stepcom::bench
