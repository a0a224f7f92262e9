#pragma once

#include "device/statusrecorder.h"

#include "widgets/plots/navigablechartview.h"
#include <QTimer>

class QLineSeries;
class QValueAxis;

namespace stepcom {

// Each motor's position over time from a StatusRecorder's history: a sliding window of the last
// N seconds, autoscaled. Redraws at most every refreshMs and only while visible, with one
// replace() per series, so a plot on screen stays cheap at any poll rate. Zooming (rubber band,
// wheel, +/-) or panning (middle drag, arrows) pauses the view; fit() goes back to autoscale.
// While paused the recorder keeps recording; the view catches up on resume.
class PositionPlot : public NavigableChartView
{
    Q_OBJECT
public:
    explicit PositionPlot(StatusRecorder *recorder, QWidget *parent = nullptr);

    void setWindowSeconds(int seconds);
    int windowSeconds() const { return m_windowSeconds; }
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Autoscale both axes to the data shown; when live, also back to the sliding window.
    void fit() override;
    // Zoom around the centre (factor > 1 zooms in); pauses a live view.
    void zoom(qreal factor) override;
    void pan(qreal dx, qreal dy) override;
    void setMaxPointsPerSeries(int points) { m_maxPoints = std::max(16, points); }
    void setRefreshMs(int ms) { m_refreshTimer.setInterval(ms); }

    int seriesCount() const { return int(m_series.size()); }
    QLineSeries *series(int motor) const { return m_series.value(motor - 1); }
    int pointCount(int motor) const;
    // The samples inside the visible time range (what "export CSV" writes).
    QList<StatusSample> visibleSamples() const;
    bool exportPng(const QString &path, QString *error);
    bool exportCsv(const QString &path, QString *error) const;

    // Redraw from the recorder now (skipped while paused).
    void refresh();

Q_SIGNALS:
    void pausedChanged(bool paused);

protected:
    void changeEvent(QEvent *event) override;
    void zoomAt(const QPointF &plotPoint, qreal factor) override;
    void showEvent(QShowEvent *event) override;

private:
    void scheduleRefresh();
    void redraw(bool force);
    void setRanges(double fromS, double toS, double low, double high, bool exact);
    void tuneTicks();
    void userChangedRange();
    void applyPalette();
    void retranslate();
    void retranslateTime();

    StatusRecorder *m_recorder;
    QList<QLineSeries *> m_series;
    QValueAxis *m_axisX; // seconds relative to the newest sample (m_originMs)
    QValueAxis *m_axisY;
    QTimer m_refreshTimer;
    int m_windowSeconds = 30;
    int m_maxPoints = 2000;
    bool m_paused = false;
    bool m_stale = false;
    bool m_settingRange = false; // our own range changes are not the user zooming
    qint64 m_originMs = 0;
    double m_low = 0.0;
    double m_high = 0.0;
};

} // namespace stepcom
