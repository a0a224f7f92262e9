#include "widgets/plots/xyplot.h"

#include <QContextMenuEvent>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QGraphicsLayout>
#include <QLegendMarker>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>
#include <QWheelEvent>

#include <cmath>
#include <functional>
#include <limits>

namespace stepcom {

namespace {

// A round tick step (1, 2 or 5 × 10^n) giving about `ticks` intervals over `span`.
double niceStep(double span, int ticks)
{
    const double raw = span / std::max(1, ticks);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (raw <= m * magnitude)
            return m * magnitude;
    }
    return 10.0 * magnitude;
}

void includePoints(QRectF &bounds, bool &any, const QList<QPointF> &points)
{
    for (const QPointF &p : points) {
        if (!any) {
            bounds = QRectF(p, QSizeF(0, 0));
            any = true;
            continue;
        }
        bounds.setLeft(std::min(bounds.left(), p.x()));
        bounds.setRight(std::max(bounds.right(), p.x()));
        bounds.setTop(std::min(bounds.top(), p.y()));
        bounds.setBottom(std::max(bounds.bottom(), p.y()));
    }
}

} // namespace

XYPlot::XYPlot(QWidget *parent)
    : NavigableChartView(new QChart, parent)
    , m_axisX(new QValueAxis(this))
    , m_axisY(new QValueAxis(this))
    , m_traceSeries(new QLineSeries(this))
    , m_markerSeries(new QScatterSeries(this))
{
    setObjectName(QStringLiteral("xyPlot"));
    QChart *c = chart();
    c->setAnimationOptions(QChart::NoAnimation);
    c->setBackgroundRoundness(0);
    c->layout()->setContentsMargins(0, 0, 0, 0);
    c->legend()->setAlignment(Qt::AlignTop);
    c->addAxis(m_axisX, Qt::AlignBottom);
    c->addAxis(m_axisY, Qt::AlignLeft);
    addSeries(m_traceSeries);
    addSeries(m_markerSeries);
    m_markerSeries->setMarkerShape(QScatterSeries::MarkerShapeCircle);
    for (QValueAxis *a : {m_axisX, m_axisY}) {
        a->setTickType(QValueAxis::TicksDynamic);
        a->setTickAnchor(0.0);
        connect(a, &QValueAxis::rangeChanged, this, &XYPlot::userChangedRange);
    }
    setRenderHint(QPainter::Antialiasing);
    setRubberBand(QChartView::RectangleRubberBand);
    setFrameShape(QFrame::NoFrame);
    setFocusPolicy(Qt::StrongFocus);
    m_flushTimer.setSingleShot(true);
    m_flushTimer.setInterval(0);
    connect(&m_flushTimer, &QTimer::timeout, this, &XYPlot::flush);
    m_aspectTimer.setSingleShot(true);
    m_aspectTimer.setInterval(0);
    connect(&m_aspectTimer, &QTimer::timeout, this, [this] {
        // Only when clearly off: new tick labels resize the plot area, which lands here again.
        const QRectF area = chart()->plotArea();
        const QRectF r = visibleRect();
        if (area.width() < 4 || area.height() < 4 || r.height() <= 0)
            return;
        const double ratio = (r.width() / area.width()) / (r.height() / area.height());
        if (std::abs(ratio - 1.0) < 0.01)
            return;
        if (m_autoFit)
            fit();
        else
            setView(r);
    });
    connect(c, &QChart::plotAreaChanged, this, [this] { m_aspectTimer.start(); });
    applyPalette();
    setTraceName(QString());
    setView(QRectF(-m_minSpan, -m_minSpan, 2 * m_minSpan, 2 * m_minSpan));
}

QXYSeries *XYPlot::addSeries(QXYSeries *series)
{
    chart()->addSeries(series);
    series->attachAxis(m_axisX);
    series->attachAxis(m_axisY);
    return series;
}

