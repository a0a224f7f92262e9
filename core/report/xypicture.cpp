#include "report/xypicture.h"

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

QImage XyPicture::render(const QSize &size) const
{
    QImage image(size, QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);

    QList<QPointF> all = m_line.points + m_arc.points;
    all << QPointF(0, 0);
    double minX = all.first().x(), maxX = minX, minY = all.first().y(), maxY = minY;
    for (const QPointF &p : std::as_const(all)) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y());
        maxY = std::max(maxY, p.y());
    }
    double span = std::max({maxX - minX, maxY - minY, 1.0}) * 1.1;
    const double cx = (minX + maxX) / 2;
    const double cy = (minY + maxY) / 2;
    const int margin = size.height() / 10;
    const double side = std::min(size.width(), size.height()) - 2.0 * margin;
    const QPointF origin(size.width() / 2.0, size.height() / 2.0);
    auto toImage = [&](const QPointF &p) {
        return QPointF(origin.x() + (p.x() - cx) / span * side,
                       origin.y() - (p.y() - cy) / span * side); // y up, as on the machine
    };

    QFont font = painter.font();
    font.setPixelSize(std::max(10, size.height() / 32));
    painter.setFont(font);
    // Axes through the coordinate zero, with the motors named.
    painter.setPen(QPen(QColor(150, 150, 150), 1));
    const QPointF zero = toImage(QPointF(0, 0));
    painter.drawLine(QPointF(margin / 2.0, zero.y()),
                     QPointF(size.width() - margin / 2.0, zero.y()));
    painter.drawLine(QPointF(zero.x(), margin / 2.0),
                     QPointF(zero.x(), size.height() - margin / 2.0));
    painter.setPen(Qt::black);
    const QFontMetricsF fm(font);
    const QString xName = tr("X: motor 1");
    painter.drawText(
        QPointF(size.width() - margin / 2.0 - fm.horizontalAdvance(xName), zero.y() - 4), xName);
    painter.drawText(QPointF(zero.x() + 4, margin / 2.0 + fm.height()), tr("Y: motor 2"));

    auto drawShape = [&](const Shape &shape, const QColor &colour, const QString &name, int row) {
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
        painter.setPen(colour);
        const QString state = shape.enabled ? tr("on") : tr("off");
        painter.drawText(
            QPointF(margin / 2.0, size.height() - margin / 3.0 - fm.height() * (2.2 - row * 1.1)),
            QStringLiteral("%1 (%2)").arg(name, state));
    };
    drawShape(m_arc, QColor(30, 90, 200), tr("Arc"), 0);
    drawShape(m_line, QColor(220, 110, 20), tr("Line"), 1);
    painter.setPen(Qt::darkGray);
    painter.drawText(QPointF(margin / 2.0, size.height() - margin / 3.0),
                     tr("● start   ○ end   dashed: interpolation off"));
    return image;
}

} // namespace stepcom
