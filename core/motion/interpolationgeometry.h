#pragma once

#include "motion/interpolationpath.h"
#include "motion/motorderived.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace stepcom {

class RegisterMap;

// Checks an arc or line interpolation as the technician typed it, before anything is written or
// started, and works out what the controller will do with it: radius, centre, sweep, length,
// time, and the approach move. Distances are in the pitch's distance units (registers ×100);
// motor 1 is x, motor 2 is y, counter-clockwise (x towards y) is positive. The path itself is
// the simulator's InterpolationPath, so the preview draws what the simulator runs.
namespace interpolation {

using Point = InterpolationPath::Point;

// Start and end may differ in their distance from the centre by one register count.
inline constexpr double kRadiusTolerance = 0.01;

enum class ArcMode { Centre = 0, ThreePoints = 1 }; // register 40183

struct ArcInput
{
    ArcMode mode = ArcMode::Centre;
    Point start;
    Point end;
    Point centre; // mode Centre
    Point middle; // mode ThreePoints
    bool counterClockwise = false;
};

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

Geometry arc(const ArcInput &input);
Geometry line(Point start, Point end);

// The move along the path at `speedRpm`: the simulator's interpolator runs the path length with
// motor 1's pulse rates (start frequency, acceleration, the speed as motor 1 revolutions per
// minute), so the time is motor 1's single move over the path length. nullopt when a motor 1
// value it needs is unknown or zero.
std::optional<double> pathUnitsPerSecond(double speedRpm, const MotorParameters &motor1);
std::optional<double> pathTimeMs(double length, double speedRpm, const MotorParameters &motor1);

// Before the path the controller drives each axis on its own to the start point (the manual:
// "each first moves there separately"); the simulator starts both at once, each with its own
// speed and ramp, so the way there is a straight piece until the first axis arrives and then
// the other axis alone. `points` is that polyline (from, corner, to; the corner is left out
// when both arrive together or only one axis moves); timeMs is when the last axis arrives.
struct Approach
{
    QList<Point> points;
    std::optional<double> timeMs;
    bool exact = false; // false: a motor's parameters are unknown, drawn as equal speeds
};
Approach approach(Point from, Point to, const MotorParameters &motor1,
                  const MotorParameters &motor2);

// A motor's parameters from raw register values by map key (the store's shown values, or a
// simulated device's), for the estimates above.
MotorParameters motorParameters(const RegisterMap &map, int motor,
                                const std::function<std::optional<qint64>(const QString &)> &raw);

} // namespace interpolation

} // namespace stepcom
