#include "widgets/plots/marginplot.h"

#include <QEvent>
#include <QGraphicsLayout>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace stepcom {

MarginPlot::MarginPlot(QWidget *parent)
    : QChartView(parent)
    , m_line(new QLineSeries(this))
    , m_kept(new QScatterSeries(this))
    , m_lost(new QScatterSeries(this))
    , m_recommended(new QLineSeries(this))
    , m_axisX(new QValueAxis(this))
    , m_axisY(new QValueAxis(this))
{
    setObjectName(QStringLiteral("marginPlot"));
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(220);
    QChart *c = chart();
    c->layout()->setContentsMargins(0, 0, 0, 0);
    c->legend()->setAlignment(Qt::AlignTop);
    m_kept->setColor(QColor(0x2e, 0x7d, 0x32));
    m_lost->setColor(QColor(0xc6, 0x28, 0x28));
    for (QScatterSeries *s : {m_kept, m_lost}) {
        s->setMarkerSize(9);
        s->setBorderColor(s->color());
    }
    QPen dashed(QColor(0x15, 0x65, 0xc0));
    dashed.setStyle(Qt::DashLine);
    dashed.setWidth(2);
    m_recommended->setPen(dashed);
    c->addAxis(m_axisX, Qt::AlignBottom);
    c->addAxis(m_axisY, Qt::AlignLeft);
    for (QXYSeries *s : std::initializer_list<QXYSeries *>{m_line, m_kept, m_lost, m_recommended}) {
        c->addSeries(s);
        s->attachAxis(m_axisX);
        s->attachAxis(m_axisY);
    }
    // The line joins the points; the legend names what the colours mean.
    c->legend()->markers(m_line).first()->setVisible(false);
    m_axisY->setLabelFormat(QStringLiteral("%.2f"));
    m_axisX->setLabelFormat(QStringLiteral("%d"));
    retranslate();
    fitAxes();
}

void MarginPlot::clear(bool accel)
{
    m_accel = accel;
    for (QXYSeries *s : std::initializer_list<QXYSeries *>{m_line, m_kept, m_lost, m_recommended})
        s->clear();
    retranslate();
    fitAxes();
}

void MarginPlot::addStep(const MarginStep &step)
{
    const double lost = step.lost.value_or(0);
    m_line->append(double(step.value), lost);
    (step.verdict == LostStepResult::Verdict::Lost ? m_lost : m_kept)
        ->append(double(step.value), lost);
    fitAxes();
}

void MarginPlot::setRecommended(std::optional<qint64> value)
{
    m_recommended->clear();
    if (value) {
        m_recommended->append(double(*value), m_axisY->min());
        m_recommended->append(double(*value), m_axisY->max());
    }
}

int MarginPlot::pointCount() const
{
    return int(m_line->count());
}

void MarginPlot::fitAxes()
{
    double xMin = 0, xMax = 100, yMin = -0.1, yMax = 0.1;
    const QList<QPointF> points = m_line->points();
    if (!points.isEmpty()) {
        const auto [lx, hx] = std::minmax_element(
            points.begin(), points.end(), [](QPointF a, QPointF b) { return a.x() < b.x(); });
        const auto [ly, hy] = std::minmax_element(
            points.begin(), points.end(), [](QPointF a, QPointF b) { return a.y() < b.y(); });
        const double span = std::max(1.0, hx->x() - lx->x());
        xMin = std::max(0.0, lx->x() - span * 0.1);
        xMax = hx->x() + span * 0.1;
        yMin = std::min(-0.1, ly->y() * 1.1);
        yMax = std::max(0.1, hy->y() * 1.1);
    }
    m_axisX->setRange(xMin, xMax);
    m_axisY->setRange(yMin, yMax);
}

void MarginPlot::retranslate()
{
    m_kept->setName(tr("kept its steps"));
    m_lost->setName(tr("lost steps"));
    m_recommended->setName(tr("recommended"));
    m_axisX->setTitleText(m_accel ? tr("Acceleration (Hz/ms)") : tr("Speed (rpm)"));
    m_axisY->setTitleText(tr("Lost (mm)"));
}

void MarginPlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QChartView::changeEvent(event);
}

} // namespace stepcom
