#include "session/restartwatch.h"

#include "map/registermap.h"

namespace stepcom {

RestartWatch::RestartWatch(const RegisterMap &map, QObject *parent)
    : QObject(parent)
{
    for (const Parameter *p : map.holdings()) {
        if (p->block != QLatin1String("motor"))
            continue;
        if (p->localKey == QLatin1String("position"))
            m_positionKeys << p->key;
        else if (p->localKey == QLatin1String("running"))
            m_runningKeys << p->key;
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

void RestartWatch::statusRead(int device, bool ok, const QHash<QString, qint64> &values,
                              qint64 nowMs)
{
    Device &d = m_devices[device];
    if (!ok) {
        d.failed = true;
        return;
    }
    bool complete = true;
    bool anyNonZero = false;
    bool running = false;
    for (const QString &key : std::as_const(m_positionKeys)) {
        complete = complete && values.contains(key);
        anyNonZero = anyNonZero || values.value(key) != 0;
    }
    for (const QString &key : std::as_const(m_runningKeys))
        running = running || values.value(key) != 0;
    const qint64 silentMs = d.answeredAtMs >= 0 ? nowMs - d.answeredAtMs : 0;
    const bool silent = std::exchange(d.failed, false) && silentMs >= kSilenceMs;
    d.answeredAtMs = nowMs;
    // Back at 0 with nothing that moves or zeroes: the counters started again. A motor that was
    // running may have stopped at 0 by itself, unless the controller was silent in between.
    const auto recent = [nowMs](qint64 at) { return at >= 0 && nowMs - at < kCommandWindowMs; };
    const bool explained = d.commanded || recent(d.commandedAtMs) || recent(d.runningAtMs);
    // Back at 0 where a motion was under way or commanded before a silence: a motion may end
    // at 0 (homing does), a restart puts it there too. Not known.
    const bool zeroed = complete && d.known && d.anyNonZero && !anyNonZero && !running;
    const bool reset = zeroed && !explained && !d.running;
    const Zeros zeros = reset ? Zeros::Reset : zeroed && silent ? Zeros::AfterMotion : Zeros::Kept;
    if (running)
        d.runningAtMs = nowMs;
    if (complete) {
        d.known = true;
        d.anyNonZero = anyNonZero;
        d.running = running;
        d.commanded = false;
    }
    if (silent)
        Q_EMIT suspected(device,
                         tr("it answers again after %1 s without an answer")
                             .arg(double(silentMs) / 1000.0, 0, 'f', 1),
                         zeros);
    else if (reset)
        Q_EMIT suspected(device, tr("its positions went back to 0 with no motion and no command"),
                         zeros);
}

void RestartWatch::commandSent(int device, qint64 nowMs)
{
    Device &d = m_devices[device];
    d.commanded = true;
    d.commandedAtMs = nowMs;
}

void RestartWatch::forget()
{
    m_devices.clear();
}

} // namespace stepcom
