#pragma once

#include "widgets/plots/navigablechartview.h"
#include <QHash>
#include <QTimer>

#include <optional>

class QLineSeries;
class QScatterSeries;
class QXYSeries;
class QValueAxis;

namespace stepcom {

// A plane view with equal scales on both axes (a circle stays round): fixed paths and point
// sets (a planned line or arc), a trace that grows (where the tool has been), and a live
// marker. It knows nothing about motors or the device: callers hand it points.
// Follows the data (autoFit) until the user zooms (drag, wheel, +/-) or pans (middle drag,
// arrows); fit() or a double-click follows again. Updates are batched: a burst of calls
// redraws once, and nothing is redrawn while hidden.
class XYPlot : public NavigableChartView
{
    Q_OBJECT
public:
    explicit XYPlot(QWidget *parent = nullptr);

    // A polyline shown as given, replaced when set again under the same id.
    void setPath(const QString &id, const QList<QPointF> &points, const QString &name = {});
    // Points shown as dots (no lines), e.g. an arc's centre and end points.
    void setPoints(const QString &id, const QList<QPointF> &points, const QString &name = {});
    void removePath(const QString &id);
    void clearPaths();
    QStringList pathIds() const { return m_paths.keys(); }
    QList<QPointF> path(const QString &id) const;
    // The series of a path or point set, to style it (pen, marker shape); nullptr if unknown.
    QXYSeries *series(const QString &id) const { return m_paths.value(id); }
    QXYSeries *traceSeries() const;

    // The trace: a point equal to the last one is skipped (a tool at rest adds nothing); the
    // oldest points go beyond traceLimit.
    void appendTrace(const QList<QPointF> &points);
    void appendTrace(const QPointF &point) { appendTrace(QList<QPointF>{point}); }
    void clearTrace();
    const QList<QPointF> &trace() const { return m_trace; }
    int traceCount() const { return int(m_trace.size()); }
    void setTraceLimit(int points);
    int traceLimit() const { return m_traceLimit; }
    void setTraceName(const QString &name);

    void setMarker(const QPointF &point);
    void clearMarker();
    std::optional<QPointF> marker() const { return m_marker; }

    void setAxisTitles(const QString &x, const QString &y);
    // Smallest range shown on either axis, in data units (default 1).
    void setMinimumSpan(double span) { m_minSpan = std::max(1e-9, span); }
    void setAutoFit(bool on);
    bool autoFit() const { return m_autoFit; }
    // Show everything and follow the data again.
    void fit() override;
    // Zoom around the centre (factor > 1 zooms in) and pan by pixels; both stop autoFit.
    void zoom(qreal factor) override;
    void pan(qreal dx, qreal dy) override;
    QRectF visibleRect() const;
    // Draw pending changes now instead of on the next turn of the event loop.
    void flush();

    bool exportPng(const QString &path, QString *error);

Q_SIGNALS:
    void autoFitChanged(bool on);
    // A right-click on the plot at `value` (data units), for a menu at `globalPos`.
    void pointMenuRequested(const QPointF &value, const QPoint &globalPos);

protected:
    void changeEvent(QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void zoomAt(const QPointF &plotPoint, qreal factor) override;
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void schedule();
    void setView(const QRectF &wanted);
    void userChangedRange();
    void applyPalette();
    QXYSeries *addSeries(QXYSeries *series);
    void setSeries(const QString &id, bool dots, const QList<QPointF> &points, const QString &name);

    QValueAxis *m_axisX;
    QValueAxis *m_axisY;
    QLineSeries *m_traceSeries;
    QScatterSeries *m_markerSeries;
    QHash<QString, QXYSeries *> m_paths;
    QList<QPointF> m_trace;
    std::optional<QPointF> m_marker;
    int m_traceLimit = 20000;
    double m_minSpan = 1.0;
    bool m_autoFit = true;
    bool m_dirty = false;
    bool m_settingRange = false; // our own range changes are not the user zooming
    QTimer m_flushTimer;
    QTimer m_aspectTimer; // squares the view after a rubber-band zoom
};

} // namespace stepcom
