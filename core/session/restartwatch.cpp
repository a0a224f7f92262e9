#include "session/restartwatch.h"

#include "i18n/translators.h"
#include "map/registermap.h"

namespace stepcom {

bool RestartWatch::Evidence::conclusive() const
{
    for (const int motor : stoodStill) {
        if (zeroed.contains(motor))
            return true;
    }
    return false;
}

RestartWatch::RestartWatch(const RegisterMap &map, QObject *parent)
    : QObject(parent)
{
    for (const Parameter *p : map.holdings()) {
        if (p->block != QLatin1String("motor"))
            continue;
        if (p->localKey == QLatin1String("position"))
            m_positionKeys.insert(p->instance, p->key);
        else if (p->localKey == QLatin1String("running"))
            m_runningKeys.insert(p->instance, p->key);
    }
}

bool RestartWatch::movesOrZeroes(const QString &coilKey) const
{
    // Stops, outputs and saving leave the positions where they are; everything else may move
    // an axis to 0 or make 0 the position it stands at.
    static const QStringList keep{
        QStringLiteral("estop"),           QStringLiteral("output1_on"),
        QStringLiteral("output1_off"),     QStringLiteral("outputs_all_on"),
        QStringLiteral("outputs_all_off"), QStringLiteral("save_to_flash"),
        QStringLiteral("arc.stop"),        QStringLiteral("line.stop")};
    return !keep.contains(coilKey) && !coilKey.endsWith(QLatin1String(".stop"));
}

QList<int> RestartWatch::motorsOf(const RegisterMap &map, const QString &coilKey)
{
    // A motor's own coils move only that motor; zeroing, homing in order, return to zero,
    // the paths and a factory reset may move or zero any of them.
    const Parameter *p = map.find(coilKey);
    if (p && p->block == QLatin1String("motor") && p->instance > 0)
        return {p->instance};
    return {};
}

bool RestartWatch::stoodStill(const Axis &axis, qint64 sampledAtMs, qint64 nowMs)
{
    // A command shortly before the last sample may not have shown in it yet (the read was
    // under way); one after it may have moved the axis since.
    const bool commanded =
        axis.commandedAtMs >= 0 && axis.commandedAtMs > sampledAtMs - kCommandWindowMs;
    const bool ranLately = axis.runningAtMs >= 0 && nowMs - axis.runningAtMs < kCommandWindowMs;
    return !axis.running && !commanded && !ranLately;
}

void RestartWatch::statusRead(int device, bool ok, const QHash<QString, qint64> &values,
                              qint64 nowMs)
{
    Device &d = m_devices[device];
    if (!ok) {
        d.failed = true;
        return;
    }
    bool complete = !m_positionKeys.isEmpty();
    bool anyNonZero = false;
    bool running = false;
    for (auto it = m_positionKeys.cbegin(); it != m_positionKeys.cend(); ++it) {
        complete = complete && values.contains(it.value());
        anyNonZero = anyNonZero || values.value(it.value()) != 0;
    }
    for (const QString &key : std::as_const(m_runningKeys))
        running = running || values.value(key) != 0;
    const qint64 silentMs = d.answeredAtMs >= 0 ? nowMs - d.answeredAtMs : 0;
    const bool silent = std::exchange(d.failed, false) && silentMs >= kSilenceMs;
    d.answeredAtMs = nowMs;

    // Every position back at 0 and nothing running, from a sample where one was not 0: what
    // each axis did before says whether a restart is proven or only possible.
    bool wasNonZero = false;
    for (const Axis &a : std::as_const(d.axes))
        wasNonZero = wasNonZero || a.position != 0;
    const bool known = d.axes.size() == m_positionKeys.size() && d.sampledAtMs >= 0;
    const bool zeroed = complete && known && wasNonZero && !anyNonZero && !running;
    Evidence evidence;
    evidence.silentMs = silent ? silentMs : 0;
    if (zeroed) {
        QList<int> motors = m_positionKeys.keys();
        std::sort(motors.begin(), motors.end());
        for (const int motor : motors) {
            const Axis &a = d.axes.value(motor);
            evidence.before.insert(motor, a.position);
            if (a.position != 0)
                evidence.zeroed << motor;
            (stoodStill(a, d.sampledAtMs, nowMs) ? evidence.stoodStill : evidence.moving) << motor;
        }
    }
    // An axis that stood still cannot have gone to 0 by itself: the counters began again. An
    // axis that moved may have ended at 0 (homing does): after a silence that is not known.
    const bool reset = zeroed && evidence.conclusive();
    const Zeros zeros = reset ? Zeros::Reset : zeroed && silent ? Zeros::AfterMotion : Zeros::Kept;

    for (auto it = m_positionKeys.cbegin(); it != m_positionKeys.cend(); ++it) {
        Axis &a = d.axes[it.key()];
        const bool axisRunning = values.value(m_runningKeys.value(it.key())) != 0;
        if (axisRunning)
            a.runningAtMs = nowMs;
        if (complete) {
            a.position = values.value(it.value());
            a.running = axisRunning;
        }
    }
    if (complete)
        d.sampledAtMs = nowMs;
    if (silent)
        Q_EMIT suspected(device,
                         tr("it answers again after %1 s without an answer")
                             .arg(double(silentMs) / 1000.0, 0, 'f', 1),
                         zeros, evidence);
    else if (reset)
        Q_EMIT suspected(
            device, tr("its positions went back to 0 where an axis stood still, with no command"),
            zeros, evidence);
}

void RestartWatch::commandSent(int device, qint64 nowMs, const QList<int> &motors)
{
    Device &d = m_devices[device];
    const QList<int> all = motors.isEmpty() ? m_positionKeys.keys() : motors;
    for (const int motor : all)
        d.axes[motor].commandedAtMs = nowMs;
}

void RestartWatch::forget()
{
    m_devices.clear();
}

QString RestartWatch::describe(const Evidence &e, const RegisterMap &map, const QString &first)
{
    const QString locale = Translators::current();
    const auto at = [&](int motor, qint64 raw) {
        const Parameter *p =
            map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"));
        return p ? p->displayRaw(raw, locale) : QString::number(raw);
    };
    QStringList parts;
    if (!first.isEmpty())
        parts << first;
    for (const int motor : e.stoodStill) {
        if (e.zeroed.contains(motor))
            parts << tr("motor %1 stood still at %2 and reads %3")
                         .arg(motor)
                         .arg(at(motor, e.before.value(motor)), at(motor, 0));
        else
            parts << tr("motor %1 stood still at %2").arg(motor).arg(at(motor, 0));
    }
    // A moving axis's position before says nothing: it went on moving after it.
    for (const int motor : e.moving)
        parts << tr("motor %1 was moving and reads %2").arg(motor).arg(at(motor, 0));
    return parts.join(tr("; ", "between what was seen"));
}

} // namespace stepcom
