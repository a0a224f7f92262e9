#include "device/writereview.h"

#include "device/parameterstore.h"
#include "device/wiringcheck.h"
#include "i18n/translators.h"
#include "motion/interpolationgeometry.h"
#include "motion/pathsetup.h"

namespace stepcom {

namespace {

const QString kMode = QStringLiteral("mode.system");

bool isWiring(const QString &key)
{
    return key.endsWith(QLatin1String(".limit_positive")) ||
           key.endsWith(QLatin1String(".limit_negative")) ||
           key.endsWith(QLatin1String(".home_input")) || key == kMode;
}

} // namespace

QStringList WriteReview::problems(const ParameterStore &store, const QList<ParameterWrite> &writes)
{
    return problems(
        store.map(), [&store](const QString &key) { return store.deviceValue(key); }, writes);
}

QStringList WriteReview::keysRead(const RegisterMap &map, const QList<ParameterWrite> &writes)
{
    QStringList prefixes;
    bool wiring = false;
    for (const ParameterWrite &w : writes) {
        const QString &k = w.parameter->key;
        if (k.startsWith(QLatin1String("arc.")))
            prefixes << QStringLiteral("arc.");
        if (k.startsWith(QLatin1String("line.")))
            prefixes << QStringLiteral("line.");
        wiring = wiring || isWiring(k);
    }
    QStringList keys;
    for (const Parameter *p : map.holdings()) {
        const bool wanted =
            (wiring && isWiring(p->key)) ||
            std::any_of(prefixes.cbegin(), prefixes.cend(),
                        [p](const QString &prefix) { return p->key.startsWith(prefix); });
        // The written ones too: a mode is questioned only when it changes.
        if (wanted)
            keys << p->key;
    }
    return keys;
}

QStringList WriteReview::problems(const RegisterMap &map, const Held &held,
                                  const QList<ParameterWrite> &writes)
{
    QHash<QString, qint64> after;
    for (const ParameterWrite &w : writes)
        after.insert(w.parameter->key, w.raw);
    const auto raw = [&](const QString &key) -> std::optional<qint64> {
        if (after.contains(key))
            return after.value(key);
        return held(key);
    };
    const auto touches = [&](const QString &prefix) {
        return std::any_of(after.keyBegin(), after.keyEnd(),
                           [&](const QString &k) { return k.startsWith(prefix); });
    };
    // A geometry is judged only when every point it needs is known (core/motion reads the
    // registers; it counts an unknown value as 0).
    const auto known = [&](const QString &prefix, std::initializer_list<const char *> points) {
        return std::all_of(points.begin(), points.end(), [&](const char *name) {
            const QString base = prefix + QLatin1String(name);
            return raw(base + QStringLiteral("_x")) && raw(base + QStringLiteral("_y"));
        });
    };

    QStringList problems;
    // The window's mode page asks before any change of mode: what the inputs do changes at once.
    if (const Parameter *mode = map.find(kMode); mode && after.contains(kMode)) {
        const qint64 next = after.value(kMode);
        if (held(kMode) != next) {
            const QString lang = Translators::current();
            problems << (modeIgnoresLimits(next)
                             ? tr("System mode %1 “%2” changes what the inputs IN1-IN4 do, at "
                                  "once, and ignores the limit settings: no limit input stops "
                                  "a motor then.")
                             : tr("System mode %1 “%2” changes what the inputs IN1-IN4 do, at "
                                  "once."))
                            .arg(next)
                            .arg(mode->displayRaw(next, lang));
        }
    }
    if (touches(QStringLiteral("arc."))) {
        const interpolation::ArcSetup arc = interpolation::arcSetup(map, raw);
        const char *third = arc.mode == interpolation::ArcMode::Centre ? "center" : "middle";
        const interpolation::Geometry g = interpolation::arc(arc);
        if (known(QStringLiteral("arc."), {"start", "end", third}) && !g.valid)
            problems << tr("Arc: %1").arg(g.error);
    }
    if (touches(QStringLiteral("line."))) {
        const interpolation::LineSetup line = interpolation::lineSetup(map, raw);
        const interpolation::Geometry g = interpolation::line(line.start, line.end);
        if (known(QStringLiteral("line."), {"start", "end"}) && !g.valid)
            problems << tr("Line: %1").arg(g.error);
    }
    const bool wiring = std::any_of(after.keyBegin(), after.keyEnd(), isWiring);
    if (wiring) {
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
