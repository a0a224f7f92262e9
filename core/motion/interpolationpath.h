#pragma once

#include <optional>
#include <utility>

namespace stepcom {

// The geometry of a two-axis interpolation in distance units: a straight line or a circular
// arc, walked by arc length. Motor 1 is x, motor 2 is y; counter-clockwise is the mathematical
// positive sense (x towards y).
class InterpolationPath
{
public:
    struct Point
    {
        double x = 0;
        double y = 0;
    };

    static InterpolationPath line(Point start, Point end);
    // Arc around `centre`; start == end is a full circle. When the end is not on the circle the
    // radius changes evenly along the way (as CNC controls do), so the path still ends there.
    // nullopt when the start is the centre.
    static std::optional<InterpolationPath> arcAroundCentre(Point start, Point end, Point centre,
                                                            bool counterClockwise);
    // The centre of the circle through three points; nullopt when they are on one line.
    static std::optional<Point> circleCentre(Point a, Point b, Point c);

    bool isArc() const { return m_arc; }
    double length() const { return m_length; }
    Point start() const { return m_start; }
    Point end() const { return m_end; }
    Point centre() const { return m_centre; }
    double sweep() const { return m_sweep; }
    // The point at arc length s (clamped to the path); the end point exactly at the end.
    Point pointAt(double s) const;
    // The way each axis first moves from the start: the sign of dx and dy (-1, 0 or 1) of the
    // path's tangent there (an arc's start is across the radius, plus the spiral's radial
    // part). An axis the tangent leaves alone (a rounding residue is no move) reads 0.
    std::pair<int, int> startDirection() const;

private:
    bool m_arc = false;
    Point m_start;
    Point m_end;
    Point m_centre;
    double m_startAngle = 0;
    double m_sweep = 0; // signed, radians
    double m_startRadius = 0;
    double m_endRadius = 0;
    double m_length = 0;
};

} // namespace stepcom
