#include "support/replaytrack.h"

#include "map/registermap.h"
#include "support/replaystate.h"

#include <QVarLengthArray>

#include <cmath>
#include <limits>

namespace stepcom {

namespace {

using Cells = QVarLengthArray<qint64, 16>;

// The raw value of `p` in what the controller holds, when all of its words are known.
bool rawOf(const Parameter *p, const QMap<quint16, quint16> &words, qint64 *raw)
{
    if (!p)
        return false;
    quint16 w[2] = {0, 0};
    for (int i = 0; i < p->words && i < 2; ++i) {
        const auto it = words.constFind(quint16(p->address + i));
        if (it == words.cend())
            return false;
        w[i] = it.value();
    }
    *raw = p->decode(w);
    return true;
}

void setBit(qint64 *words, int bit)
{
    words[bit / 64] |= qint64(quint64(1) << (bit % 64));
}

bool bit(const qint64 *words, int bit)
{
    return (quint64(words[bit / 64]) >> (bit % 64)) & 1;
}

} // namespace

ReplayTrack::ReplayTrack(const RegisterMap &map)
{
    const StatusColumns columns(map);
    m_motors = columns.motors();
    for (const QString &key : columns.positionKeys)
        m_positions << map.find(key);
    m_scale = columns.positionScale;
    for (const QString &key : columns.runningKeys)
        m_flags << (key.isEmpty() ? nullptr : map.find(key));
    for (const QString &key : columns.inputKeys)
        m_flags << map.find(key);
    for (const QString &key : columns.outputKeys)
        m_flags << map.find(key);
    m_runningCount = m_motors;
    m_inputCount = int(columns.inputKeys.size());
    // A position known: 1 bit; a flag: known and its value.
    m_bitWords = (m_motors + 2 * int(m_flags.size()) + 63) / 64;
    m_stride = 1 + m_motors + m_bitWords;
}

qsizetype ReplayTrack::size(int id) const
{
    const auto it = m_tracks.constFind(id);
    return it == m_tracks.cend() ? 0 : count(*it);
}

bool ReplayTrack::sameStatus(const qint64 *a, const qint64 *b) const
{
    return std::equal(a + 1, a + m_stride, b + 1);
}

void ReplayTrack::add(int id, qint64 ms, const ReplayDevice &device)
{
    Cells cells(m_stride, 0);
    cells[0] = ms;
    qint64 *bits = cells.data() + 1 + m_motors;
    for (int m = 0; m < m_motors; ++m) {
        if (rawOf(m_positions.at(m), device.words, &cells[1 + m]))
            setBit(bits, m);
    }
    for (int f = 0; f < m_flags.size(); ++f) {
        qint64 raw = 0;
        if (!rawOf(m_flags.at(f), device.words, &raw))
            continue;
        setBit(bits, m_motors + 2 * f);
        if (raw != 0)
            setBit(bits, m_motors + 2 * f + 1);
    }
    Track &t = m_tracks[id];
    if (t.cells.empty()) {
        push(t, cells.constData());
        return;
    }
    // Worth keeping after the last sample kept: a change (no closer than the spacing a thinned
    // track keeps), or the end of a run that lasted.
    const auto worth = [this, &t](const qint64 *s) {
        const qint64 *last = at(t, count(t) - 1);
        const qint64 gap = s[0] - last[0];
        return sameStatus(s, last) ? gap >= std::max(kRunMs, m_minGapMs) : gap >= m_minGapMs;
    };
    if (!sameStatus(cells.constData(), at(t, count(t) - 1)) && worth(cells.constData())) {
        if (t.held && worth(t.heldCells.data()))
            push(t, t.heldCells.data());
        t.held = false;
        push(t, cells.constData());
        return;
    }
    t.held = true;
    t.heldCells.assign(cells.cbegin(), cells.cend());
}

void ReplayTrack::push(Track &t, const qint64 *cells)
{
    t.cells.insert(t.cells.end(), cells, cells + m_stride);
    if (++m_total > m_maxSamples)
        thin();
}

void ReplayTrack::thin()
{
    qint64 span = 0;
    m_total = 0;
    for (Track &t : m_tracks) {
        const qsizetype n = count(t);
        qsizetype kept = 0;
        for (qsizetype i = 0; i < n; ++i) {
            if (i % 2 != 0 && i != n - 1)
                continue;
            if (kept != i)
                std::copy(at(t, i), at(t, i) + m_stride, t.cells.begin() + kept * m_stride);
            ++kept;
        }
        t.cells.resize(std::size_t(kept * m_stride));
        t.cells.shrink_to_fit();
        m_total += kept;
        if (kept > 1)
            span += at(t, kept - 1)[0] - at(t, 0)[0];
    }
    // New samples no closer than the old ones are now: the track stays even.
    m_minGapMs = std::max<qint64>({2 * m_minGapMs, span / std::max<qsizetype>(1, m_total), 1});
}

void ReplayTrack::finish()
{
    for (Track &t : m_tracks) {
        if (t.held && t.heldCells.front() > at(t, count(t) - 1)[0])
            push(t, t.heldCells.data());
        t.held = false;
        t.heldCells.clear();
    }
}

qsizetype ReplayTrack::upperBound(const Track &t, qint64 ms) const
{
    qsizetype lo = 0;
    qsizetype hi = count(t);
    while (lo < hi) {
        const qsizetype mid = (lo + hi) / 2;
        if (at(t, mid)[0] <= ms)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

StatusSample ReplayTrack::sampleOf(const qint64 *c, qint64 epochMs,
                                   const StatusSample *previous) const
{
    const qint64 *bits = c + 1 + m_motors;
    // The flags as the previous sample's when they are the same (they seldom change): its
    // vectors shared, not allocated again -- a seek makes tens of thousands of samples.
    const auto flags = [&](int from, int count, const QVector<qint8> *same) {
        QVarLengthArray<qint8, 32> v(count);
        for (int n = 0; n < count; ++n) {
            const int f = from + n;
            v[n] = bit(bits, m_motors + 2 * f) ? qint8(bit(bits, m_motors + 2 * f + 1)) : qint8(-1);
        }
        if (same && same->size() == count && std::equal(v.cbegin(), v.cend(), same->cbegin()))
            return *same;
        return QVector<qint8>(v.cbegin(), v.cend());
    };
    const int outputs = int(m_flags.size()) - m_runningCount - m_inputCount;
    StatusSample s;
    s.elapsedMs = c[0];
    s.epochMs = epochMs + c[0];
    s.positions.resize(m_motors);
    for (int m = 0; m < m_motors; ++m)
        s.positions[m] = bit(bits, m) ? double(c[1 + m]) / m_scale.at(m)
                                      : std::numeric_limits<double>::quiet_NaN();
    s.running = flags(0, m_runningCount, previous ? &previous->running : nullptr);
    s.inputs = flags(m_runningCount, m_inputCount, previous ? &previous->inputs : nullptr);
    s.outputs =
        flags(m_runningCount + m_inputCount, outputs, previous ? &previous->outputs : nullptr);
    return s;
}

QList<StatusSample> ReplayTrack::samples(int id, qint64 fromMs, qint64 toMs, qint64 epochMs) const
{
    QList<StatusSample> out;
    const auto it = m_tracks.constFind(id);
    if (it == m_tracks.cend() || toMs < fromMs)
        return out;
    const qsizetype from = upperBound(*it, fromMs - 1);
    const qsizetype to = upperBound(*it, toMs);
    out.reserve(std::max<qsizetype>(0, to - from));
    for (qsizetype i = from; i < to; ++i)
        out << sampleOf(at(*it, i), epochMs, out.isEmpty() ? nullptr : &out.constLast());
    return out;
}

std::optional<StatusSample> ReplayTrack::sampleAt(int id, qint64 ms, qint64 epochMs) const
{
    const auto it = m_tracks.constFind(id);
    if (it == m_tracks.cend())
        return std::nullopt;
    const qsizetype i = upperBound(*it, ms);
    if (i == 0)
        return std::nullopt;
    return sampleOf(at(*it, i - 1), epochMs, nullptr);
}

QList<QPointF> ReplayTrack::path(int id, qint64 toMs, int maxPoints) const
{
    QList<QPointF> points;
    const auto it = m_tracks.constFind(id);
    if (it == m_tracks.cend() || m_motors < 2)
        return points;
    const qsizetype to = upperBound(*it, toMs);
    for (qsizetype i = 0; i < to; ++i) {
        const qint64 *c = at(*it, i);
        const qint64 *bits = c + 1 + m_motors;
        if (!bit(bits, 0) || !bit(bits, 1))
            continue;
        const QPointF p(double(c[1]) / m_scale.at(0), double(c[2]) / m_scale.at(1));
        if (points.isEmpty() || points.last() != p)
            points << p;
    }
    maxPoints = std::max(4, maxPoints);
    if (points.size() <= maxPoints)
        return points;
    // Finer than any plot shows: points closer than 1/kPathResolution of the extent to the last
    // one kept are left out (the last point always stays).
    QPointF low = points.first();
    QPointF high = low;
    for (const QPointF &p : std::as_const(points)) {
        low = QPointF(std::min(low.x(), p.x()), std::min(low.y(), p.y()));
        high = QPointF(std::max(high.x(), p.x()), std::max(high.y(), p.y()));
    }
    const double near = std::max(high.x() - low.x(), high.y() - low.y()) / kPathResolution;
    QList<QPointF> kept{points.first()};
    for (qsizetype i = 1; i + 1 < points.size(); ++i) {
        const QPointF d = points.at(i) - kept.last();
        if (std::hypot(d.x(), d.y()) >= near)
            kept << points.at(i);
    }
    kept << points.last();
    if (kept.size() <= maxPoints)
        return kept;
    // Still too many (a path over and over the same ground): evenly thinned, the ends kept.
    QList<QPointF> thinned;
    thinned.reserve(maxPoints);
    for (qsizetype k = 0; k < maxPoints - 1; ++k)
        thinned << kept.at(k * (kept.size() - 1) / (maxPoints - 1));
    thinned << kept.last();
    return thinned;
}

} // namespace stepcom
