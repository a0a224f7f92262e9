#pragma once

#include "device/statusrecorder.h" // StatusColumns, StatusSample

#include <QList>
#include <QMap>
#include <QPointF>

#include <optional>
#include <vector>

namespace stepcom {

class Parameter;
class RegisterMap;
struct ReplayDevice;

// The status of each controller through a whole session log -- what the plots show up to a
// moment of a replay -- gathered once while ReplayLog opens the log, so a seek reads
// nothing of the file again for the plots. A sample (the StatusRecorder's columns: positions,
// running flags, inputs, outputs) after every answer that changed one of them; an unchanged run
// longer than kRunMs keeps its last answer too, so the lines drawn between samples are the ones
// the live plot drew. About 32 bytes a sample; beyond maxSamples() over all devices every other
// one is dropped (the first and the last stay) and new ones come no closer than the spacing left:
// a long log stays in bounded memory, a gross view of its oldest part.
class ReplayTrack
{
public:
    static constexpr qint64 kRunMs = 1000;
    static constexpr qsizetype kMaxSamples = 1000000;
    static constexpr int kPathResolution = 2000;

    ReplayTrack() = default;
    explicit ReplayTrack(const RegisterMap &map);
    void setMaxSamples(qsizetype samples) { m_maxSamples = std::max<qsizetype>(16, samples); }
    qsizetype maxSamples() const { return m_maxSamples; }

    // After an answer of controller `id` at `ms` (in time order), with what it holds then.
    void add(int id, qint64 ms, const ReplayDevice &device);
    // The end of the log: every run's last answer kept.
    void finish();

    QList<int> devices() const { return m_tracks.keys(); }
    qsizetype size(int id) const;
    qsizetype totalSize() const { return m_total; }
    // Thinned to stay within maxSamples() (the spacing kept, ms; 0: every change is kept).
    qint64 thinnedToMs() const { return m_minGapMs; }

    // The samples of `id` from `fromMs` through `toMs`, as StatusRecorder keeps them: elapsedMs
    // the log's ms, epochMs that plus `epochMs` (the wall-clock time of the log's start).
    QList<StatusSample> samples(int id, qint64 fromMs, qint64 toMs, qint64 epochMs) const;
    // The last sample of `id` at or before `ms`, if any.
    std::optional<StatusSample> sampleAt(int id, qint64 ms, qint64 epochMs) const;
    // The tool's path (motor 1 = x, motor 2 = y) from the start of the log through `toMs`, a
    // point each time it moved. More than `maxPoints`: points closer to the last one kept than
    // 1/kPathResolution of the path's extent are left out (finer than a plot shows), then, if
    // still too many, the rest thinned evenly; the first and the last point always stay.
    QList<QPointF> path(int id, qint64 toMs, int maxPoints) const;

private:
    struct Track
    {
        std::vector<qint64> cells; // per sample: ms, each position (raw), the flag bits
        bool held = false;         // an answer not kept yet (a run going on, or thinned)
        std::vector<qint64> heldCells;
    };
    void push(Track &t, const qint64 *cells);
    void thin();
    qsizetype count(const Track &t) const { return qsizetype(t.cells.size()) / m_stride; }
    const qint64 *at(const Track &t, qsizetype i) const { return t.cells.data() + i * m_stride; }
    // Index of the first sample later than `ms`.
    qsizetype upperBound(const Track &t, qint64 ms) const;
    bool sameStatus(const qint64 *a, const qint64 *b) const;
    StatusSample sampleOf(const qint64 *cells, qint64 epochMs, const StatusSample *previous) const;

    int m_motors = 0;
    QList<const Parameter *> m_positions;
    QList<int> m_scale;
    QList<const Parameter *> m_flags; // running (per motor), inputs, outputs
    int m_runningCount = 0;
    int m_inputCount = 0;
    int m_bitWords = 0;
    int m_stride = 1;
    QMap<int, Track> m_tracks;
    qsizetype m_total = 0;
    qsizetype m_maxSamples = kMaxSamples;
    qint64 m_minGapMs = 0;
};

} // namespace stepcom
