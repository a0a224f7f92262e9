#include "device/motionjudge.h"

#include "i18n/translators.h"
#include "map/registermap.h"

#include <cmath>

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");

std::optional<qint64> get(const StatusValues &v, const QString &key)
{
    const auto it = v.constFind(key);
    if (key.isEmpty() || it == v.cend())
        return std::nullopt;
    return *it;
}

const Parameter *motorParam(const RegisterMap &map, int motor, const char *local)
{
    return map.blockParameter(kMotor, motor, QLatin1String(local));
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

// The input number of motor's limit in `direction` (+1/-1) when it reads ON, else 0.
int limitOn(const RegisterMap &map, const StatusValues &v, int motor, int direction)
{
    const qint64 input =
        motorValue(map, v, motor, direction > 0 ? "limit_positive" : "limit_negative").value_or(0);
    return inputOn(v, input) ? int(input) : 0;
}

// A value of a coordinate register (arc.end_x ...) as raw counts of motor's position.
std::optional<qint64> asPosition(const RegisterMap &map, const StatusValues &v, int motor,
                                 const QString &key)
{
    const Parameter *from = map.find(key);
    const Parameter *pos = motorParam(map, motor, "position");
    const auto raw = from ? get(v, key) : std::nullopt;
    if (!pos || !raw)
        return std::nullopt;
    return qint64(std::llround(from->toEngineering(*raw) * pos->scale));
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
    if (p->block == kMotor && p->localKey == QLatin1String("move"))
        return MotionKind::SingleMove;
    if (p->block == kMotor && p->localKey == QLatin1String("home"))
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
    for (int n = 1; n <= map.blockCount(kMotor); ++n) {
        for (const char *local : {"position", "running"}) {
            if (const Parameter *p = motorParam(map, n, local))
                keys << p->key;
        }
    }
    for (int n = 1; map.find(QStringLiteral("io.in%1").arg(n)); ++n)
        keys << QStringLiteral("io.in%1").arg(n);
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
    const int motors = map.blockCount(kMotor);
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
        const QString prefix =
            *kind == MotionKind::Arc ? QStringLiteral("arc.") : QStringLiteral("line.");
        const auto x = asPosition(map, before, 1, prefix + QStringLiteral("end_x"));
        const auto y = asPosition(map, before, 2, prefix + QStringLiteral("end_y"));
        if (!x || !y)
            return std::nullopt;
        s.motors = {1, 2};
        s.target.insert(1, *x);
        s.target.insert(2, *y);
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
    if (homing)
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
    // Modes 1-5 give the inputs other meanings and ignore the limit registers.
    if (get(now, QStringLiteral("mode.system")).value_or(0) != 0)
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
        for (int n = 1; n <= map.blockCount(kMotor); ++n) {
            if (const auto p = motorValue(map, now, n, "position"))
                check(n, sign(double(-*p)), tr("the return to data zero"));
        }
        break;
    case MotionKind::Arc:
    case MotionKind::Line: {
        const bool arc = *kind == MotionKind::Arc;
        const QString prefix = arc ? QStringLiteral("arc.") : QStringLiteral("line.");
        const auto pos = [&](int motor, const char *point) {
            return asPosition(map, now, motor,
                              prefix + QLatin1String(point) +
                                  (motor == 1 ? QStringLiteral("_x") : QStringLiteral("_y")));
        };
        // The centre as plain numbers (an optional pair trips GCC's uninitialised warnings).
        bool haveCentre = false;
        double centreX = 0;
        double centreY = 0;
        if (const auto cx = pos(1, "center"), cy = pos(2, "center"); cx && cy) {
            haveCentre = true;
            centreX = double(*cx);
            centreY = double(*cy);
        }
        if (arc && get(now, QStringLiteral("arc.mode")).value_or(0) == 1) {
            // Three points: the centre of the circle through start, middle and end.
            const auto sx = pos(1, "start"), sy = pos(2, "start"), mx = pos(1, "middle"),
                       my = pos(2, "middle"), ex = pos(1, "end"), ey = pos(2, "end");
            haveCentre = false;
            if (sx && sy && mx && my && ex && ey) {
                const double ax = double(*sx), ay = double(*sy), bx = double(*mx), by = double(*my),
                             cx = double(*ex), cy = double(*ey);
                const double d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
                if (d != 0) {
                    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by,
                                 c2 = cx * cx + cy * cy;
                    haveCentre = true;
                    centreX = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / d;
                    centreY = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / d;
                }
            }
        }
        const bool ccw = get(now, QStringLiteral("arc.direction")).value_or(0) == 1;
        const auto s1 = pos(1, "start"), s2 = pos(2, "start");
        for (int n = 1; n <= 2; ++n) {
            const auto here = motorValue(map, now, n, "position");
            const auto start = n == 1 ? s1 : s2;
            if (!here || !start)
                continue;
            if (std::abs(*start - *here) > 1) {
                check(n, sign(double(*start - *here)), tr("the approach to the start point"));
                continue;
            }
            int dir = 0;
            if (!arc) {
                if (const auto e = pos(n, "end"))
                    dir = sign(double(*e - *start));
            } else if (s1 && s2 && haveCentre) {
                // The tangent at the start: counter-clockwise (-dy, dx) around the centre.
                const double dx = double(*s1) - centreX, dy = double(*s2) - centreY;
                const double t = n == 1 ? -dy : dx;
                dir = sign(ccw ? t : -t);
            }
            check(n, dir, arc ? tr("the arc") : tr("the line"));
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
