#include "sim/simregisters.h"

#include <QCoreApplication>

#include <algorithm>

namespace stepcom {

namespace {

int countNumbered(const RegisterMap &map, const QString &prefix)
{
    int n = 0;
    while (map.find(prefix + QString::number(n + 1)))
        ++n;
    return n;
}

} // namespace

SimRegisters::SimRegisters(const RegisterMap &map)
    : m_map(map)
{
    m_inputs = countNumbered(m_map, QStringLiteral("io.in"));
    m_outputs = countNumbered(m_map, QStringLiteral("io.out"));
    m_motors = m_map.blockCount(QStringLiteral("motor"));
    for (const Parameter &p : m_map.parameters()) {
        if (!p.isHolding())
            continue;
        m_values.insert(p.key, factoryValue(p));
        m_lastAddress = std::max(m_lastAddress, int(p.lastAddress()));
    }
}

qint64 SimRegisters::raw(const QString &key, qint64 fallback) const
{
    const auto it = m_values.constFind(key);
    return it == m_values.cend() ? fallback : *it;
}

void SimRegisters::setRaw(const Parameter *param, qint64 raw)
{
    if (param && param->isHolding())
        m_values.insert(param->key, raw);
}

qint64 SimRegisters::factoryValue(const Parameter &p) const
{
    static const QHash<QString, qint64> motor = {
        {QStringLiteral("step_angle"), 180},      {QStringLiteral("microsteps"), 8},
        {QStringLiteral("start_frequency"), 400}, {QStringLiteral("accel_frequency"), 80},
        {QStringLiteral("direction"), 0},         {QStringLiteral("speed"), 300},
        {QStringLiteral("pitch"), 500},           {QStringLiteral("move_distance"), 1000},
    };
    static const QHash<QString, qint64> single = {
        {QStringLiteral("homing.first"), 1},    {QStringLiteral("homing.second"), 2},
        {QStringLiteral("arc.enabled"), 0},     {QStringLiteral("arc.mode"), 0},
        {QStringLiteral("arc.start_x"), 2000},  {QStringLiteral("arc.start_y"), 2000},
        {QStringLiteral("arc.end_x"), 6000},    {QStringLiteral("arc.end_y"), 2000},
        {QStringLiteral("arc.center_x"), 4000}, {QStringLiteral("arc.center_y"), 2000},
        {QStringLiteral("arc.middle_x"), 4000}, {QStringLiteral("arc.middle_y"), 4000},
        {QStringLiteral("arc.direction"), 0},   {QStringLiteral("arc.speed"), 60},
        {QStringLiteral("line.enabled"), 0},    {QStringLiteral("line.start_x"), 2000},
        {QStringLiteral("line.start_y"), 2000}, {QStringLiteral("line.end_x"), 8000},
        {QStringLiteral("line.end_y"), 6000},   {QStringLiteral("line.speed"), 60},
        {QStringLiteral("device.id"), 1},       {QStringLiteral("device.baud"), 9600},
        {QStringLiteral("mode.system"), 0},     {QStringLiteral("mode.round_trips"), 0},
    };
    qint64 value = 0;
    bool known = false;
    if (p.block == QLatin1String("motor")) {
        // Switches wired motor n: positive end IN(2n-1), negative end and home IN(2n).
        const int n = p.instance;
        if (p.localKey == QLatin1String("limit_positive")) {
            value = 2 * n - 1 <= m_inputs ? 2 * n - 1 : 0;
            known = true;
        } else if (p.localKey == QLatin1String("limit_negative") ||
                   p.localKey == QLatin1String("home_input")) {
            value = 2 * n <= m_inputs ? 2 * n : 0;
            known = true;
        } else if (motor.contains(p.localKey)) {
            value = motor.value(p.localKey);
            known = true;
        }
    } else if (single.contains(p.key)) {
        value = single.value(p.key);
        known = true;
    }
    if (known && p.checkRaw(value).isEmpty())
        return value;
    // Anything else starts at zero, or the nearest value the map allows.
    if (!p.values.isEmpty())
        return p.checkRaw(0).isEmpty() ? 0 : p.values.first().value;
    return qBound(p.rawMin, qint64(0), p.rawMax);
}

void SimRegisters::resetToFactory()
{
    for (const Parameter &p : m_map.parameters()) {
        if (!p.writable() || p.key == QLatin1String("device.id") ||
            p.key == QLatin1String("device.baud"))
            continue;
        m_values.insert(p.key, factoryValue(p));
    }
}

QHash<QString, qint64> SimRegisters::writableValues() const
{
    QHash<QString, qint64> out;
    for (const Parameter &p : m_map.parameters()) {
        if (p.writable())
            out.insert(p.key, m_values.value(p.key));
    }
    return out;
}

QStringList SimRegisters::applyValues(const QHash<QString, qint64> &values)
{
    QStringList problems;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        const Parameter *p = m_map.find(it.key());
        if (!p || !p->writable()) {
            problems << QCoreApplication::translate("stepcom::SimRegisters",
                                                    "%1: not a writable parameter of the map")
                            .arg(it.key());
            continue;
        }
        if (const QString why = p->checkRaw(it.value()); !why.isEmpty()) {
            problems << why;
            continue;
        }
        m_values.insert(p->key, it.value());
    }
    return problems;
}

} // namespace stepcom
