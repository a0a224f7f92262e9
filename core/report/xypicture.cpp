#include "report/xypicture.h"

#include "map/registermap.h"
#include "motion/pathsetup.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace stepcom {

namespace {
constexpr int kSamples = 180;
}

XyPicture::XyPicture(const RegisterMap &map, const QHash<QString, qint64> &values)
{
    using namespace interpolation;
    const RawValue raw = [&values](const QString &key) -> std::optional<qint64> {
        const auto it = values.constFind(key);
        return it == values.cend() ? std::nullopt : std::optional<qint64>(*it);
    };
    const LineSetup lineSetup = interpolation::lineSetup(map, raw);
    const InterpolationPath line = linePath(lineSetup);
    m_line.enabled = lineSetup.enabled;
    for (const double s : {0.0, line.length()}) {
        const Point p = line.pointAt(s);
        m_line.points << QPointF(p.x, p.y);
    }

    if (const Parameter *x = map.find(QStringLiteral("line.start_x")))
        m_unit = x->unit;
    const ArcSetup arcSetup = interpolation::arcSetup(map, raw);
    m_arc.enabled = arcSetup.enabled;
    const ArcPath arc = arcPath(arcSetup);
    switch (arc.problem) {
    case ArcProblem::None:
        for (int i = 0; i <= kSamples; ++i) {
            const Point p = arc.path->pointAt(arc.path->length() * i / kSamples);
            m_arc.points << QPointF(p.x, p.y);
        }
        break;
    case ArcProblem::PointsOnALine:
        m_arcProblem = tr("start, middle and end point are on one line");
        break;
    case ArcProblem::OnTheCentre:
        m_arcProblem = tr("the start point is the centre");
        break;
    }
}

double XyPicture::gridStep(double span)
{
    const double raw = std::max(span, 1e-9) / 6.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double f : {1.0, 2.0, 5.0}) {
        if (f * magnitude >= raw)
            return f * magnitude;
    }
    return 10.0 * magnitude;
}