void XYPlot::setSeries(const QString &id, bool dots, const QList<QPointF> &points,
                       const QString &name)
{
    QXYSeries *s = m_paths.value(id);
    if (s && (qobject_cast<QScatterSeries *>(s) != nullptr) != dots) {
        removePath(id);
        s = nullptr;
    }
    if (!s && dots) {
        auto *scatter = new QScatterSeries(this);
        scatter->setMarkerSize(fontMetrics().height() * 0.5);
        s = m_paths[id] = addSeries(scatter);
    } else if (!s) {
        s = m_paths[id] = addSeries(new QLineSeries(this));
    }
    s->setName(name);
    s->replace(points);
    for (QLegendMarker *m : chart()->legend()->markers(s))
        m->setVisible(!name.isEmpty());
    schedule();
}

QXYSeries *XYPlot::traceSeries() const
{
    return m_traceSeries;
}

void XYPlot::setPath(const QString &id, const QList<QPointF> &points, const QString &name)
{
    setSeries(id, false, points, name);
}

void XYPlot::setPoints(const QString &id, const QList<QPointF> &points, const QString &name)
{
    setSeries(id, true, points, name);
}

void XYPlot::removePath(const QString &id)
{
    if (QXYSeries *s = m_paths.take(id)) {
        chart()->removeSeries(s);
        s->deleteLater();
        schedule();
    }
}

void XYPlot::clearPaths()
{
    for (const QString &id : m_paths.keys())
        removePath(id);
}

QList<QPointF> XYPlot::path(const QString &id) const
{
    const QXYSeries *s = m_paths.value(id);
    return s ? s->points() : QList<QPointF>();
}

void XYPlot::appendTrace(const QList<QPointF> &points)
{
    bool changed = false;
    for (const QPointF &p : points) {
        if (!m_trace.isEmpty() && m_trace.last() == p)
            continue;
        m_trace << p;
        changed = true;
    }
    if (m_trace.size() > m_traceLimit)
        m_trace.remove(0, m_trace.size() - m_traceLimit);
    if (changed)
        schedule();
}

void XYPlot::clearTrace()
{
    m_trace.clear();
    schedule();
}

void XYPlot::setTraceLimit(int points)
{
    m_traceLimit = std::max(2, points);
    appendTrace(QList<QPointF>());
}

void XYPlot::setTraceName(const QString &name)
{
    m_traceSeries->setName(name);
    for (QLegendMarker *m : chart()->legend()->markers(m_traceSeries))
        m->setVisible(!name.isEmpty());
    for (QLegendMarker *m : chart()->legend()->markers(m_markerSeries))
        m->setVisible(false);
}

void XYPlot::setMarker(const QPointF &point)
{
    if (m_marker == point)
        return;
    m_marker = point;
    schedule();
}

void XYPlot::clearMarker()
{
    m_marker.reset();
    schedule();
}

void XYPlot::setAxisTitles(const QString &x, const QString &y)
{
    m_axisX->setTitleText(x);
    m_axisY->setTitleText(y);
}

void XYPlot::setAutoFit(bool on)
{
    if (m_autoFit == on)
        return;
    m_autoFit = on;
    if (on)
        schedule();
    Q_EMIT autoFitChanged(on);
}

void XYPlot::schedule()
{
    m_dirty = true;
    if (!m_flushTimer.isActive())
        m_flushTimer.start();
}

void XYPlot::showEvent(QShowEvent *event)
{
    QChartView::showEvent(event);
    if (m_dirty)
        schedule();
}

void XYPlot::flush()
{
    if (!isVisible())
        return; // drawn when shown (m_dirty stays set)
    m_dirty = false;
    m_traceSeries->replace(m_trace);
    if (m_marker)
        m_markerSeries->replace(QList<QPointF>{*m_marker});
    else
        m_markerSeries->clear();
    if (m_autoFit)
        fit();
}

void XYPlot::fit()
{
    QRectF bounds;
    bool any = false;
    includePoints(bounds, any, m_trace);
    if (m_marker)
        includePoints(bounds, any, {*m_marker});
    for (const QXYSeries *s : std::as_const(m_paths))
        includePoints(bounds, any, s->points());
    if (!any)
        bounds = QRectF(0, 0, 0, 0);
    const double margin = std::max(bounds.width(), bounds.height()) * 0.05;
    setView(bounds.adjusted(-margin, -margin, margin, margin));
    setAutoFit(true);
}

