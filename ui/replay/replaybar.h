#pragma once

#include "support/replaystate.h" // ReplayEvent

#include <QFrame>
#include <QTimer>

#include <functional>

class QComboBox;
class QHBoxLayout;
class QLabel;
class QToolButton;

namespace stepcom {

class ReplaySlider;

// The replay's controls under the pages: play/pause, the speed (1×, 4×, 16×), a
// frame back and on, the timeline with its event markers, the moment in words, the events in a
// list with the one before and after, and the device shown when the log has several. A view: it
// asks for moments (seekRequested, stepFrame, deviceChosen) and shows the one it is given.
class ReplayBar : public QFrame
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 100; // playing: one step of the moment every tick
    // The list names at most this many events (a dead line logs thousands of timeouts); the
    // timeline and Event ◀ ▶ reach every one.
    static constexpr int kListedEvents = 2000;

    explicit ReplayBar(QWidget *parent = nullptr);

    // What the log holds: its length, its events, how a moment reads, its devices.
    void setLog(qint64 durationMs, const QList<ReplayEvent> &events, const QList<int> &devices,
                std::function<QString(qint64)> momentText);
    // The moment shown (the slider, the text, the event list follow; no signal).
    void setMoment(qint64 ms);
    qint64 moment() const { return m_moment; }
    void setDevice(int id);

    bool isPlaying() const { return m_timer.isActive(); }
    void setPlaying(bool playing);
    int speed() const;
    void setSpeed(int factor); // 1, 4 or 16
    // One tick of playing (what the timer does): the moment on by kTickMs × speed.
    void tick();

    ReplaySlider *slider() const { return m_slider; }
    QLabel *momentLabel() const { return m_momentLabel; }
    QComboBox *eventList() const { return m_events; }
    QComboBox *deviceList() const { return m_devices; }
    QToolButton *playButton() const { return m_play; }
    // One row instead of two, for a low window (1024×600): the pages keep their room.
    void setCompact(bool compact);
    bool isCompact() const { return m_compact; }

Q_SIGNALS:
    void seekRequested(qint64 ms);
    void stepFrame(int direction); // -1 or +1
    void deviceChosen(int id);
    void closeRequested();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void retranslate();
    void fillEvents();
    void stepEvent(int direction);
    void place();

    QToolButton *m_play;
    QComboBox *m_speed;
    QToolButton *m_backFrame;
    QToolButton *m_nextFrame;
    ReplaySlider *m_slider;
    QLabel *m_momentLabel;
    QToolButton *m_backEvent;
    QComboBox *m_events;
    QToolButton *m_nextEvent;
    QLabel *m_deviceCaption;
    QComboBox *m_devices;
    QToolButton *m_close;
    QTimer m_timer;
    QHBoxLayout *m_top;
    QHBoxLayout *m_bottom;
    bool m_compact = false;
    QList<ReplayEvent> m_eventList;
    std::function<QString(qint64)> m_momentText;
    qint64 m_moment = 0;
    qint64 m_duration = 0;
};

} // namespace stepcom
