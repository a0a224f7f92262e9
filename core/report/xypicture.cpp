#include "report/xypicture.h"

#include "map/registermap.h"
#include "motion/interpolationpath.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace stepcom {

namespace {
constexpr int kSamples = 180;
}

double XyPicture::value(const char *key) const
{
    const Parameter *p = m_map.find(QLatin1String(key));
    if (!p)
        return 0;
    return p->toEngineering(m_values.value(p->key));
}

XyPicture::XyPicture(const RegisterMap &map, const QHash<QString, qint64> &values)
    : m_map(map)
    , m_values(values)
{
    using Point = InterpolationPath::Point;
    const Point lineStart{value("line.start_x"), value("line.start_y")};
    const Point lineEnd{value("line.end_x"), value("line.end_y")};
    const InterpolationPath line = InterpolationPath::line(lineStart, lineEnd);
    m_line.enabled = value("line.enabled") != 0;
    for (const double s : {0.0, line.length()}) {
        const Point p = line.pointAt(s);
        m_line.points << QPointF(p.x, p.y);
    }

    m_arc.enabled = value("arc.enabled") != 0;
    const Point start{value("arc.start_x"), value("arc.start_y")};
    const Point end{value("arc.end_x"), value("arc.end_y")};
    std::optional<Point> centre;
    if (value("arc.mode") == 0) {
        centre = Point{value("arc.center_x"), value("arc.center_y")};
    } else {
        centre = InterpolationPath::circleCentre(
            start, Point{value("arc.middle_x"), value("arc.middle_y")}, end);
        if (!centre)
            m_arcProblem = tr("start, middle and end point are on one line");
    }
    if (centre) {
        const auto arc =
            InterpolationPath::arcAroundCentre(start, end, *centre, value("arc.direction") != 0);
        if (!arc) {
            m_arcProblem = tr("the start point is the centre");
        } else {
            for (int i = 0; i <= kSamples; ++i) {
                const Point p = arc->pointAt(arc->length() * i / kSamples);
                m_arc.points << QPointF(p.x, p.y);
            }
        }
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
