#include "device/writereview.h"

#include "device/interpolationgeometry.h"
#include "device/parameterstore.h"
#include "device/wiringcheck.h"

namespace stepcom {

QStringList WriteReview::problems(const ParameterStore &store, const QList<ParameterWrite> &writes)
{
    QHash<QString, qint64> after;
    for (const ParameterWrite &w : writes)
        after.insert(w.parameter->key, w.raw);
    const auto raw = [&](const QString &key) -> std::optional<qint64> {
        if (after.contains(key))
            return after.value(key);
        return store.deviceValue(key);
    };
    const auto units = [&](const QString &key) -> std::optional<double> {
        const Parameter *p = store.map().find(key);
        const auto r = p ? raw(key) : std::nullopt;
        return r ? std::optional<double>(p->toEngineering(*r)) : std::nullopt;
    };
    const auto touches = [&](const QString &prefix) {
        return std::any_of(after.keyBegin(), after.keyEnd(),
                           [&](const QString &k) { return k.startsWith(prefix); });
    };
    const auto point = [&](const QString &prefix, const char *name,
                           bool *known) -> interpolation::Point {
        const auto x = units(prefix + QLatin1String(name) + QStringLiteral("_x"));
        const auto y = units(prefix + QLatin1String(name) + QStringLiteral("_y"));
        *known = *known && x && y;
        return {x.value_or(0), y.value_or(0)};
    };

    QStringList problems;
    if (touches(QStringLiteral("arc."))) {
        bool known = true;
        interpolation::ArcInput in;
        in.mode = raw(QStringLiteral("arc.mode")).value_or(0) == 1
                      ? interpolation::ArcMode::ThreePoints
                      : interpolation::ArcMode::Centre;
        in.start = point(QStringLiteral("arc."), "start", &known);
        in.end = point(QStringLiteral("arc."), "end", &known);
        if (in.mode == interpolation::ArcMode::Centre)
            in.centre = point(QStringLiteral("arc."), "center", &known);
        else
            in.middle = point(QStringLiteral("arc."), "middle", &known);
        in.counterClockwise = raw(QStringLiteral("arc.direction")).value_or(0) == 1;
        const interpolation::Geometry g = interpolation::arc(in);
        if (known && !g.valid)
            problems << tr("Arc: %1").arg(g.error);
    }
    if (touches(QStringLiteral("line."))) {
        bool known = true;
        const auto start = point(QStringLiteral("line."), "start", &known);
        const auto end = point(QStringLiteral("line."), "end", &known);
        const interpolation::Geometry g = interpolation::line(start, end);
        if (known && !g.valid)
            problems << tr("Line: %1").arg(g.error);
    }
    const bool wiring = std::any_of(after.keyBegin(), after.keyEnd(), [](const QString &k) {
        return k.endsWith(QLatin1String(".limit_positive")) ||
               k.endsWith(QLatin1String(".limit_negative")) ||
               k.endsWith(QLatin1String(".home_input")) || k == QLatin1String("mode.system");
    });
    if (wiring) {
        const RegisterMap &map = store.map();
        QList<MotorWiring> motors;
        for (int n = 1; n <= map.blockCount(QStringLiteral("motor")); ++n) {
            const auto input = [&](const char *local) -> std::optional<int> {
                const Parameter *p =
                    map.blockParameter(QStringLiteral("motor"), n, QLatin1String(local));
                const auto r = p ? raw(p->key) : std::nullopt;
                return r ? std::optional<int>(int(*r)) : std::nullopt;
            };
            motors.append(
                {n, input("limit_positive"), input("limit_negative"), input("home_input")});
        }
        const auto mode = raw(QStringLiteral("mode.system"));
        for (const WiringWarning &w :
             checkWiring(motors, mode ? std::optional<int>(int(*mode)) : std::nullopt)) {
            if (w.severity != WiringWarning::Severity::Info)
                problems << w.message;
        }
    }
    return problems;
}

} // namespace stepcom
