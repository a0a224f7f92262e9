#pragma once

#include "motion/interpolationpath.h"
#include "motion/motorderived.h"

#include <QString>
#include <QtGlobal>

#include <functional>
#include <optional>

namespace stepcom {

class RegisterMap;

// The arc (40182-40201) and the line (40202-40211) as the registers hold them, and the path the
// controller runs from them. Distances are in the pitch's distance units (registers ×100); motor
// 1 is x, motor 2 is y, counter-clockwise (x towards y) is positive.
namespace interpolation {

using Point = InterpolationPath::Point;
// A raw register value by map key; nullopt when it is not known.
using RawValue = std::function<std::optional<qint64>(const QString &key)>;

// Two points closer than half a register count are the same point for the controller.
inline constexpr double kSamePoint = 0.005;

enum class ArcMode { Centre = 0, ThreePoints = 1 }; // register 40183

struct ArcSetup
{
    bool enabled = false; // 40182 is 1
    ArcMode mode = ArcMode::Centre;
    Point start;
    Point end;
    Point centre;                  // mode Centre
    Point middle;                  // mode ThreePoints
    bool counterClockwise = false; // 40200 is 1
    double speedRpm = 0;           // 40201, as motor 1 revolutions per minute along the path
};

struct LineSetup
{
    bool enabled = false; // 40202 is 1
    Point start;
    Point end;
    double speedRpm = 0; // 40211
};

// From raw register values by map key; a value not known counts as 0.
ArcSetup arcSetup(const RegisterMap &map, const RawValue &raw);
LineSetup lineSetup(const RegisterMap &map, const RawValue &raw);
// A motor's parameters (motor 1 or 2) from raw register values, nullopt where not known.
MotorParameters motorParameters(const RegisterMap &map, int motor, const RawValue &raw);

// The centre the arc turns around: the given one (mode 0), or the centre of the circle through
// start, middle and end (mode 1; the direction register still chooses the way round). nullopt
// when the three points are on one line.
std::optional<Point> arcCentre(const ArcSetup &arc);

enum class ArcProblem { None, PointsOnALine, OnTheCentre };
struct ArcPath
{
    std::optional<InterpolationPath> path;
    ArcProblem problem = ArcProblem::None;
};
// The arc as the controller runs it, without the editor's checks: a start and end at different
// distances from the centre make a spiral. No path when start or end is the centre or the three
// points are on one line.
ArcPath arcPath(const ArcSetup &arc);
InterpolationPath linePath(const LineSetup &line);

} // namespace interpolation

} // namespace stepcom
