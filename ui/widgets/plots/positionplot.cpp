#include "widgets/plots/positionplot.h"

#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QGraphicsLayout>
#include <QHash>
#include <QLineSeries>
#include <QValueAxis>
#include <QWheelEvent>

#include <cmath>
#include <functional>
#include <limits>

namespace stepcom {

namespace {

constexpr double kMinSpan = 1.0; // one distance unit: a motor at rest is a flat line, not noise

// A round tick step (1, 2 or 5 × 10^n) giving about `ticks` intervals over `span`.
double niceStep(double span, int ticks)
{
    const double raw = std::max(span, 1e-9) / std::max(1, ticks);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (raw <= m * magnitude)
            return m * magnitude;
    }
    return 10.0 * magnitude;
}

} // namespace

PositionPlot::PositionPlot(StatusRecorder *recorder, QWidget *parent)
    : NavigableChartView(new QChart, parent)
    , m_recorder(recorder)
    , m_axisX(new QValueAxis(this))
    , m_axisY(new QValueAxis(this))
{
    setObjectName(QStringLiteral("positionPlot"));
    QChart *c = chart();
    c->setAnimationOptions(QChart::NoAnimation);
    c->setBackgroundRoundness(0);
    c->layout()->setContentsMargins(0, 0, 0, 0);
    c->legend()->setAlignment(Qt::AlignTop);
    for (QValueAxis *a : {m_axisX, m_axisY}) {
        a->setTickType(QValueAxis::TicksDynamic);
        a->setTickAnchor(0.0);
    }
    c->addAxis(m_axisX, Qt::AlignBottom);
    c->addAxis(m_axisY, Qt::AlignLeft);
    for (int m = 0; m < recorder->motorCount(); ++m) {
        auto *s = new QLineSeries(this);
        c->addSeries(s);
        s->attachAxis(m_axisX);
        s->attachAxis(m_axisY);
        m_series << s;
    }
    setRenderHint(QPainter::Antialiasing);
    setRubberBand(QChartView::RectangleRubberBand);
    setFrameShape(QFrame::NoFrame);
    setFocusPolicy(Qt::StrongFocus);

    m_refreshTimer.setSingleShot(true);
    m_refreshTimer.setInterval(200);
    connect(&m_refreshTimer, &QTimer::timeout, this, [this] { redraw(false); });
    connect(recorder, &StatusRecorder::sampleAdded, this, &PositionPlot::scheduleRefresh);
    connect(recorder, &StatusRecorder::cleared, this, &PositionPlot::refresh);
    applyPalette();
    retranslate();
    m_originMs = QDateTime::currentMSecsSinceEpoch();
    setRanges(-m_windowSeconds, 0.0, 0.0, kMinSpan, true);
    // Only now: adding axes and series moves the ranges, and that is not the user zooming.
    for (QValueAxis *a : {m_axisX, m_axisY})
        connect(a, &QValueAxis::rangeChanged, this, &PositionPlot::userChangedRange);
}

void PositionPlot::setWindowSeconds(int seconds)
{
    m_windowSeconds = std::max(1, seconds);
    redraw(false);
}

void PositionPlot::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    m_paused = paused;
    if (!paused)
        redraw(false);
    Q_EMIT pausedChanged(paused);
}

int PositionPlot::pointCount(int motor) const
{
    const QLineSeries *s = series(motor);
    return s ? int(s->count()) : 0;
}

void PositionPlot::scheduleRefresh()
{
    if (!m_paused && !m_refreshTimer.isActive())
        m_refreshTimer.start();
}

void PositionPlot::refresh()
{
    redraw(false);
}

void PositionPlot::showEvent(QShowEvent *event)
{
    QChartView::showEvent(event);
    if (m_stale)
        redraw(false);
}

void PositionPlot::redraw(bool force)
{
    if (m_paused && !force)
        return;
    if (!isVisible() && !force) {
        m_stale = true; // nobody is looking: draw once when shown
        return;
    }
    m_stale = false;
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    if (!m_recorder->isEmpty()) {
        const StatusSample &last = m_recorder->last();
        m_originMs = last.epochMs; // x = 0: the newest sample
        const int from = m_recorder->indexAtOrAfter(last.elapsedMs - m_windowSeconds * 1000LL);
        const int to = m_recorder->size();
        // More samples than pixels: keep each bucket's lowest and highest, in time order.
        const int buckets = std::max(1, m_maxPoints / 2);
        const int perBucket = std::max(1, (to - from + buckets - 1) / buckets);
        for (int m = 0; m < m_series.size(); ++m) {
            QList<QPointF> points;
            points.reserve(std::min(to - from, m_maxPoints) + 2);
            for (int b = from; b < to; b += perBucket) {
                int lo = -1;
                int hi = -1;
                for (int i = b; i < std::min(to, b + perBucket); ++i) {
                    const double v = m_recorder->at(i).positions.value(m, qQNaN());
                    if (std::isnan(v))
                        continue;
                    if (lo < 0 || v < m_recorder->at(lo).positions.at(m))
                        lo = i;
                    if (hi < 0 || v > m_recorder->at(hi).positions.at(m))
                        hi = i;
                }
                if (lo < 0)
                    continue;
                for (int i : {std::min(lo, hi), std::max(lo, hi)}) {
                    const StatusSample &sample = m_recorder->at(i);
                    const double v = sample.positions.at(m);
                    points << QPointF(double(sample.epochMs - m_originMs) / 1000.0, v);
                    low = std::min(low, v);
                    high = std::max(high, v);
                    if (lo == hi)
                        break;
                }
            }
            m_series.at(m)->replace(points);
        }
    } else {
        for (QLineSeries *s : std::as_const(m_series))
            s->clear();
    }
    if (low > high) {
        low = m_low;
        high = m_high;
    }
    setRanges(-m_windowSeconds, 0.0, low, high, force);
    retranslateTime();
}

