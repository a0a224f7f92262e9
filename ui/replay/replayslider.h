#pragma once

#include "support/replaystate.h" // ReplayEvent

#include <QList>
#include <QSlider>

namespace stepcom {

// The replay's timeline: a slider over the log's duration in milliseconds with a
// marker for every event, coloured by its kind (writes, commands, E-STOP, errors, the link,
// restarts); a tooltip names the events under the pointer.
class ReplaySlider : public QSlider
{
    Q_OBJECT
public:
    explicit ReplaySlider(QWidget *parent = nullptr);

    void setEvents(const QList<ReplayEvent> &events, qint64 durationMs);
    int markerCount() const { return int(m_events.size()); }
    // The x of the moment `ms` on the groove, and the texts of the events drawn within a few
    // pixels of `x` (what the tooltip says there).
    int xOf(qint64 ms) const;
    QStringList textsAt(int x) const;
    static QColor colorOf(ReplayEvent::Kind kind);

protected:
    void paintEvent(QPaintEvent *event) override;
    bool event(QEvent *event) override;

private:
    QRect groove() const;

    QList<ReplayEvent> m_events;
    qint64 m_duration = 0;
};

} // namespace stepcom
