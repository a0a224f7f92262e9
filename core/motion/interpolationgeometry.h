#pragma once

#include "motion/pathsetup.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace stepcom {

// Checks an arc or line interpolation as the technician typed it, before anything is written or
// started, and works out what the controller will do with it: radius, centre, sweep, length.
// Distances are in the pitch's distance units (registers ×100); motor 1 is x, motor 2 is y,
// counter-clockwise (x towards y) is positive. The path is the one the simulator runs
// (pathsetup.h), so the preview draws what the simulator runs.
namespace interpolation {

// Start and end may differ in their distance from the centre by one register count.
inline constexpr double kRadiusTolerance = 0.01;

struct Geometry
{
    bool valid = false;
    QString error;     // why it cannot run (translated), empty when valid
    QStringList notes; // what is worth knowing about a valid path (full circle, ...)
    bool arc = false;
    std::optional<InterpolationPath> path;
    Point start;
    Point end;
    std::optional<Point> centre; // given (mode 0) or computed (mode 1)
    std::optional<Point> middle; // mode 1
    double startRadius = 0;
    double endRadius = 0;
    double radiusDifference = 0; // |end radius - start radius|
    bool fullCircle = false;
    double sweepDegrees = 0; // signed: positive counter-clockwise
    double length = 0;
    double radius() const { return (startRadius + endRadius) / 2; }
};

// The arc's enabled flag and speed play no part in the checks.
Geometry arc(const ArcSetup &setup);
Geometry line(Point start, Point end);

} // namespace interpolation

} // namespace stepcom
