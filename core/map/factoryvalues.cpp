#include "map/factoryvalues.h"

namespace stepcom {

qint64 FactoryValues::value(const Parameter &p)
{
    static const QHash<QString, qint64> motor = {
        {QStringLiteral("step_angle"), 180},      {QStringLiteral("microsteps"), 8},
        {QStringLiteral("start_frequency"), 400}, {QStringLiteral("accel_frequency"), 80},
        {QStringLiteral("direction"), 0},         {QStringLiteral("speed"), 300},
        {QStringLiteral("pitch"), 500},           {QStringLiteral("move_distance"), 1000},
        {QStringLiteral("limit_positive"), 0},    {QStringLiteral("limit_negative"), 0},
        {QStringLiteral("home_input"), 0},
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
    const bool inMotor = p.block == QLatin1String("motor");
    const QHash<QString, qint64> &table = inMotor ? motor : single;
    if (const auto it = table.constFind(inMotor ? p.localKey : p.key);
        it != table.cend() && p.checkRaw(*it).isEmpty())
        return *it;
    // Anything else starts at zero, or the nearest value the map allows.
    if (!p.values.isEmpty())
        return p.checkRaw(0).isEmpty() ? 0 : p.values.first().value;
    return qBound(p.rawMin, qint64(0), p.rawMax);
}

QHash<QString, qint64> FactoryValues::writable(const RegisterMap &map)
{
    QHash<QString, qint64> out;
    for (const Parameter &p : map.parameters()) {
        if (p.writable())
            out.insert(p.key, value(p));
    }
    return out;
}

} // namespace stepcom
