#include "motion/interpolationpath.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stepcom {

InterpolationPath InterpolationPath::line(Point start, Point end)
{
    InterpolationPath p;
    p.m_start = start;
    p.m_end = end;
    p.m_length = std::hypot(end.x - start.x, end.y - start.y);
    return p;
}

std::optional<InterpolationPath>
InterpolationPath::arcAroundCentre(Point start, Point end, Point centre, bool counterClockwise)
{
    InterpolationPath p;
    p.m_arc = true;
    p.m_start = start;
    p.m_end = end;
    p.m_centre = centre;
    p.m_startRadius = std::hypot(start.x - centre.x, start.y - centre.y);
    p.m_endRadius = std::hypot(end.x - centre.x, end.y - centre.y);
    if (p.m_startRadius < 1e-9 || p.m_endRadius < 1e-9)
        return std::nullopt;
    constexpr double twoPi = 2 * std::numbers::pi;
    p.m_startAngle = std::atan2(start.y - centre.y, start.x - centre.x);
    const double endAngle = std::atan2(end.y - centre.y, end.x - centre.x);
    // Sweep in (0, 2π] in the chosen sense: equal start and end points make a full circle.
    double ccwSweep = std::fmod(endAngle - p.m_startAngle, twoPi);
    if (ccwSweep <= 1e-12)
        ccwSweep += twoPi;
    if (counterClockwise) {
        p.m_sweep = ccwSweep;
    } else {
        double cwSweep = twoPi - ccwSweep;
        if (cwSweep <= 1e-12)
            cwSweep = twoPi;
        p.m_sweep = -cwSweep;
    }
    p.m_length = std::abs(p.m_sweep) * (p.m_startRadius + p.m_endRadius) / 2;
    return p;
}

std::optional<InterpolationPath::Point> InterpolationPath::circleCentre(Point a, Point b, Point c)
{
    const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
    const double scale = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y),
                                   std::abs(c.x), std::abs(c.y), 1.0});
    if (std::abs(d) < 1e-9 * scale * scale)
        return std::nullopt;
    const double a2 = a.x * a.x + a.y * a.y;
    const double b2 = b.x * b.x + b.y * b.y;
    const double c2 = c.x * c.x + c.y * c.y;
    return Point{(a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d,
                 (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d};
}

InterpolationPath::Point InterpolationPath::pointAt(double s) const
{
    if (m_length <= 0 || s >= m_length)
        return m_end;
    if (s <= 0)
        return m_start;
    const double t = s / m_length;
    if (!m_arc)
        return {m_start.x + (m_end.x - m_start.x) * t, m_start.y + (m_end.y - m_start.y) * t};
    const double angle = m_startAngle + m_sweep * t;
    const double radius = m_startRadius + (m_endRadius - m_startRadius) * t;
    return {m_centre.x + radius * std::cos(angle), m_centre.y + radius * std::sin(angle)};
}

std::pair<int, int> InterpolationPath::startDirection() const
{
    double dx = m_end.x - m_start.x;
    double dy = m_end.y - m_start.y;
    if (m_arc) {
        // d/dt of centre + r(t)·(cos a(t), sin a(t)) at t = 0.
        const double c = std::cos(m_startAngle);
        const double s = std::sin(m_startAngle);
        const double dr = m_endRadius - m_startRadius;
        dx = dr * c - m_startRadius * m_sweep * s;
        dy = dr * s + m_startRadius * m_sweep * c;
    }
    const double norm = std::hypot(dx, dy);
    const auto sign = [norm](double v) { return std::abs(v) <= 1e-9 * norm ? 0 : v > 0 ? 1 : -1; };
    return {sign(dx), sign(dy)};
}

} // namespace stepcom