QImage XyPicture::render(const QSize &size) const
{
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPixelSize(std::max(10, size.height() / 32));
    painter.setFont(font);
    const QFontMetricsF fm(font);

    QList<QPointF> all = m_line.points + m_arc.points;
    all << QPointF(0, 0);
    double minX = all.first().x(), maxX = minX, minY = all.first().y(), maxY = minY;
    for (const QPointF &p : std::as_const(all)) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y());
        maxY = std::max(maxY, p.y());
    }
    const double span = std::max({maxX - minX, maxY - minY, 1.0}) * 1.15;
    const double cx = (minX + maxX) / 2;
    const double cy = (minY + maxY) / 2;
    const double step = gridStep(span);
    const auto number = [step](double v) {
        const int decimals = step >= 1 ? 0 : int(std::ceil(-std::log10(step)));
        return QString::number(std::abs(v) < step / 1000 ? 0.0 : v, 'f', decimals);
    };
    // The plot: a square left of nothing but the values of the y grid, above the values of the
    // x grid and one line of legend.
    const double pad = fm.height() / 2;
    const double labelWidth =
        std::max(fm.horizontalAdvance(number(cy - span)), fm.horizontalAdvance(number(cy + span)));
    const QRectF area(pad + labelWidth + pad, pad, 0, 0);
    const double side = std::min(size.width() - area.left() - pad,
                                 size.height() - area.top() - 3.6 * fm.height() - pad);
    const QRectF plot(area.left(), area.top(), side, side);
    const QPointF origin = plot.center();
    auto toImage = [&](const QPointF &p) {
        return QPointF(origin.x() + (p.x() - cx) / span * side,
                       origin.y() - (p.y() - cy) / span * side); // y up, as on the machine
    };
    painter.setPen(QPen(QColor(200, 200, 200), 1));
    painter.drawRect(plot);

    // The grid, its values along the left and bottom edges: the picture has a scale.
    for (double x = std::ceil((cx - span / 2) / step) * step; x <= cx + span / 2; x += step) {
        const double px = toImage(QPointF(x, 0)).x();
        painter.setPen(QPen(QColor(230, 230, 230), 1));
        painter.drawLine(QPointF(px, plot.top()), QPointF(px, plot.bottom()));
        painter.setPen(Qt::darkGray);
        const QString t = number(x);
        painter.drawText(QPointF(px - fm.horizontalAdvance(t) / 2, plot.bottom() + fm.height()), t);
    }
    for (double y = std::ceil((cy - span / 2) / step) * step; y <= cy + span / 2; y += step) {
        const double py = toImage(QPointF(0, y)).y();
        painter.setPen(QPen(QColor(230, 230, 230), 1));
        painter.drawLine(QPointF(plot.left(), py), QPointF(plot.right(), py));
        painter.setPen(Qt::darkGray);
        const QString t = number(y);
        painter.drawText(QPointF(plot.left() - pad - fm.horizontalAdvance(t), py + fm.ascent() / 2),
                         t);
    }
    painter.setClipRect(plot);
    // Axes through the coordinate zero, with the motors and the unit named.
    painter.setPen(QPen(QColor(150, 150, 150), 1));
    const QPointF zero = toImage(QPointF(0, 0));
    painter.drawLine(QPointF(plot.left(), zero.y()), QPointF(plot.right(), zero.y()));
    painter.drawLine(QPointF(zero.x(), plot.top()), QPointF(zero.x(), plot.bottom()));
    painter.setPen(Qt::black);
    const QString unit = m_unit.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(m_unit);
    const QString xName = tr("X: motor 1") + unit;
    painter.drawText(QPointF(plot.right() - pad - fm.horizontalAdvance(xName),
                             std::min(zero.y(), plot.bottom()) - pad / 2),
                     xName);
    painter.drawText(QPointF(std::max(zero.x(), plot.left()) + pad, plot.top() + fm.height()),
                     tr("Y: motor 2") + unit);

    QList<std::pair<QString, QColor>> legend;
    auto drawShape = [&](const Shape &shape, const QColor &colour, const QString &name) {
        if (shape.points.size() < 2)
            return;
        QPainterPath path(toImage(shape.points.first()));
        for (qsizetype i = 1; i < shape.points.size(); ++i)
            path.lineTo(toImage(shape.points.at(i)));
        QPen pen(colour, std::max(2, size.height() / 150));
        if (!shape.enabled)
            pen.setStyle(Qt::DashLine);
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawPath(path);
        painter.setBrush(colour);
        const double r = std::max(3, size.height() / 100);
        painter.drawEllipse(toImage(shape.points.first()), r, r); // start: filled
        painter.setBrush(Qt::white);
        painter.drawEllipse(toImage(shape.points.last()), r * 1.4, r * 1.4); // end: hollow
        legend.append(
            {QStringLiteral("%1 (%2)").arg(name, shape.enabled ? tr("on") : tr("off")), colour});
    };
    drawShape(m_arc, QColor(30, 90, 200), tr("Arc"));
    drawShape(m_line, QColor(220, 110, 20), tr("Line"));
    painter.setClipping(false);

    // Under the plot: what is drawn in which colour and a scale bar of one grid step; then the
    // marks.
    const double baseline = plot.bottom() + 2.2 * fm.height();
    double x = plot.left();
    for (const auto &[text, colour] : std::as_const(legend)) {
        painter.setPen(colour);
        painter.drawText(QPointF(x, baseline), text);
        x += fm.horizontalAdvance(text) + 2 * fm.height();
    }
    painter.setPen(Qt::darkGray);
    painter.drawText(QPointF(plot.left(), baseline + 1.2 * fm.height()),
                     tr("● start   ○ end   dashed: interpolation off"));
    const double bar = step / span * side;
    const QString barText =
        number(step) + (m_unit.isEmpty() ? QString() : QLatin1Char(' ') + m_unit);
    const QPointF barEnd(plot.right(), baseline + pad);
    painter.setPen(QPen(Qt::black, 2));
    painter.drawLine(barEnd - QPointF(bar, 0), barEnd);
    painter.drawLine(barEnd - QPointF(bar, pad / 2), barEnd - QPointF(bar, -pad / 2));
    painter.drawLine(barEnd - QPointF(0, pad / 2), barEnd + QPointF(0, pad / 2));
    painter.drawText(
        QPointF(barEnd.x() - bar / 2 - fm.horizontalAdvance(barText) / 2, barEnd.y() - pad / 2 - 2),
        barText);
    return image;
}

} // namespace stepcom
