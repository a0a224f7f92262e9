#include "motion/motionjudge.h"

#include "i18n/translators.h"
#include "map/registermap.h"
#include "motion/interpolationtiming.h"
#include "motion/pathsetup.h"

#include <cmath>

namespace stepcom {

namespace {

std::optional<qint64> get(const StatusValues &v, const QString &key)
{
    const auto it = v.constFind(key);
    if (key.isEmpty() || it == v.cend())
        return std::nullopt;
    return *it;
}

const Parameter *motorParam(const RegisterMap &map, int motor, const char *local)
{
    return map.blockParameter(kMotorBlock, motor, QLatin1String(local));
}

std::optional<qint64> motorValue(const RegisterMap &map, const StatusValues &v, int motor,
                                 const char *local)
{
    const Parameter *p = motorParam(map, motor, local);
    return p ? get(v, p->key) : std::nullopt;
}

bool inputOn(const StatusValues &v, qint64 input)
{
    return input > 0 && get(v, QStringLiteral("io.in%1").arg(input)).value_or(0) == 1;
}

// Modes 1-5 give the inputs other meanings and ignore the limit registers.
bool limitsApply(const StatusValues &v)
{
    return get(v, QStringLiteral("mode.system")).value_or(0) == 0;
}

// The input number of motor's limit in `direction` (+1/-1) when it reads ON, else 0.
int limitOn(const RegisterMap &map, const StatusValues &v, int motor, int direction)
{
    if (!limitsApply(v))
        return 0;
    const qint64 input =
        motorValue(map, v, motor, direction > 0 ? "limit_positive" : "limit_negative").value_or(0);
    return inputOn(v, input) ? int(input) : 0;
}

// An arc or line as the controller will run it from the values held (core/motion reads the
// registers): the start point the approach drives to and the end point, as position counts,
// and the way each axis first moves along the path (0: not at first, or not known).
struct PathPlan
{
    interpolation::Counts approach;
    interpolation::Counts end;
    std::pair<int, int> firstDirection{0, 0};
};

// nullopt when a start or end coordinate, or a motor's step angle, microsteps or pitch is not
// known: no end point is guessed.
std::optional<PathPlan> pathPlan(const RegisterMap &map, const StatusValues &v, MotionKind kind)
{
    const bool arc = kind == MotionKind::Arc;
    const QString prefix = arc ? QStringLiteral("arc.") : QStringLiteral("line.");
    for (const char *k : {"start_x", "start_y", "end_x", "end_y"}) {
        if (!get(v, prefix + QLatin1String(k)))
            return std::nullopt;
    }
    const interpolation::RawValue raw = [&v](const QString &key) { return get(v, key); };
    interpolation::Point start;
    interpolation::Point end;
    std::optional<InterpolationPath> path;
    if (arc) {
        const interpolation::ArcSetup a = interpolation::arcSetup(map, raw);
        start = a.start;
        end = a.end;
        // The centre (or the middle point) must be known for the way round, not for the end.
        const QString point =
            prefix + (a.mode == interpolation::ArcMode::ThreePoints ? QStringLiteral("middle")
                                                                    : QStringLiteral("center"));
        if (get(v, point + QStringLiteral("_x")) && get(v, point + QStringLiteral("_y")))
            path = interpolation::arcPath(a).path;
    } else {
        const interpolation::LineSetup l = interpolation::lineSetup(map, raw);
        start = l.start;
        end = l.end;
        path = interpolation::linePath(l);
    }
    const auto targets =
        interpolation::pathTargets(start, end, interpolation::motorParameters(map, 1, raw),
                                   interpolation::motorParameters(map, 2, raw));
    if (!targets)
        return std::nullopt;
    PathPlan plan{targets->approach, targets->end};
    if (path)
        plan.firstDirection = path->startDirection();
    return plan;
}

int sign(double d)
{
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

QString motorsText(const QList<int> &motors)
{
    QStringList n;
    for (int m : motors)
        n << QString::number(m);
    return Translators::joinList(n);
}

} // namespace

std::optional<MotionKind> MotionJudge::kindOf(const RegisterMap &map, const QString &command)
{
    const Parameter *p = map.find(command);
    if (!p || !p->isCoil())
        return std::nullopt;
    if (p->block == kMotorBlock && p->localKey == QLatin1String("move"))
        return MotionKind::SingleMove;
    if (p->block == kMotorBlock && p->localKey == QLatin1String("home"))
        return MotionKind::Home;
    if (command == QLatin1String("home_all"))
        return MotionKind::HomeInOrder;
    if (command == QLatin1String("return_to_zero"))
        return MotionKind::ReturnToZero;
    if (command == QLatin1String("arc.start"))
        return MotionKind::Arc;
    if (command == QLatin1String("line.start"))
        return MotionKind::Line;
    return std::nullopt;
}

QStringList MotionJudge::watchKeys(const RegisterMap &map)
{
    QStringList keys;
    for (int n = 1; n <= map.blockCount(kMotorBlock); ++n) {
        for (const char *local : {"position", "running"}) {
            if (const Parameter *p = motorParam(map, n, local))
                keys << p->key;
        }
    }
    for (int n = 1; map.find(QStringLiteral("io.in%1").arg(n)); ++n)
        keys << QStringLiteral("io.in%1").arg(n);
    return keys;
}

QStringList MotionJudge::inputKeys(const RegisterMap &map, const QString &command)
{
    const auto kind = kindOf(map, command);
    if (!kind)
        return {};
    QStringList keys = watchKeys(map);
    const auto add = [&keys](const Parameter *p) {
        if (p && p->readable() && !keys.contains(p->key))
            keys << p->key;
    };
    add(map.find(QStringLiteral("mode.system")));
    QList<int> motors;
    switch (*kind) {
    case MotionKind::SingleMove:
    case MotionKind::Home:
        motors = {map.find(command)->instance};
        break;
    case MotionKind::HomeInOrder:
        add(map.find(QStringLiteral("homing.first")));
        add(map.find(QStringLiteral("homing.second")));
        [[fallthrough]];
    case MotionKind::ReturnToZero:
    case MotionKind::Arc:
    case MotionKind::Line:
        for (int n = 1; n <= map.blockCount(kMotorBlock); ++n)
            motors << n;
        break;
    }
    const bool path = *kind == MotionKind::Arc || *kind == MotionKind::Line;
    for (int n : std::as_const(motors)) {
        for (const char *local :
             {"move_distance", "direction", "limit_positive", "limit_negative", "home_input"})
            add(motorParam(map, n, local));
        // The path's end points in counts need each axis's step angle, microsteps and pitch.
        if (path) {
            for (const Parameter *p : map.holdings()) {
                if (p->block == kMotorBlock && p->instance == n)
                    add(p);
            }
        }
    }
    if (path) {
        const QString prefix =
            *kind == MotionKind::Arc ? QStringLiteral("arc.") : QStringLiteral("line.");
        for (const Parameter *p : map.holdings()) {
            if (p->key.startsWith(prefix))
                add(p);
        }
    }
    return keys;
}

std::optional<MotionStart> MotionJudge::plan(const RegisterMap &map, const QString &command,
                                             const StatusValues &before)
{
    const auto kind = kindOf(map, command);
    if (!kind)
        return std::nullopt;
    MotionStart s;
    s.kind = *kind;
    s.command = command;
    const int motors = map.blockCount(kMotorBlock);
    switch (*kind) {
    case MotionKind::SingleMove: {
        const int n = map.find(command)->instance;
        const Parameter *pos = motorParam(map, n, "position");
        const Parameter *dist = motorParam(map, n, "move_distance");
        const auto p = motorValue(map, before, n, "position");
        const auto d = motorValue(map, before, n, "move_distance");
        const auto dir = motorValue(map, before, n, "direction");
        if (!pos || !dist || !p || !d || !dir)
            return std::nullopt;
        const double units = dist->toEngineering(*d) * (*dir ? -1 : 1);
        s.motors = {n};
        s.target.insert(n, *p + qint64(std::llround(units * pos->scale)));
        break;
    }
    case MotionKind::Home:
        s.motors = {map.find(command)->instance};
        break;
    case MotionKind::HomeInOrder:
        for (const char *k : {"homing.first", "homing.second"}) {
            const qint64 m = get(before, QLatin1String(k)).value_or(0);
            if (m >= 1 && m <= motors && !s.motors.contains(int(m)))
                s.motors << int(m);
        }
        if (s.motors.isEmpty())
            return std::nullopt; // nothing in the order: the controller does not move
        break;
    case MotionKind::ReturnToZero:
        // The controller drives every idle motor back to 0 (a running one keeps going).
        for (int n = 1; n <= motors; ++n) {
            if (motorValue(map, before, n, "running").value_or(1) == 0) {
                s.motors << n;
                s.target.insert(n, 0);
            }
        }
        if (s.motors.isEmpty())
            return std::nullopt;
        break;
    case MotionKind::Arc:
    case MotionKind::Line: {
        const auto path = pathPlan(map, before, *kind);
        if (!path)
            return std::nullopt;
        s.motors = {1, 2};
        s.target.insert(1, path->end.x);
        s.target.insert(2, path->end.y);
        break;
    }
    }
    return s;
}

MotionOutcome MotionJudge::judge(const RegisterMap &map, const MotionStart &start,
                                 const StatusValues &end, MotionCause cause)
{
    MotionOutcome o;
    o.start = start;
    o.cause = cause;
    const bool homing = start.kind == MotionKind::Home || start.kind == MotionKind::HomeInOrder;
    bool allGood = !start.motors.isEmpty();
    for (int n : start.motors) {
        AxisEnd a;
        a.motor = n;
        a.position = motorValue(map, end, n, "position");
        if (start.target.contains(n))
            a.target = start.target.value(n);
        a.atTarget = a.position && a.target && std::abs(*a.position - *a.target) <= 1;
        a.homeInput = int(motorValue(map, end, n, "home_input").value_or(0));
        a.homeInputOn = inputOn(end, a.homeInput);
        // Where the controller zeroes the position on the home input, it reads exactly 0.
        a.referenced = cause == MotionCause::None && a.homeInput > 0 && a.homeInputOn &&
                       a.position && *a.position == 0;
        a.limitPositiveOn = limitOn(map, end, n, 1);
        a.limitNegativeOn = limitOn(map, end, n, -1);
        allGood = allGood && (homing ? a.referenced : a.atTarget);
        o.axes << a;
    }
    using V = MotionOutcome::Verdict;
    if (cause == MotionCause::Silent)
        o.verdict = V::NotKnown; // not "interrupted", not "stopped": nothing showed how it ended
    else if (homing)
        o.verdict = cause != MotionCause::None ? V::Interrupted
                    : allGood                  ? V::Referenced
                                               : V::NoHomeInput;
    else
        o.verdict = allGood ? V::Done : V::Stopped;
    return o;
}

QString MotionJudge::limitWarning(const RegisterMap &map, const QString &command,
                                  const StatusValues &now)
{
    if (!limitsApply(now))
        return {};
    const auto kind = kindOf(map, command);
    if (!kind)
        return {};
    QStringList warnings;
    const auto check = [&](int motor, int direction, const QString &what) {
        if (direction == 0)
            return;
        if (const int input = limitOn(map, now, motor, direction))
            warnings << (direction > 0 ? tr("Motor %1's positive limit (IN%2) is already ON and "
                                            "%3 drives motor %1 forward: it stops at once.")
                                       : tr("Motor %1's negative limit (IN%2) is already ON and "
                                            "%3 drives motor %1 in reverse: it stops at once."))
                            .arg(motor)
                            .arg(input)
                            .arg(what);
    };
    switch (*kind) {
    case MotionKind::SingleMove: {
        const int n = map.find(command)->instance;
        if (const auto dir = motorValue(map, now, n, "direction"))
            check(n, *dir ? -1 : 1, tr("the single move"));
        break;
    }
    case MotionKind::Home:
    case MotionKind::HomeInOrder:
        break; // homing reverses onto its own switch, which is often the negative limit
    case MotionKind::ReturnToZero:
        for (int n = 1; n <= map.blockCount(kMotorBlock); ++n) {
            if (const auto p = motorValue(map, now, n, "position"))
                check(n, sign(double(-*p)), tr("the return to data zero"));
        }
        break;
    case MotionKind::Arc:
    case MotionKind::Line: {
        const bool arc = *kind == MotionKind::Arc;
        const auto path = pathPlan(map, now, *kind);
        if (!path)
            break;
        for (int n = 1; n <= 2; ++n) {
            const auto here = motorValue(map, now, n, "position");
            const qint64 start = n == 1 ? path->approach.x : path->approach.y;
            if (!here)
                continue;
            // Not at the start point yet: the approach drives this axis there first.
            if (std::abs(start - *here) > 1) {
                check(n, sign(double(start - *here)), tr("the approach to the start point"));
                continue;
            }
            check(n, n == 1 ? path->firstDirection.first : path->firstDirection.second,
                  arc ? tr("the arc") : tr("the line"));
        }
        break;
    }
    }
    return warnings.join(QLatin1Char(' '));
}

QString MotionJudge::name(const MotionStart &start)
{
    switch (start.kind) {
    case MotionKind::SingleMove:
        return tr("Single move of motor %1").arg(motorsText(start.motors));
    case MotionKind::Home:
        return tr("Homing motor %1").arg(motorsText(start.motors));
    case MotionKind::HomeInOrder:
        return tr("Homing in order");
    case MotionKind::ReturnToZero:
        return tr("Return to data zero");
    case MotionKind::Arc:
        return tr("Arc");
    case MotionKind::Line:
        return tr("Line");
    }
    return {};
}

QString MotionJudge::causeText(MotionCause cause)
{
    switch (cause) {
    case MotionCause::Stop:
        return tr("stop");
    case MotionCause::EmergencyStop:
        return tr("E-STOP");
    case MotionCause::LinkLost:
        return tr("link lost");
    case MotionCause::Silent:
        return tr("no answer while it moved; the controller may have restarted");
    case MotionCause::Restarted:
        return tr("the controller restarted");
    case MotionCause::None:
        break;
    }
    return {};
}

QString MotionJudge::text(const RegisterMap &map, const MotionOutcome &o)
{
    const QString lang = Translators::current();
    // One axis: "−20.66 mm"; two: "(x, y) mm"; more: "motor 1 at …, motor 2 at …".
    const auto where = [&](bool target) {
        QStringList parts;
        QString unit;
        for (const AxisEnd &a : o.axes) {
            const Parameter *p = motorParam(map, a.motor, "position");
            const auto raw = target ? a.target : a.position;
            if (!p || !raw)
                return tr("an unknown position");
            parts << (o.axes.size() == 1 ? p->displayRaw(*raw, lang) : p->formatRaw(*raw));
            unit = p->unit;
        }
        if (parts.size() == 1)
            return parts.first();
        return QStringLiteral("(%1) %2").arg(parts.join(QStringLiteral(", ")), unit).trimmed();
    };
    QStringList notReferenced;
    QStringList limits;
    for (const AxisEnd &a : o.axes) {
        if (!a.referenced)
            notReferenced << QString::number(a.motor);
        if (a.limitPositiveOn)
            limits
                << tr("motor %1's positive limit (IN%2) is ON").arg(a.motor).arg(a.limitPositiveOn);
        if (a.limitNegativeOn)
            limits
                << tr("motor %1's negative limit (IN%2) is ON").arg(a.motor).arg(a.limitNegativeOn);
    }
    const QString what = name(o.start);
    const QString cause = causeText(o.cause);
    switch (o.verdict) {
    case MotionOutcome::Verdict::Done:
        return tr("%1: done at %2").arg(what, where(false));
    case MotionOutcome::Verdict::Referenced:
        return tr("%1: referenced at %2").arg(what, where(false));
    case MotionOutcome::Verdict::Stopped: {
        const QString why = !cause.isEmpty()    ? cause
                            : !limits.isEmpty() ? Translators::joinList(limits)
                                                : tr("no stop, limit or E-STOP seen");
        return tr("%1: stopped at %2, not at the end point %3 (%4)")
            .arg(what, where(false), where(true), why);
    }
    case MotionOutcome::Verdict::Interrupted:
        return o.axes.size() == 1
                   ? tr("%1 interrupted at %2 (%3): not referenced").arg(what, where(false), cause)
                   : tr("%1 interrupted at %2 (%3): motor %4 not referenced")
                         .arg(what, where(false), cause, Translators::joinList(notReferenced));
    case MotionOutcome::Verdict::NotKnown:
        return tr("%1: how it ended is not known, last seen at %2 (%3): not referenced")
            .arg(what, where(false), cause);
    case MotionOutcome::Verdict::NoHomeInput:
        return o.axes.size() == 1
                   ? tr("%1 ended without the home input at %2: not referenced")
                         .arg(what, where(false))
                   : tr("%1 ended without the home input at %2: motor %3 not referenced")
                         .arg(what, where(false), Translators::joinList(notReferenced));
    }
    return {};
}

} // namespace stepcom
