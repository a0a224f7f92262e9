#pragma once

#include "motion/motorderived.h"
#include "motion/pathsetup.h"

#include <QList>

#include <optional>

namespace stepcom::interpolation {

// The move along a path at `speedRpm`: the controller (as the simulator models it) runs the path
// length with motor 1's pulse rates (start frequency, acceleration, the speed as motor 1
// revolutions per minute), so the time is motor 1's single move over the path length. nullopt
// when a motor 1 value it needs is unknown or zero.
std::optional<double> pathUnitsPerSecond(double speedRpm, const MotorParameters &motor1);
std::optional<double> pathTimeMs(double length, double speedRpm, const MotorParameters &motor1);

// Before the path the controller drives each axis on its own to the start point (the manual:
// "each first moves there separately"); both start at once, each with its own speed and ramp,
// so the way there is a straight piece until the first axis arrives and then the other axis
// alone. `points` is that polyline (from, corner, to; the corner is left out when both arrive
// together or only one axis moves); timeMs is when the last axis arrives.
struct Approach
{
    QList<Point> points;
    std::optional<double> timeMs;
    bool exact = false; // false: a motor's parameters are unknown, drawn as equal speeds
};
Approach approach(Point from, Point to, const MotorParameters &motor1,
                  const MotorParameters &motor2);

// Motor 1's and motor 2's position registers (distance units ×100).
struct Counts
{
    qint64 x = 0;
    qint64 y = 0;
    bool operator==(const Counts &) const = default;
};
// Where the position registers stand after the approach (the start point) and after the path
// (the end point): the controller sends whole pulses, so a point between two pulses ends on the
// nearer one. nullopt when a motor's step angle, microsteps or pitch is unknown or zero.
struct PathTargets
{
    Counts approach;
    Counts end;
};
std::optional<PathTargets> pathTargets(Point start, Point end, const MotorParameters &motor1,
                                       const MotorParameters &motor2);

} // namespace stepcom::interpolation
