#pragma once

#include "session/parts/sessionconnection.h" // TrafficLog, TrafficEntry

#include <QAbstractTableModel>
#include <QHash>
#include <QSet>
#include <QTimer>

#include <deque>

namespace stepcom {

// Rows of a TrafficLog for the Traffic dock: time, direction, raw bytes in hex, decoded
// summary. Keeps the last `capacity()` frames (an hour of polling at full rate and more) and
// shows those that pass the filters (kinds, search text). Frames are taken in batches a few
// times a second, so a fast poll costs the window one update per batch, not one per frame.
class TrafficModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    static constexpr int kDefaultCapacity = 250000;
    static constexpr int kBatchMs = 100;

    explicit TrafficModel(QObject *parent = nullptr);
    void setLog(TrafficLog *log);

    void setCapacity(int entries);
    int capacity() const { return m_capacity; }
    // Paused: the rows stand still; frames still arrive and are shown on resume.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Which kinds are shown (events always are); polls are hidden at first.
    void setKindShown(TrafficEntry::Kind kind, bool shown);
    bool isKindShown(TrafficEntry::Kind kind) const;
    // Only rows whose meaning or bytes contain this text (any case); empty: all.
    void setSearch(const QString &text);
    QString search() const { return m_search; }
    void clear();

    // Queues a frame; flush() (run by a timer) makes the rows.
    void append(const TrafficEntry &entry);
    // Frames from before the first one kept (a replay scrolled back), in order, as
    // many as there is room for below capacity() (the newest of them); the rows shown added.
    int prepend(const QList<TrafficEntry> &entries);
    void flush();
    int pendingCount() const { return int(m_pending.size()); }
    // Frames kept (shown or filtered out).
    int storedCount() const { return int(m_entries.size()); }
    const TrafficEntry &entryAt(int row) const;
    bool matches(const TrafficEntry &entry) const;

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

Q_SIGNALS:
    // Rows were added at the end (the view follows them unless paused).
    void appended();

private:
    void refilter();
    TrafficEntry shared(TrafficEntry entry);

    TrafficLog *m_log = nullptr;
    std::deque<TrafficEntry> m_entries; // every kept frame, oldest first
    std::deque<qint64> m_visible;       // sequence numbers of the shown ones
    qint64 m_firstSeq = 0;              // sequence number of m_entries.front()
    std::deque<TrafficEntry> m_pending;
    QSet<int> m_hiddenKinds;
    QString m_search;
    bool m_paused = false;
    int m_capacity = kDefaultCapacity;
    QTimer m_batch;
    // Polls repeat the same request text and bytes: one copy of each is shared by every row.
    QHash<QString, QString> m_texts;
    QHash<QByteArray, QByteArray> m_frames;
};

} // namespace stepcom
