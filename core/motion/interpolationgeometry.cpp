#include "motion/interpolationgeometry.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stepcom::interpolation {

namespace {

double distance(Point a, Point b)
{
    return std::hypot(b.x - a.x, b.y - a.y);
}

bool same(Point a, Point b)
{
    return distance(a, b) < kSamePoint;
}

QString number(double v)
{
    return QString::number(v, 'f', 2);
}

QString pointText(Point p)
{
    return QStringLiteral("(%1, %2)").arg(number(p.x), number(p.y));
}

void fillArc(Geometry &g, const InterpolationPath &path)
{
    g.path = path;
    g.sweepDegrees = path.sweep() * 180.0 / std::numbers::pi;
    g.length = path.length();
}

// Does the arc swept from `path`'s start pass the point `p` (seen from the centre)?
bool sweepContains(const InterpolationPath &path, Point p)
{
    const Point c = path.centre();
    const double startAngle = std::atan2(path.start().y - c.y, path.start().x - c.x);
    const double angle = std::atan2(p.y - c.y, p.x - c.x);
    constexpr double twoPi = 2 * std::numbers::pi;
    double along = std::fmod(angle - startAngle, twoPi); // counter-clockwise from the start
    if (along < 0)
        along += twoPi;
    if (path.sweep() < 0)
        along = along == 0 ? 0 : twoPi - along;
    return along <= std::abs(path.sweep()) + 1e-9;
}

} // namespace

Geometry arc(const ArcSetup &in)
{
    Geometry g;
    g.arc = true;
    g.start = in.start;
    g.end = in.end;
    if (in.mode == ArcMode::ThreePoints) {
        g.middle = in.middle;
        if (same(in.start, in.end)) {
            g.error = QCoreApplication::translate(
                "stepcom::InterpolationGeometry",
                "Start and end are the same point: three points cannot describe a full "
                "circle. Use the centre mode for a full circle.");
            return g;
        }
        if (same(in.middle, in.start) || same(in.middle, in.end)) {
            g.error = QCoreApplication::translate(
                          "stepcom::InterpolationGeometry",
                          "The middle point %1 is the same as the start or the end point: three "
                          "distinct points are needed.")
                          .arg(pointText(in.middle));
            return g;
        }
        const std::optional<Point> c = arcCentre(in);
        if (!c) {
            g.error = QCoreApplication::translate(
                "stepcom::InterpolationGeometry",
                "Start, middle and end are on one straight line: no circle passes "
                "through them. Use the line editor for a straight move.");
            return g;
        }
        g.centre = *c;
    } else {
        g.centre = in.centre;
    }
    const Point c = *g.centre;
    g.startRadius = distance(in.start, c);
    g.endRadius = distance(in.end, c);
    g.radiusDifference = std::abs(g.endRadius - g.startRadius);
    if (g.startRadius < kSamePoint) {
        g.error = QCoreApplication::translate("stepcom::InterpolationGeometry",
                                              "The start point is the centre: the radius is zero.");
        return g;
    }
    if (g.endRadius < kSamePoint) {
        g.error = QCoreApplication::translate("stepcom::InterpolationGeometry",
                                              "The end point is the centre: the radius is zero.");
        return g;
    }
    if (g.radiusDifference > kRadiusTolerance + 1e-9) {
        g.error = QCoreApplication::translate(
                      "stepcom::InterpolationGeometry",
                      "Start and end are not the same distance from the centre: start radius %1, "
                      "end radius %2, difference %3 (at most %4 allowed).")
                      .arg(number(g.startRadius), number(g.endRadius), number(g.radiusDifference),
                           number(kRadiusTolerance));
        return g;
    }
    const std::optional<InterpolationPath> path = arcPath(in).path;
    if (!path) {
        g.error = QCoreApplication::translate("stepcom::InterpolationGeometry",
                                              "The start point is the centre: the radius is zero.");
        return g;
    }
    fillArc(g, *path);
    g.fullCircle = same(in.start, in.end);
    if (g.fullCircle)
        g.notes << QCoreApplication::translate(
            "stepcom::InterpolationGeometry",
            "Start and end are the same point: this is a full circle.");
    if (in.mode == ArcMode::ThreePoints && !sweepContains(*path, in.middle))
        g.notes << QCoreApplication::translate(
            "stepcom::InterpolationGeometry",
            "The arc in the chosen direction does not pass through the middle point: "
            "the controller goes the other way round the circle. Change the direction "
            "to pass through it.");
    g.valid = true;
    return g;
}

Geometry line(Point start, Point end)
{
    Geometry g;
    g.start = start;
    g.end = end;
    if (same(start, end)) {
        g.error = QCoreApplication::translate(
                      "stepcom::InterpolationGeometry",
                      "Start and end are the same point %1: the line has no length.")
                      .arg(pointText(start));
        return g;
    }
    g.path = InterpolationPath::line(start, end);
    g.length = g.path->length();
    g.valid = true;
    return g;
}

} // namespace stepcom::interpolation
