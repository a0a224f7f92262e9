#include "replay/replayviews.h"

#include "pages/plotpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionstatus.h"
#include "session/sessionlog.h"
#include "support/replaylog.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/docks/trafficview.h"
#include "widgets/plots/xyplot.h"

#include <QDateTime>

#include <deque>

namespace stepcom {

namespace {

constexpr qint64 kDayMs = 24 * 3600 * 1000;

// A line of the log as the traffic view shows a live one. Its clock as the log wrote it: a
// QDateTime in UTC holds it unchanged (no time zone to look up a hundred thousand times).
TrafficEntry entryOf(const LogLine &line)
{
    static const QHash<QByteArray, TrafficEntry::Kind> kinds = [] {
        QHash<QByteArray, TrafficEntry::Kind> k;
        for (const auto kind :
             {TrafficEntry::Kind::Event, TrafficEntry::Kind::Poll, TrafficEntry::Kind::Read,
              TrafficEntry::Kind::Write, TrafficEntry::Kind::Command, TrafficEntry::Kind::Error})
            k.insert(SessionLog::kindName(kind).toLatin1(), kind);
        return k;
    }();
    TrafficEntry e;
    e.time = QDateTime(QDate::fromJulianDay(line.stamp / kDayMs),
                       QTime::fromMSecsSinceStartOfDay(int(line.stamp % kDayMs)), Qt::UTC);
    e.summary = line.text;
    const auto kind = kinds.constFind(line.kind);
    if (kind != kinds.cend())
        e.kind = *kind;
    if (line.type == LogLine::Type::Frame) {
        e.direction = line.sent ? TrafficEntry::Direction::Sent : TrafficEntry::Direction::Received;
        e.bytes = line.bytes;
    } else if (kind == kinds.cend()) { // the session's own marks: "linkdown: the port vanished"
        e.summary = QStringLiteral("%1: %2").arg(QString::fromLatin1(line.kind), line.text);
    }
    return e;
}

bool shownInTraffic(const LogLine &line)
{
    return line.type == LogLine::Type::Frame || line.type == LogLine::Type::Mark;
}

} // namespace

ReplayViews::ReplayViews(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_traffic(new TrafficLog(this))
{
    m_traffic->setCapacity(kTrafficLines);
}

void ReplayViews::setTrafficView(TrafficView *view)
{
    m_view = view;
}

void ReplayViews::setDeviceList(DeviceListDock *list)
{
    m_deviceList = list;
}

void ReplayViews::setPlots(PlotPage *plots)
{
    m_plots = plots;
}

void ReplayViews::start(const ReplayLog *log, const std::function<void(int)> &choose)
{
    m_log = log;
    m_choose = choose;
    m_shownAt = -1;
    m_epochMs = QDateTime::fromString(log->startText(), QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz"))
                    .toMSecsSinceEpoch();
    m_traffic->clear();
    if (m_view)
        m_view->setLog(m_traffic);
}

void ReplayViews::stop()
{
    m_log = nullptr;
    m_shownAt = -1;
    m_firstLine = -1;
    if (m_view) {
        m_view->setEarlier({});
        m_view->setLog(m_session->connection()->traffic());
    }
    m_traffic->clear();
    m_session->status()->recorder()->clear();
    if (m_deviceList)
        m_deviceList->endReplay();
}

void ReplayViews::show(qint64 moment, int device, const QList<int> &devices,
                       const ReplayState &state)
{
    if (!m_log)
        return;
    // Playing on: what came since, unless the path would outgrow the XY plot's trace.
    const XYPlot *xy = m_plots ? m_plots->xyPlot() : nullptr;
    const bool roomInTrace = !xy || xy->traceCount() < xy->traceLimit() * 9 / 10;
    if (m_shownAt >= 0 && device == m_shownDevice && moment > m_shownAt &&
        moment - m_shownAt <= kFollowMs && roomInTrace)
        follow(m_shownAt, moment, device, state);
    else if (moment != m_shownAt || device != m_shownDevice)
        showAfresh(moment, device, state);
    m_shownAt = moment;
    m_shownDevice = device;
    showDevices(device, devices, state);
}

void ReplayViews::showAfresh(qint64 moment, int device, const ReplayState &state)
{
    // The traffic view: the last lines through the moment, read from a snapshot before them.
    std::deque<std::pair<TrafficEntry, qint64>> tail; // with its line number
    m_log->walkTail(moment, kTrafficLines,
                    [&tail](QByteArrayView, const LogLine &line, qint64, qint64 lineNo) {
                        if (shownInTraffic(line)) {
                            tail.emplace_back(entryOf(line), lineNo);
                            if (tail.size() > std::size_t(kTrafficLines))
                                tail.pop_front();
                        }
                        return true;
                    });
    m_traffic->clear();
    for (const auto &[entry, lineNo] : tail)
        m_traffic->add(entry);
    m_firstLine = tail.empty() ? -1 : tail.front().second;
    if (m_view) // scrolled back: the lines before these (enabled again)
        m_view->setEarlier([this] { return earlierLines(); });
    // The plots: the half hour the live recorder keeps, from the track (a run that began
    // before it from the window's start); the XY plot: the whole path.
    StatusRecorder *recorder = m_session->status()->recorder();
    recorder->clear();
    const ReplayTrack &track = m_log->track();
    const qint64 from = std::max<qint64>(0, moment - recorder->maxAgeMs());
    QList<StatusSample> samples = track.samples(device, from, moment, m_epochMs);
    if (samples.isEmpty() || samples.first().elapsedMs > from) {
        if (std::optional<StatusSample> before = track.sampleAt(device, from - 1, m_epochMs)) {
            before->elapsedMs = from;
            before->epochMs = m_epochMs + from;
            samples.prepend(*before);
        }
    }
    addLastAnswer(&samples, samples.isEmpty() ? -1 : samples.last().elapsedMs, device, state);
    recorder->addSamples(samples);
    if (m_plots) // drawn at the plot's resolution; playing on adds to it up to its limit
        m_plots->showTrace(track.path(device, moment, kTracePoints));
}

QList<TrafficEntry> ReplayViews::earlierLines()
{
    QList<TrafficEntry> lines;
    // Chunk after chunk back, until one holds a line the view shows (or the log begins).
    while (m_log && m_firstLine > 1 && lines.isEmpty()) {
        const qint64 before = m_firstLine;
        m_log->walkBefore(before, kTrafficLines,
                          [&](QByteArrayView, const LogLine &line, qint64, qint64 lineNo) {
                              m_firstLine = std::min(m_firstLine, lineNo);
                              if (shownInTraffic(line))
                                  lines << entryOf(line);
                              return true;
                          });
        if (m_firstLine == before) // nothing before it could be read
            break;
    }
    return lines;
}

void ReplayViews::follow(qint64 from, qint64 moment, int device, const ReplayState &state)
{
    m_log->walk(from + 1, moment,
                [this](QByteArrayView, const LogLine &line, qint64, const ReplayState &) {
                    if (shownInTraffic(line))
                        m_traffic->add(entryOf(line));
                    return true;
                });
    StatusRecorder *recorder = m_session->status()->recorder();
    QList<StatusSample> samples = m_log->track().samples(device, from + 1, moment, m_epochMs);
    const qint64 last = !samples.isEmpty()     ? samples.last().elapsedMs
                        : !recorder->isEmpty() ? recorder->last().elapsedMs
                                               : -1;
    addLastAnswer(&samples, last, device, state);
    recorder->addSamples(samples); // the plot page feeds its trace from them, as when live
}

void ReplayViews::addLastAnswer(QList<StatusSample> *samples, qint64 after, int device,
                                const ReplayState &state) const
{
    // The track keeps changes; the live recorder took a sample at every answer: its latest.
    const qint64 answered = state.devices.value(device).lastAnswerMs;
    if (answered <= after || answered < 0)
        return;
    if (std::optional<StatusSample> s = m_log->track().sampleAt(device, answered, m_epochMs)) {
        s->elapsedMs = answered;
        s->epochMs = m_epochMs + answered;
        samples->append(*s);
    }
}

void ReplayViews::showDevices(int device, const QList<int> &devices, const ReplayState &state)
{
    if (!m_deviceList)
        return;
    const RegisterMap &map = m_log->map();
    const QHash<int, QString> names = m_log->deviceNames();
    const int motors = map.blockCount(QStringLiteral("motor"));
    QHash<int, ReplayDeviceRow> rows;
    for (const int id : devices) {
        ReplayDeviceRow row;
        row.linkUp = state.linkUp;
        row.name = names.value(id);
        const auto it = state.devices.constFind(id);
        if (it != state.devices.cend()) {
            const ReplayDevice &d = *it;
            row.asked = d.requests > 0;
            row.answering = d.answering;
            row.requests = d.requests;
            row.errors = d.errors;
            if (!d.lastError.isEmpty())
                row.lastError =
                    QStringLiteral("%1: %2").arg(m_log->momentText(d.lastErrorMs), d.lastError);
            if (d.restartMs >= 0) {
                row.restartAt = m_log->momentText(d.restartMs);
                row.restartText = d.restartText;
            }
            // Its running flags as last read, and the motion command acknowledged last.
            const QHash<QString, qint64> values = d.values(map);
            for (int m = 1; m <= motors; ++m) {
                const Parameter *run =
                    map.blockParameter(QStringLiteral("motor"), m, QStringLiteral("running"));
                if (run && values.value(run->key) != 0)
                    row.runningMotors << m;
            }
            const Parameter *command = map.find(d.lastCommand);
            if (!row.runningMotors.isEmpty() && command && command->command == CommandClass::Motion)
                row.command = command->key; // the list names it in the language shown
        }
        rows.insert(id, row);
    }
    m_deviceList->showReplay(devices, rows, device, m_choose);
}

} // namespace stepcom
