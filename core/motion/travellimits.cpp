#include "motion/travellimits.h"

#include "map/registermap.h"

#include <QJsonValue>
#include <QLocale>

#include <cmath>

namespace stepcom {

namespace {

const QString kMin = QStringLiteral("min");
const QString kMax = QStringLiteral("max");

// Axis units to the position register's raw units, rounded to its resolution: 199.9 + 0.1 is
// 200.00 exactly, not 200.00000000000003.
std::optional<qint64> toRaw(const Parameter &p, double value)
{
    const double scaled = value * p.scale;
    if (!std::isfinite(scaled) || std::fabs(scaled) > 9.0e15)
        return std::nullopt;
    return qint64(std::llround(scaled));
}

QString shown(const Parameter &p, qint64 raw)
{
    return p.unit.isEmpty() ? p.formatRaw(raw) : p.formatRaw(raw) + QLatin1Char(' ') + p.unit;
}

} // namespace

const Parameter *TravelLimits::positionParameter(const RegisterMap &map, int motor)
{
    return map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"));
}

bool TravelLimits::isEmpty() const
{
    return std::all_of(m_axes.cbegin(), m_axes.cend(),
                       [](const AxisTravel &a) { return a.isEmpty(); });
}

QString TravelLimits::setAxis(const RegisterMap &map, int motor, std::optional<double> min,
                              std::optional<double> max)
{
    const Parameter *p = positionParameter(map, motor);
    if (!p)
        return tr("motor %1: this register map has no such axis").arg(motor);
    AxisTravel axis;
    for (const auto &[value, end, out] :
         {std::tuple{min, kMin, &axis.min}, std::tuple{max, kMax, &axis.max}}) {
        if (!value)
            continue;
        QString why;
        const auto raw = p->fromEngineering(*value, &why);
        if (!raw)
            return tr("motor %1, software travel limit %2: %3").arg(motor).arg(end, why);
        *out = raw;
    }
    if (axis.min && axis.max && *axis.min >= *axis.max)
        return tr("motor %1: the software travel limit min (%2) must be below max (%3)")
            .arg(motor)
            .arg(shown(*p, *axis.min), shown(*p, *axis.max));
    if (axis.isEmpty())
        m_axes.remove(motor);
    else
        m_axes.insert(motor, axis);
    return {};
}

QString TravelLimits::refuseTarget(const RegisterMap &map, int motor, double current,
                                   double target) const
{
    const AxisTravel axis = m_axes.value(motor);
    if (axis.isEmpty())
        return {};
    const Parameter *p = positionParameter(map, motor);
    if (!p)
        return tr("motor %1: this register map has no such axis").arg(motor);
    const auto t = toRaw(*p, target);
    const auto c = toRaw(*p, current);
    if (!t || !c)
        return tr("motor %1: %2 is not a position").arg(motor).arg(target, 0, 'g', 17);
    if (axis.max && *t > *axis.max && !(*c > *axis.max && *t < *c))
        return tr("motor %1: %2 is beyond the software travel limit max %3")
            .arg(motor)
            .arg(shown(*p, *t), shown(*p, *axis.max));
    if (axis.min && *t < *axis.min && !(*c<*axis.min && * t> * c))
        return tr("motor %1: %2 is beyond the software travel limit min %3")
            .arg(motor)
            .arg(shown(*p, *t), shown(*p, *axis.min));
    return {};
}

QString TravelLimits::refuseJog(const RegisterMap &map, int motor, bool positive,
                                double current) const
{
    const AxisTravel axis = m_axes.value(motor);
    const Parameter *p = positionParameter(map, motor);
    if (axis.isEmpty() || !p)
        return {};
    const auto c = toRaw(*p, current);
    if (!c)
        return tr("motor %1: %2 is not a position").arg(motor).arg(current, 0, 'g', 17);
    if (positive && axis.max && *c >= *axis.max)
        return tr("motor %1 is at %2, at or beyond its software travel limit max %3: it may only "
                  "jog toward −")
            .arg(motor)
            .arg(shown(*p, *c), shown(*p, *axis.max));
    if (!positive && axis.min && *c <= *axis.min)
        return tr("motor %1 is at %2, at or beyond its software travel limit min %3: it may only "
                  "jog toward +")
            .arg(motor)
            .arg(shown(*p, *c), shown(*p, *axis.min));
    return {};
}

QString TravelLimits::crossed(const RegisterMap &map, int motor, bool positive, double polled) const
{
    const AxisTravel axis = m_axes.value(motor);
    const Parameter *p = positionParameter(map, motor);
    if (axis.isEmpty() || !p)
        return {};
    const auto c = toRaw(*p, polled);
    if (!c)
        return {};
    if (positive && axis.max && *c >= *axis.max)
        return tr("motor %1 reached its software travel limit max %2 (polled at %3): stop")
            .arg(motor)
            .arg(shown(*p, *axis.max), shown(*p, *c));
    if (!positive && axis.min && *c <= *axis.min)
        return tr("motor %1 reached its software travel limit min %2 (polled at %3): stop")
            .arg(motor)
            .arg(shown(*p, *axis.min), shown(*p, *c));
    return {};
}

OverrunEstimate TravelLimits::overrun(const OverrunInputs &in)
{
    auto clean = [](double v) { return std::isfinite(v) && v > 0 ? v : 0.0; };
    OverrunEstimate e;
    e.reactionMs = clean(in.pollIntervalMs) + clean(in.readMs) + clean(in.stopMs);
    const double speed = clean(in.unitsPerSecond);
    const double start = std::min(clean(in.startUnitsPerSecond), speed);
    e.distance = speed * e.reactionMs / 1000.0 + (speed + start) / 2.0 * clean(in.brakeMs) / 1000.0;
    return e;
}

QString TravelLimits::describeOverrun(const OverrunInputs &in, const QString &unit)
{
    const OverrunEstimate e = overrun(in);
    const QLocale locale;
    auto len = [&](double v) {
        return unit.isEmpty() ? locale.toString(v, 'f', 2)
                              : locale.toString(v, 'f', 2) + QLatin1Char(' ') + unit;
    };
    auto ms = [&](double v) { return locale.toString(v, 'f', 0); };
    QString text = tr("up to %1 beyond a software limit at %2/s (reaction %3 ms: poll %4 ms, "
                      "read %5 ms, stop %6 ms)")
                       .arg(len(e.distance), len(in.unitsPerSecond), ms(e.reactionMs),
                            ms(in.pollIntervalMs), ms(in.readMs), ms(in.stopMs));
    if (in.brakeMs > 0)
        text += QLatin1String("; ") + tr("braking %1 ms included").arg(ms(in.brakeMs));
    return text;
}

QJsonObject TravelLimits::toJson(const RegisterMap &map) const
{
    QJsonObject out;
    for (auto it = m_axes.cbegin(); it != m_axes.cend(); ++it) {
        const Parameter *p = positionParameter(map, it.key());
        if (!p || it->isEmpty())
            continue;
        QJsonObject axis;
        // Engineering units as the profile's values are written: exact decimal text to double.
        if (it->min)
            axis.insert(kMin, p->formatRaw(*it->min).toDouble());
        if (it->max)
            axis.insert(kMax, p->formatRaw(*it->max).toDouble());
        out.insert(QStringLiteral("motor%1").arg(it.key()), axis);
    }
    return out;
}

std::optional<TravelLimits> TravelLimits::fromJson(const QJsonValue &value, const RegisterMap &map,
                                                   QStringList *errors)
{
    const qsizetype before = errors->size();
    if (!value.isObject()) {
        *errors << tr("\"travelLimits\" must be an object {\"motor1\": {\"min\": …, \"max\": …}}");
        return std::nullopt;
    }
    const int motors = map.blockCount(QStringLiteral("motor"));
    TravelLimits limits;
    const QJsonObject o = value.toObject();
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString name = it.key();
        bool isNumber = false;
        const int motor =
            name.startsWith(QLatin1String("motor")) ? name.mid(5).toInt(&isNumber) : 0;
        if (!isNumber || motor < 1 || motor > motors ||
            name != QStringLiteral("motor%1").arg(motor)) {
            *errors << tr("\"travelLimits\": unknown axis \"%1\" (this map has motor1 .. motor%2)")
                           .arg(name.left(40))
                           .arg(motors);
            continue;
        }
        if (!it.value().isObject()) {
            *errors << tr("\"travelLimits\": \"%1\" must be an object {\"min\": …, \"max\": …}")
                           .arg(name);
            continue;
        }
        const QJsonObject axis = it.value().toObject();
        bool ok = true;
        for (auto f = axis.begin(); f != axis.end(); ++f) {
            if (f.key() != kMin && f.key() != kMax) {
                *errors << tr("\"travelLimits\": \"%1\": unknown field \"%2\" (allowed: min, max)")
                               .arg(name, f.key().left(40));
                ok = false;
            } else if (!f.value().isDouble()) {
                *errors
                    << tr("\"travelLimits\": \"%1\": \"%2\" must be a number").arg(name, f.key());
                ok = false;
            }
        }
        if (!ok)
            continue;
        if (axis.isEmpty()) {
            *errors << tr("\"travelLimits\": \"%1\" sets neither min nor max").arg(name);
            continue;
        }
        auto end = [&](const QString &k) -> std::optional<double> {
            return axis.contains(k) ? std::optional<double>(axis.value(k).toDouble())
                                    : std::nullopt;
        };
        if (const QString e = limits.setAxis(map, motor, end(kMin), end(kMax)); !e.isEmpty())
            *errors << QStringLiteral("\"travelLimits\": ") + e;
    }
    if (errors->size() != before)
        return std::nullopt;
    return limits;
}

} // namespace stepcom
