#include "widgets/docks/trafficmodel.h"

#include <QBrush>
#include <QColor>

namespace stepcom {

TrafficModel::TrafficModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_hiddenKinds.insert(int(TrafficEntry::Kind::Poll));
    m_batch.setInterval(kBatchMs);
    m_batch.setSingleShot(true);
    connect(&m_batch, &QTimer::timeout, this, &TrafficModel::flush);
}

void TrafficModel::setLog(TrafficLog *log)
{
    if (m_log)
        m_log->disconnect(this);
    m_log = log;
    // Another log (a replay's, then the session's again): its rows, not the last one's.
    clear();
    if (!m_log)
        return;
    for (const TrafficEntry &e : m_log->entries())
        append(e);
    connect(m_log, &TrafficLog::entryAdded, this, &TrafficModel::append);
    connect(m_log, &TrafficLog::cleared, this, &TrafficModel::clear);
}

void TrafficModel::setCapacity(int entries)
{
    m_capacity = std::max(100, entries);
    flush();
}

void TrafficModel::setPaused(bool paused)
{
    m_paused = paused;
    if (!paused)
        flush();
}

void TrafficModel::setKindShown(TrafficEntry::Kind kind, bool shown)
{
    if (kind == TrafficEntry::Kind::Event || shown == isKindShown(kind))
        return;
    if (shown)
        m_hiddenKinds.remove(int(kind));
    else
        m_hiddenKinds.insert(int(kind));
    refilter();
}

bool TrafficModel::isKindShown(TrafficEntry::Kind kind) const
{
    return !m_hiddenKinds.contains(int(kind));
}

void TrafficModel::setSearch(const QString &text)
{
    if (text == m_search)
        return;
    m_search = text;
    refilter();
}

void TrafficModel::clear()
{
    beginResetModel();
    m_firstSeq += qint64(m_entries.size());
    m_entries.clear();
    m_visible.clear();
    m_pending.clear();
    m_texts.clear();
    m_frames.clear();
    endResetModel();
}

TrafficEntry TrafficModel::shared(TrafficEntry entry)
{
    if (m_texts.size() > 4096)
        m_texts.clear();
    if (m_frames.size() > 4096)
        m_frames.clear();
    auto text = m_texts.constFind(entry.summary);
    if (text == m_texts.constEnd())
        text = m_texts.insert(entry.summary, entry.summary);
    entry.summary = *text;
    if (!entry.bytes.isEmpty()) {
        auto frame = m_frames.constFind(entry.bytes);
        if (frame == m_frames.constEnd())
            frame = m_frames.insert(entry.bytes, entry.bytes);
        entry.bytes = *frame;
    }
    return entry;
}

void TrafficModel::append(const TrafficEntry &entry)
{
    m_pending.push_back(shared(entry));
    while (int(m_pending.size()) > m_capacity)
        m_pending.pop_front();
    if (!m_paused && !m_batch.isActive())
        m_batch.start();
}

int TrafficModel::prepend(const QList<TrafficEntry> &entries)
{
    const qsizetype room = m_capacity - qsizetype(m_entries.size() + m_pending.size());
    const qsizetype take = std::clamp<qsizetype>(room, 0, entries.size());
    std::deque<qint64> shown;
    for (qsizetype i = entries.size() - 1, seq = m_firstSeq - 1; i >= entries.size() - take;
         --i, --seq) {
        m_entries.push_front(shared(entries.at(i)));
        if (matches(m_entries.front()))
            shown.push_front(seq);
    }
    m_firstSeq -= take;
    if (shown.empty())
        return 0;
    beginInsertRows({}, 0, int(shown.size()) - 1);
    m_visible.insert(m_visible.begin(), shown.begin(), shown.end());
    endInsertRows();
    return int(shown.size());
}

bool TrafficModel::matches(const TrafficEntry &entry) const
{
    if (m_hiddenKinds.contains(int(entry.kind)))
        return false;
    if (m_search.isEmpty())
        return true;
    return entry.summary.contains(m_search, Qt::CaseInsensitive) ||
           QString::fromLatin1(entry.bytes.toHex(' ')).contains(m_search, Qt::CaseInsensitive);
}

void TrafficModel::flush()
{
    m_batch.stop();
    if (m_paused)
        return;
    // Oldest frames go first, and their rows with them.
    const qint64 incoming = qint64(m_pending.size());
    const qint64 excess = qint64(m_entries.size()) + incoming - m_capacity;
    if (excess > 0) {
        const qint64 dropEntries = std::min<qint64>(excess, qint64(m_entries.size()));
        const qint64 newFirst = m_firstSeq + dropEntries;
        int rows = 0;
        while (rows < int(m_visible.size()) && m_visible.at(rows) < newFirst)
            ++rows;
        if (rows > 0)
            beginRemoveRows({}, 0, rows - 1);
        m_entries.erase(m_entries.begin(), m_entries.begin() + dropEntries);
        m_visible.erase(m_visible.begin(), m_visible.begin() + rows);
        m_firstSeq = newFirst;
        if (rows > 0)
            endRemoveRows();
    }
    std::deque<qint64> shown;
    qint64 seq = m_firstSeq + qint64(m_entries.size());
    for (TrafficEntry &e : m_pending) {
        if (matches(e))
            shown.push_back(seq);
        m_entries.push_back(std::move(e));
        ++seq;
    }
    m_pending.clear();
    if (shown.empty())
        return;
    const int first = int(m_visible.size());
    beginInsertRows({}, first, first + int(shown.size()) - 1);
    m_visible.insert(m_visible.end(), shown.begin(), shown.end());
    endInsertRows();
    Q_EMIT appended();
}

void TrafficModel::refilter()
{
    beginResetModel();
    m_visible.clear();
    qint64 seq = m_firstSeq;
    for (const TrafficEntry &e : m_entries) {
        if (matches(e))
            m_visible.push_back(seq);
        ++seq;
    }
    endResetModel();
}

const TrafficEntry &TrafficModel::entryAt(int row) const
{
    return m_entries.at(std::size_t(m_visible.at(std::size_t(row)) - m_firstSeq));
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_visible.size());
}

int TrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : 4;
}

QVariant TrafficModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_visible.size()))
        return {};
    const TrafficEntry &e = entryAt(index.row());
    // Long frames are cut in the table (the meaning must stay in view): the whole text on hover.
    if (role == Qt::ToolTipRole && index.column() >= 2)
        return data(index, Qt::DisplayRole);
    if (role == Qt::ForegroundRole && e.kind == TrafficEntry::Kind::Error)
        return QBrush(QColor(200, 30, 30));
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case 0:
            return e.time.toString(QStringLiteral("HH:mm:ss.zzz"));
        case 1:
            return e.direction == TrafficEntry::Direction::Sent       ? QStringLiteral("TX")
                   : e.direction == TrafficEntry::Direction::Received ? QStringLiteral("RX")
                                                                      : QStringLiteral("—");
        case 2:
            return QString::fromLatin1(e.bytes.toHex(' ').toUpper());
        case 3:
            return e.summary;
        }
    }
    return {};
}

QVariant TrafficModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case 0:
        return tr("Time");
    case 1:
        return tr("Dir");
    case 2:
        return tr("Bytes (hex)");
    case 3:
        return tr("Meaning");
    }
    return {};
}

} // namespace stepcom
