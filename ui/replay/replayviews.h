#pragma once

#include "device/statusrecorder.h" // StatusSample

#include <QObject>
#include <QPointer>

#include <functional>

namespace stepcom {

class DeviceListDock;
class DeviceSession;
class PlotPage;
class ReplayLog;
struct ReplayState;
class TrafficLog;
struct TrafficEntry;
class TrafficView;

// What the window's views beside the pages show of a replayed log at its moment, as
// the live window showed them then: the traffic view the log's lines through the moment (its
// last kTrafficLines; scrolled back, the ones before), the plots (the session's StatusRecorder) the
// positions, flags, inputs and outputs of the half hour before it (what the live recorder keeps),
// the XY plot the whole path from the start of the log, the device list each device's state. A
// short step forward (playing) feeds only what came since, as the live window is fed; any other
// moment is shown afresh from the log's snapshots (ReplayLog::walkTail) and its track
// (ReplayLog::track), never by reading the whole log again.
class ReplayViews : public QObject
{
    Q_OBJECT
public:
    // The traffic view's lines at a moment chosen anywhere, about 4 minutes of polling at 10 Hz
    // (scrolled back, as many again each time; playing on adds to them; the view's own limit).
    static constexpr int kTrafficLines = 10000;
    // The XY trace's points at a moment chosen anywhere: the whole path from the start at the
    // plot's resolution (ReplayTrack::path), so drawing it stays cheap.
    static constexpr int kTracePoints = 4000;
    // A step forward at most this long is fed on instead of shown afresh.
    static constexpr qint64 kFollowMs = 10000;

    explicit ReplayViews(DeviceSession *session, QObject *parent = nullptr);

    void setTrafficView(TrafficView *view);
    void setDeviceList(DeviceListDock *list);
    void setPlots(PlotPage *plots);
    TrafficLog *traffic() const { return m_traffic; }

    // The replay of `log` begins: the traffic view shows its lines; a click on a device of the
    // list calls `choose`.
    void start(const ReplayLog *log, const std::function<void(int)> &choose);
    // Every view at `moment` with `device` in view; `state` is the log's state then.
    void show(qint64 moment, int device, const QList<int> &devices, const ReplayState &state);
    // The replay ends: the session's own traffic, plots and devices again.
    void stop();

private:
    void showAfresh(qint64 moment, int device, const ReplayState &state);
    void follow(qint64 from, qint64 moment, int device, const ReplayState &state);
    // The traffic view scrolled back: the lines before the first one it has.
    QList<TrafficEntry> earlierLines();
    void showDevices(int device, const QList<int> &devices, const ReplayState &state);
    // The device's sample at its last answer through the moment, when it is later than `after`.
    void addLastAnswer(QList<StatusSample> *samples, qint64 after, int device,
                       const ReplayState &state) const;

    DeviceSession *m_session;
    TrafficLog *m_traffic;
    QPointer<TrafficView> m_view;
    QPointer<DeviceListDock> m_deviceList;
    QPointer<PlotPage> m_plots;
    const ReplayLog *m_log = nullptr;
    std::function<void(int)> m_choose;
    qint64 m_epochMs = 0;  // the log's first moment on the wall clock
    qint64 m_shownAt = -1; // the moment the traffic and the plots were fed up to; -1: none
    int m_shownDevice = 0;
    qint64 m_firstLine = -1; // the log's line number of the traffic view's first row
};

} // namespace stepcom
