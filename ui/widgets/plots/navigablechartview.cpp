#include "widgets/plots/navigablechartview.h"

#include <QKeyEvent>
#include <QLegend>
#include <QMouseEvent>
#include <QValueAxis>
#include <QWheelEvent>

#include <cmath>

namespace stepcom {

void NavigableChartView::setAxisRange(QValueAxis *axis, double min, double max, double step)
{
    const bool coarser = step >= axis->tickInterval();
    if (coarser)
        axis->setTickInterval(step);
    axis->setRange(min, max);
    if (!coarser)
        axis->setTickInterval(step);
    const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
    axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
}

void NavigableChartView::styleChart(std::initializer_list<QValueAxis *> axes)
{
    const QPalette pal = palette();
    QChart *c = chart();
    c->setBackgroundBrush(pal.brush(QPalette::Base));
    c->setBackgroundPen(Qt::NoPen);
    c->legend()->setLabelColor(pal.color(QPalette::Text));
    c->legend()->setFont(font());
    QColor grid = pal.color(QPalette::Text);
    grid.setAlphaF(0.15);
    for (QValueAxis *axis : axes) {
        axis->setLabelsBrush(pal.brush(QPalette::Text));
        axis->setTitleBrush(pal.brush(QPalette::Text));
        axis->setLabelsFont(font());
        axis->setTitleFont(font());
        axis->setLinePen(QPen(pal.color(QPalette::Mid), 1));
        axis->setGridLinePen(QPen(grid, 1));
    }
}

void NavigableChartView::wheelEvent(QWheelEvent *event)
{
    const QRectF area = chart()->plotArea();
    const QPointF at = chart()->mapFromScene(mapToScene(event->position().toPoint()));
    if (!area.contains(at) || event->angleDelta().y() == 0) {
        event->ignore();
        return;
    }
    zoomAt(at, std::pow(1.2, event->angleDelta().y() / 120.0));
    event->accept();
}

void NavigableChartView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::MiddleButton) {
        m_panning = true;
        m_panFrom = event->position().toPoint();
        event->accept();
        return;
    }
    QChartView::mousePressEvent(event);
}

void NavigableChartView::mouseMoveEvent(QMouseEvent *event)
{
    if (m_panning) {
        const QPoint delta = event->position().toPoint() - m_panFrom;
        m_panFrom = event->position().toPoint();
        pan(-delta.x(), delta.y());
        event->accept();
        return;
    }
    QChartView::mouseMoveEvent(event);
}

void NavigableChartView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_panning && event->button() == Qt::MiddleButton) {
        m_panning = false;
        event->accept();
        return;
    }
    QChartView::mouseReleaseEvent(event);
}

void NavigableChartView::mouseDoubleClickEvent(QMouseEvent *event)
{
    fit();
    event->accept();
}

void NavigableChartView::keyPressEvent(QKeyEvent *event)
{
    const qreal step = chart()->plotArea().width() / 10.0;
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoom(1.25);
        break;
    case Qt::Key_Minus:
        zoom(0.8);
        break;
    case Qt::Key_Left:
        pan(-step, 0);
        break;
    case Qt::Key_Right:
        pan(step, 0);
        break;
    case Qt::Key_Up:
        pan(0, step);
        break;
    case Qt::Key_Down:
        pan(0, -step);
        break;
    case Qt::Key_Home:
    case Qt::Key_0:
        fit();
        break;
    default:
        QChartView::keyPressEvent(event);
        return;
    }
    event->accept();
}

} // namespace stepcom
