#include "support/replaylog.h"

#include "support/logline.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

namespace stepcom {

namespace {

constexpr qint64 kProgressBytes = 1024 * 1024;
constexpr int kNamedGarbage = 5;
constexpr int kLineBuffer = 64 * 1024;

// What a header line tells the decoder (read again by every scan, so snapshots need not).
void applyHeader(ReplayDecoder &decoder, const LogLine &line)
{
    if (line.key == "program")
        decoder.setMarked(true); // a log with the session's own marks
    if (line.key == "line") {
        if (line.text.contains(u"transport=tcp"))
            decoder.setFraming(ReplayDecoder::Framing::Tcp);
        else if (line.text.contains(u"transport=rtu"))
            decoder.setFraming(ReplayDecoder::Framing::Rtu);
    }
}

} // namespace

ReplayLog::ReplayLog(const RegisterMap &map)
    : m_map(std::make_shared<const RegisterMap>(map))
    , m_track(std::make_shared<ReplayTrack>(map))
{}

bool ReplayLog::fail(Problem problem, const QString &text)
{
    m_problem = problem;
    m_error = text;
    return false;
}

QStringList ReplayLog::warnings() const
{
    QStringList out;
    if (m_garbage > 0) {
        QStringList numbers;
        for (const qint64 n : m_garbageNumbers)
            numbers << QString::number(n);
        if (m_garbage > m_garbageNumbers.size())
            numbers << QStringLiteral("…");
        out << tr("lines not of a session log, skipped: %1 (line %2)")
                   .arg(m_garbage)
                   .arg(numbers.join(QStringLiteral(", ")));
    }
    if (m_truncated)
        out << tr("the log ends in the middle of line %1 (cut short?): that line is left out")
                   .arg(m_lines);
    if (m_eventsDropped > 0)
        out << tr("events not listed (too many): %1").arg(m_eventsDropped);
    return out;
}

QString ReplayLog::startText() const
{
    return m_startStamp < 0 ? QString() : LogLine::stampText(m_startStamp);
}

QString ReplayLog::momentText(qint64 ms) const
{
    const QString clock =
        m_startStamp < 0 ? QString() : LogLine::stampText(m_startStamp + ms).mid(11);
    return QStringLiteral("+%1 s (%2)").arg(double(ms) / 1000.0, 0, 'f', 3).arg(clock);
}

void ReplayLog::headerLine(const LogLine &line, qint64 lineNo)
{
    const QString key = QString::fromLatin1(line.key);
    if (!m_header.contains(key))
        m_header.insert(key, line.text);
    if (key == QLatin1String("map") && line.text != m_map->identity())
        fail(Problem::OtherMap,
             tr("line %1: the log was recorded with the register map %2, not with %3 (open it "
                "with that map)")
                 .arg(lineNo)
                 .arg(line.text, m_map->identity()));
}

bool ReplayLog::open(const QString &path, const Callbacks &callbacks)
{
    *this = ReplayLog(*m_map);
    m_path = path;
    const QFileInfo info(path);
    if (!info.exists())
        return fail(Problem::NotFound, tr("%1: no such file").arg(path));
    m_fileSize = info.size();
    m_snapshotBytes = std::max(kSnapshotBytes, m_fileSize / kMaxSnapshots);
    if (m_fileSize == 0)
        return fail(Problem::Empty, tr("%1 is empty").arg(path));
    Snapshot snap;
    snap.decoder = ReplayDecoder(m_map.get());
    m_snapshots.append(snap);
    const auto sink = [this](const ReplayEvent &e) {
        if (m_events.size() < kMaxEvents)
            m_events.append(e);
        else
            ++m_eventsDropped;
    };
    if (!scan(snap, -1, this, callbacks, sink))
        return false;
    m_lines = snap.lineNo;
    m_durationMs = snap.lastMs;
    m_track->finish();
    if (m_validLines == 0) {
        QFile f(path);
        const bool zip =
            f.open(QIODevice::ReadOnly) && f.read(4) == QByteArrayLiteral("PK\x03\x04");
        if (zip)
            return fail(Problem::NotALog,
                        tr("%1 is a zip file, not a session log (a support bundle? open it as "
                           "one)")
                            .arg(path));
        if (!m_header.isEmpty())
            return fail(Problem::Empty, tr("%1 holds no frames, only its header").arg(path));
        return fail(Problem::NotALog,
                    tr("%1 is not a StepCom session log: not one of its lines is one (%2 "
                       "lines)")
                        .arg(path)
                        .arg(m_lines));
    }
    if (callbacks.progress)
        callbacks.progress(m_fileSize, m_fileSize);
    return true;
}

bool ReplayLog::scan(Snapshot &snap, qint64 untilMs, ReplayLog *opening, const Callbacks &callbacks,
                     const ReplayDecoder::Sink &sink, const Visitor &visit, qint64 visitFromMs,
                     bool decode) const
{
    QFile file(m_path);
    if (!file.open(QIODevice::ReadOnly) || !file.seek(snap.offset))
        return opening ? opening->fail(Problem::Unreadable,
                                       tr("cannot read %1: %2").arg(m_path, file.errorString()))
                       : false;
    QByteArray buffer(kLineBuffer, Qt::Uninitialized);
    qint64 offset = snap.offset;
    qint64 nextSnapshot = offset + m_snapshotBytes;
    qint64 nextProgress = offset + kProgressBytes;
    for (;;) {
        const qint64 n = file.readLine(buffer.data(), buffer.size());
        if (n <= 0)
            break;
        QByteArrayView chunk(buffer.constData(), n);
        bool complete = chunk.back() == '\n';
        qint64 length = n;
        bool tooLong = false;
        while (!complete && n == buffer.size() - 1) {
            // Longer than any line StepCom writes: read past it, it is garbage.
            tooLong = true;
            const qint64 more = file.readLine(buffer.data(), buffer.size());
            if (more <= 0)
                break;
            length += more;
            complete = buffer.at(more - 1) == '\n';
            if (more < buffer.size() - 1)
                break;
        }
        offset += length;
        ++snap.lineNo;
        if (!complete && !tooLong) {
            if (opening)
                opening->m_truncated = true; // the last line, cut short
            break;
        }
        const LogLine line = tooLong ? LogLine() : LogLine::parse(chunk);
        qint64 ms = snap.lastMs;
        if (line.type == LogLine::Type::Frame || line.type == LogLine::Type::Mark) {
            if (opening && m_startStamp < 0)
                opening->m_startStamp = line.stamp;
            ms = std::max(line.stamp - m_startStamp, snap.lastMs); // a clock set back
            if (untilMs >= 0 && ms > untilMs)
                return true;
            snap.lastMs = ms;
            if (opening)
                ++opening->m_validLines;
        } else if (line.type == LogLine::Type::Header) {
            applyHeader(snap.decoder, line);
            if (opening) {
                opening->headerLine(line, snap.lineNo);
                if (m_problem != Problem::None)
                    return false;
            }
        } else if (line.type == LogLine::Type::Garbage && opening) {
            if (m_garbageNumbers.size() < kNamedGarbage)
                opening->m_garbageNumbers << snap.lineNo;
            ++opening->m_garbage;
        }
        if (decode)
            snap.decoder.feed(line, ms, snap.lineNo, sink);
        snap.offset = offset;
        if (opening && snap.decoder.answeredUnit() != 0) {
            const int unit = snap.decoder.answeredUnit();
            opening->m_track->add(unit, ms, *snap.decoder.state().devices.constFind(unit));
        }
        if (visit && ms >= visitFromMs && !visit(chunk, line, ms, snap.decoder.state()))
            return true;
        if (!opening)
            continue;
        if (offset >= nextSnapshot) {
            opening->m_snapshots.append(snap);
            nextSnapshot = offset + m_snapshotBytes;
        }
        if (offset >= nextProgress) {
            nextProgress = offset + kProgressBytes;
            if (callbacks.progress)
                callbacks.progress(offset, m_fileSize);
            if (callbacks.cancelled && callbacks.cancelled())
                return opening->fail(Problem::Cancelled,
                                     tr("opening %1 was cancelled").arg(m_path));
        }
    }
    return true;
}

ReplayState ReplayLog::stateAt(qint64 ms) const
{
    if (m_snapshots.isEmpty())
        return {};
    ms = std::clamp<qint64>(ms, 0, m_durationMs);
    Snapshot snap = snapshotBefore(ms);
    scan(snap, ms, nullptr, {}, {});
    ReplayState state = snap.decoder.state();
    state.ms = ms;
    return state;
}

ReplayLog::Snapshot ReplayLog::snapshotBefore(qint64 ms) const
{
    // The last snapshot before `ms`: everything before it is before `ms` too. (A line at `ms`
    // itself may follow a snapshot at `ms`: walk() must see it.)
    auto it = std::lower_bound(m_snapshots.cbegin(), m_snapshots.cend(), ms,
                               [](const Snapshot &s, qint64 t) { return s.lastMs < t; });
    return it == m_snapshots.cbegin() ? m_snapshots.first() : *std::prev(it);
}

void ReplayLog::walk(qint64 fromMs, qint64 toMs, const Visitor &visit) const
{
    if (m_snapshots.isEmpty() || !visit)
        return;
    Snapshot snap = snapshotBefore(fromMs);
    scan(snap, toMs, nullptr, {}, {}, visit, fromMs);
}

void ReplayLog::walkTail(qint64 toMs, qint64 lines, const LineVisitor &visit) const
{
    if (m_snapshots.isEmpty() || !visit)
        return;
    // The snapshot before the moment, then one at least `lines` lines before that.
    const Snapshot &near = snapshotBefore(toMs);
    const qint64 wanted = near.lineNo - lines;
    auto it = std::upper_bound(m_snapshots.cbegin(), m_snapshots.cend(), wanted,
                               [](qint64 line, const Snapshot &s) { return line < s.lineNo; });
    Snapshot snap = it == m_snapshots.cbegin() ? m_snapshots.first() : *std::prev(it);
    scan(
        snap, toMs, nullptr, {}, {},
        [&visit, &snap](QByteArrayView raw, const LogLine &line, qint64 ms, const ReplayState &) {
            return visit(raw, line, ms, snap.lineNo);
        },
        0, false);
}

void ReplayLog::walkBefore(qint64 beforeLine, qint64 lines, const LineVisitor &visit) const
{
    const qint64 first = std::max<qint64>(1, beforeLine - lines);
    if (m_snapshots.isEmpty() || !visit || first >= beforeLine)
        return;
    // The last snapshot whose next line is the first one wanted or before it.
    auto it = std::upper_bound(m_snapshots.cbegin(), m_snapshots.cend(), first - 1,
                               [](qint64 line, const Snapshot &s) { return line < s.lineNo; });
    Snapshot snap = it == m_snapshots.cbegin() ? m_snapshots.first() : *std::prev(it);
    scan(
        snap, -1, nullptr, {}, {},
        [&](QByteArrayView raw, const LogLine &line, qint64 ms, const ReplayState &) {
            if (snap.lineNo >= beforeLine)
                return false;
            return snap.lineNo < first || visit(raw, line, ms, snap.lineNo);
        },
        0, false);
}

QHash<int, QString> ReplayLog::deviceNames() const
{
    QHash<int, QString> names;
    const QJsonObject o =
        QJsonDocument::fromJson(m_header.value(QStringLiteral("names")).toUtf8()).object();
    for (auto it = o.begin(); it != o.end(); ++it) {
        bool ok = false;
        const int id = it.key().toInt(&ok);
        if (ok && it.value().isString() && !it.value().toString().trimmed().isEmpty())
            names.insert(id, it.value().toString().trimmed());
    }
    return names;
}

std::optional<qint64> ReplayLog::parseTime(const QString &text, QString *error) const
{
    static const QRegularExpression seconds(QStringLiteral("^\\d+(\\.\\d+)?$"));
    static const QRegularExpression clock(
        QStringLiteral("^(\\d{1,2}):(\\d{2}):(\\d{2})(?:\\.(\\d{1,3}))?$"));
    const QString t = text.trimmed();
    if (seconds.match(t).hasMatch())
        return qRound64(t.toDouble() * 1000.0);
    const QRegularExpressionMatch m = clock.match(t);
    if (!m.hasMatch() || m.captured(1).toInt() > 23 || m.captured(2).toInt() > 59 ||
        m.captured(3).toInt() > 59) {
        if (error)
            *error = tr("'%1' is not a time: give seconds from the start (12.5) or a clock time "
                        "hh:mm:ss[.mmm]")
                         .arg(text);
        return std::nullopt;
    }
    const qint64 ofDay =
        ((m.captured(1).toInt() * 60 + m.captured(2).toInt()) * 60 + m.captured(3).toInt()) * 1000 +
        m.captured(4).leftJustified(3, QLatin1Char('0')).toInt();
    qint64 at = (m_startStamp / LogLine::kDayMs) * LogLine::kDayMs + ofDay;
    if (at < m_startStamp) {
        // The next day's, when the log reaches it.
        if (at + LogLine::kDayMs > m_startStamp + m_durationMs) {
            if (error)
                *error = tr("%1 is before the log's start (%2)").arg(text, startText());
            return std::nullopt;
        }
        at += LogLine::kDayMs;
    }
    return at - m_startStamp;
}

} // namespace stepcom