void XYPlot::setView(const QRectF &wanted)
{
    QRectF r = wanted.normalized();
    if (!std::isfinite(r.width()) || !std::isfinite(r.height()))
        return;
    const QPointF centre = r.center();
    double w = std::max(r.width(), m_minSpan);
    double h = std::max(r.height(), m_minSpan);
    // Equal units per pixel on both axes, so shapes keep their proportions.
    const QRectF area = chart()->plotArea();
    if (area.width() > 4 && area.height() > 4) {
        const double perPixel = std::max(w / area.width(), h / area.height());
        w = perPixel * area.width();
        h = perPixel * area.height();
    }
    m_settingRange = true;
    // One tick step for both axes, from the shorter one: round labels, equal grid squares.
    const double step = niceStep(std::min(w, h), 4);
    setAxisRange(m_axisX, centre.x() - w / 2, centre.x() + w / 2, step);
    setAxisRange(m_axisY, centre.y() - h / 2, centre.y() + h / 2, step);
    m_settingRange = false;
}

QRectF XYPlot::visibleRect() const
{
    return QRectF(QPointF(m_axisX->min(), m_axisY->min()), QPointF(m_axisX->max(), m_axisY->max()));
}

void XYPlot::userChangedRange()
{
    if (m_settingRange)
        return;
    setAutoFit(false);
    m_aspectTimer.start(); // a rubber band's rectangle has any shape: square it afterwards
}

void XYPlot::zoom(qreal factor)
{
    if (factor <= 0)
        return;
    const QRectF r = visibleRect();
    const QSizeF size = r.size() / factor;
    setAutoFit(false);
    setView(QRectF(r.center() - QPointF(size.width() / 2, size.height() / 2), size));
}

void XYPlot::pan(qreal dx, qreal dy)
{
    chart()->scroll(dx, dy);
}

bool XYPlot::exportPng(const QString &path, QString *error)
{
    flush();
    const QPixmap picture = grab();
    if (picture.isNull() || !picture.save(path, "PNG")) {
        if (error)
            *error = tr("Cannot write the picture “%1”.")
                         .arg(QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath()));
        return false;
    }
    return true;
}

void XYPlot::resizeEvent(QResizeEvent *event)
{
    QChartView::resizeEvent(event);
    m_aspectTimer.start();
}

void XYPlot::zoomAt(const QPointF &at, qreal f)
{
    // The point under the cursor stays under it.
    const QPointF value = chart()->mapToValue(at, m_traceSeries);
    const QRectF r = visibleRect();
    setAutoFit(false);
    setView(QRectF(
        QPointF(value.x() - (value.x() - r.left()) / f, value.y() - (value.y() - r.top()) / f),
        r.size() / f));
}

void XYPlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange)
        applyPalette();
    QChartView::changeEvent(event);
}

void XYPlot::applyPalette()
{
    const QPalette pal = palette();
    styleChart({m_axisX, m_axisY});
    QPen trace = m_traceSeries->pen();
    trace.setWidthF(2.0);
    m_traceSeries->setPen(trace);
    m_markerSeries->setMarkerSize(fontMetrics().height() * 0.8);
    m_markerSeries->setColor(pal.color(QPalette::Highlight));
    m_markerSeries->setBorderColor(pal.color(QPalette::Text));
}

void XYPlot::contextMenuEvent(QContextMenuEvent *event)
{
    const QPointF scene = mapToScene(event->pos());
    const QPointF inChart = chart()->mapFromScene(scene);
    if (!chart()->plotArea().contains(inChart)) {
        NavigableChartView::contextMenuEvent(event);
        return;
    }
    Q_EMIT pointMenuRequested(chart()->mapToValue(inChart), event->globalPos());
    event->accept();
}

} // namespace stepcom
