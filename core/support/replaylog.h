#pragma once

#include "map/registermap.h"
#include "support/replaydecoder.h"
#include "support/replaystate.h"
#include "support/replaytrack.h"

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

namespace stepcom {

// A session log opened for replay: the window's replay mode and `stepcomctl replay`
// stand on it. open() streams the file once -- never more than a line of it in memory -- and
// keeps the events (markers) and snapshots of the decoder, so stateAt() reads little of the
// file again: a 2 GB log opens in bounded memory and any moment
// is found in a few milliseconds. Logs without the session log's header (older StepCom) open
// with what they have.
class ReplayLog
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ReplayLog)
public:
    // What stops a log from opening; warnings (garbage lines, a cut last line) do not.
    enum class Problem { None, NotFound, Unreadable, Empty, NotALog, OtherMap, Cancelled };
    struct Callbacks
    {
        std::function<void(qint64 bytesDone, qint64 bytesTotal)> progress;
        std::function<bool()> cancelled; // asked between chunks; true stops the opening
    };
    // A snapshot every kSnapshotBytes, or every 1/kMaxSnapshots of a larger file (2 GB: 1 MiB),
    // so their memory stays bounded and a seek reads at most that much again.
    static constexpr qint64 kSnapshotBytes = 256 * 1024;
    static constexpr qint64 kMaxSnapshots = 2048;
    // Events kept at most; beyond it they are counted, not kept (a log of a dead line).
    static constexpr int kMaxEvents = 200000;

    explicit ReplayLog(const RegisterMap &map = RegisterMap::builtin());

    bool open(const QString &path, const Callbacks &callbacks = {});
    Problem problem() const { return m_problem; }
    QString errorString() const { return m_error; }
    // Garbage lines (counted, the first ones named by number), a last line cut short, events
    // not kept.
    QStringList warnings() const;
    qint64 garbageLines() const { return m_garbage; }
    QList<qint64> garbageLineNumbers() const { return m_garbageNumbers; }
    bool truncated() const { return m_truncated; }

    QString path() const { return m_path; }
    const RegisterMap &map() const { return *m_map; }
    // The "# key: value" header lines first seen ("program", "qt", "map", "line", "ids").
    QHash<QString, QString> header() const { return m_header; }
    // The first line's date and time ("2026-11-24 22:10:01.123") and the span to the last.
    QString startText() const;
    qint64 durationMs() const { return m_durationMs; }
    qint64 lineCount() const { return m_lines; }
    int snapshotCount() const { return int(m_snapshots.size()); }

    const QList<ReplayEvent> &events() const { return m_events; }
    // Each controller's status through the whole log, for the plots (gathered by open()).
    const ReplayTrack &track() const { return *m_track; }
    // The names the window's device list gave the ids ("# names:" in the header), if any.
    QHash<int, QString> deviceNames() const;
    // Every controller at `ms` since the start (past the end: the last state); reads the file
    // again from the snapshot before it.
    ReplayState stateAt(qint64 ms) const;
    // Every line from `fromMs` to `toMs` in order, with the state after it: the traffic view at
    // a moment (the raw line as written) and the plots up to it (the positions of each state).
    // `visit` returns false to stop. Reads from the snapshot before `fromMs`.
    using Visitor = std::function<bool(QByteArrayView raw, const LogLine &line, qint64 ms,
                                       const ReplayState &state)>;
    void walk(qint64 fromMs, qint64 toMs, const Visitor &visit) const;
    // Every line through `toMs` in order, from early enough that at least `lines` lines come
    // before the moment (from the start of a shorter log): the traffic view's last rows at a
    // moment. Reads from a snapshot, never the whole log, and decodes nothing (no state);
    // `visit` keeps the last ones it wants; `lineNo` is a line's number in the log.
    using LineVisitor =
        std::function<bool(QByteArrayView raw, const LogLine &line, qint64 ms, qint64 lineNo)>;
    void walkTail(qint64 toMs, qint64 lines, const LineVisitor &visit) const;
    // The `lines` lines before line number `beforeLine` (fewer at the start of the log), in
    // order, read from a snapshot: the traffic view scrolled back beyond its first row.
    void walkBefore(qint64 beforeLine, qint64 lines, const LineVisitor &visit) const;
    // "12.5" (seconds from the start) or a clock time "hh:mm:ss[.mmm]" (the first such moment
    // at or after the start) as ms since the start; nullopt and why not.
    std::optional<qint64> parseTime(const QString &text, QString *error) const;
    // An event's or a state's moment for people: "+12.345 s (22:10:13.468)".
    QString momentText(qint64 ms) const;

private:
    struct Snapshot
    {
        qint64 offset = 0; // the file position of the next line
        qint64 lineNo = 0; // the number of the last line read
        qint64 lastMs = 0;
        ReplayDecoder decoder;
    };
    // Reads lines from the snapshot on, into `snap`, until a line later than `untilMs` (< 0:
    // to the end), feeding `sink`. open() passes itself as `opening` (the checks, the index);
    // stateAt() passes nothing.
    // `visit` (optional) sees every line from `visitFromMs` on; false from it ends the scan.
    // Without `decode` the lines are only read (the state stays the snapshot's).
    bool scan(Snapshot &snap, qint64 untilMs, ReplayLog *opening, const Callbacks &callbacks,
              const ReplayDecoder::Sink &sink, const Visitor &visit = {}, qint64 visitFromMs = 0,
              bool decode = true) const;
    // The snapshot to read from for a moment.
    Snapshot snapshotBefore(qint64 ms) const;
    bool fail(Problem problem, const QString &text);
    void headerLine(const LogLine &line, qint64 lineNo);

    // Shared, so the snapshots' decoders point at it in every copy of this log.
    std::shared_ptr<const RegisterMap> m_map;
    QString m_path;
    Problem m_problem = Problem::None;
    QString m_error;
    qint64 m_fileSize = 0;
    qint64 m_snapshotBytes = kSnapshotBytes;
    qint64 m_startStamp = -1;
    qint64 m_durationMs = 0;
    qint64 m_lines = 0;
    qint64 m_validLines = 0;
    qint64 m_garbage = 0;
    QList<qint64> m_garbageNumbers;
    qint64 m_eventsDropped = 0;
    bool m_truncated = false;
    QHash<QString, QString> m_header;
    QList<ReplayEvent> m_events;
    QList<Snapshot> m_snapshots;          // the first at the start of the file
    std::shared_ptr<ReplayTrack> m_track; // shared by the copies: it does not change once open
};

} // namespace stepcom
