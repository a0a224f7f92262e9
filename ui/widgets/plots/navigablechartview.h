#pragma once

#include <QChartView>

class QValueAxis;

namespace stepcom {

// A chart view that every plot of StepCom navigates the same way: wheel zooms around the
// cursor, the middle button pans, a double click or Home/0 fits, +/- zoom, arrows pan.
// Subclasses say what zooming, panning and fitting mean for their axes.
class NavigableChartView : public QChartView
{
    Q_OBJECT
public:
    using QChartView::QChartView;

    virtual void fit() = 0;
    virtual void zoom(qreal factor) = 0;
    // In pixels of the plot area; positive dx shows what lies to the right.
    virtual void pan(qreal dx, qreal dy) = 0;

protected:
    // Zoom by `factor` keeping `plotPoint` (chart coordinates) where it is.
    virtual void zoomAt(const QPointF &plotPoint, qreal factor) = 0;

    // Background, legend and axes from the palette and font, so plots follow a dark palette
    // and the scale factor like every other widget.
    void styleChart(std::initializer_list<QValueAxis *> axes);
    // The axis from `min` to `max` with a tick (and a label of as many decimals) every `step`;
    // the step set before the range when it grows, after it when it shrinks: a range laid out
    // with the old, much finer step would make thousands of labels first (hundreds of ms).
    static void setAxisRange(QValueAxis *axis, double min, double max, double step);

    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    QPoint m_panFrom;
    bool m_panning = false;
};

} // namespace stepcom