void PositionPlot::setRanges(double fromS, double toS, double low, double high, bool exact)
{
    if (high - low < kMinSpan) {
        const double mid = (low + high) / 2.0;
        low = mid - kMinSpan / 2.0;
        high = mid + kMinSpan / 2.0;
    }
    const double step = niceStep((high - low) * 1.1, 5);
    const double wantLow = std::floor((low - (high - low) * 0.05) / step) * step;
    const double wantHigh = std::ceil((high + (high - low) * 0.05) / step) * step;
    m_settingRange = true;
    setAxisRange(m_axisX, fromS, toS, niceStep(toS - fromS, 6));
    // Keep the scale while the data fits and fills it: no jumping axis on every sample.
    const bool fits = !exact && m_axisY->min() <= low && m_axisY->max() >= high &&
                      (m_axisY->max() - m_axisY->min()) <= 2.0 * (wantHigh - wantLow);
    if (!fits)
        setAxisRange(m_axisY, wantLow, wantHigh, niceStep(wantHigh - wantLow, 5));
    tuneTicks();
    m_settingRange = false;
    m_low = low;
    m_high = high;
}

void PositionPlot::tuneTicks()
{
    for (QValueAxis *a : {m_axisX, m_axisY})
        setAxisRange(a, a->min(), a->max(), niceStep(a->max() - a->min(), a == m_axisX ? 6 : 5));
}

void PositionPlot::userChangedRange()
{
    if (m_settingRange)
        return;
    setPaused(true); // the user looks at something: hold it still
    m_settingRange = true;
    tuneTicks();
    m_settingRange = false;
}

void PositionPlot::fit()
{
    if (!m_paused) {
        redraw(true);
        return;
    }
    // Paused: back to the frozen window, autoscaled.
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    double from = -m_windowSeconds;
    for (const QLineSeries *s : std::as_const(m_series)) {
        const QList<QPointF> points = s->points();
        for (const QPointF &p : points) {
            low = std::min(low, p.y());
            high = std::max(high, p.y());
            from = std::min(from, p.x());
        }
    }
    if (low <= high)
        setRanges(from, 0.0, low, high, true);
}

void PositionPlot::zoom(qreal factor)
{
    if (factor > 0)
        chart()->zoom(factor);
}

QList<StatusSample> PositionPlot::visibleSamples() const
{
    if (m_recorder->isEmpty())
        return {};
    if (!m_paused) // live: the window up to the newest sample, drawn or about to be
        return m_recorder->samples(
            m_recorder->indexAtOrAfter(m_recorder->last().elapsedMs - m_windowSeconds * 1000LL));
    QList<StatusSample> out;
    const qint64 from = m_originMs + qint64(m_axisX->min() * 1000.0);
    const qint64 to = m_originMs + qint64(m_axisX->max() * 1000.0);
    const double low = m_axisY->min();
    const double high = m_axisY->max();
    for (int i = 0; i < m_recorder->size(); ++i) {
        const StatusSample &s = m_recorder->at(i);
        if (s.epochMs < from || s.epochMs > to)
            continue;
        // Zoomed in on the value axis too: a sample counts when any motor is in view.
        const bool inView = std::any_of(s.positions.cbegin(), s.positions.cend(),
                                        [&](double v) { return v >= low && v <= high; });
        if (inView)
            out << s;
    }
    return out;
}

bool PositionPlot::exportPng(const QString &path, QString *error)
{
    const QPixmap picture = grab();
    if (picture.isNull() || !picture.save(path, "PNG")) {
        if (error)
            *error = tr("Cannot write the picture “%1”.")
                         .arg(QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath()));
        return false;
    }
    return true;
}

bool PositionPlot::exportCsv(const QString &path, QString *error) const
{
    return m_recorder->writeCsv(path, visibleSamples(), error);
}

void PositionPlot::zoomAt(const QPointF &at, qreal f)
{
    const QRectF area = chart()->plotArea();
    const QRectF rect(at.x() - (at.x() - area.left()) / f, at.y() - (at.y() - area.top()) / f,
                      area.width() / f, area.height() / f);
    chart()->zoomIn(rect);
}

void PositionPlot::pan(qreal dx, qreal dy)
{
    chart()->scroll(dx, dy);
}

void PositionPlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange)
        applyPalette();
    QChartView::changeEvent(event);
}

void PositionPlot::applyPalette()
{
    const QPalette pal = palette();
    styleChart({m_axisX, m_axisY});
    for (QLineSeries *s : std::as_const(m_series)) {
        QPen pen = s->pen();
        pen.setWidthF(2.0);
        s->setPen(pen);
    }
}

void PositionPlot::retranslateTime()
{
    const QString newest =
        QDateTime::fromMSecsSinceEpoch(m_originMs).toString(QStringLiteral("HH:mm:ss"));
    m_axisX->setTitleText(tr("Time (s), 0 = %1").arg(newest));
}

void PositionPlot::retranslate()
{
    for (int m = 0; m < m_series.size(); ++m)
        m_series.at(m)->setName(tr("Motor %1").arg(m + 1));
    retranslateTime();
    const QString unit = m_recorder->positionUnit();
    m_axisY->setTitleText(unit.isEmpty() ? tr("Position") : tr("Position (%1)").arg(unit));
    setToolTip(tr("Drag to zoom into a region, wheel or +/- to zoom, middle button or arrow keys "
                  "to pan, double-click or Home to fit. Zooming pauses the view."));
}

} // namespace stepcom
