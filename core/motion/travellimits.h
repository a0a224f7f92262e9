#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QMap>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;
struct Parameter;

// One axis's software travel: the positions a step, a move-to or a jog may reach, in the raw
// units of the axis's position register (×100 distance units). Either end may be open.
struct AxisTravel
{
    std::optional<qint64> min;
    std::optional<qint64> max;
    bool isEmpty() const { return !min && !max; }
    bool operator==(const AxisTravel &o) const = default;
};

// What a hold-to-move jog can overrun a software limit by (see TravelLimits::overrun).
struct OverrunInputs
{
    double unitsPerSecond = 0;      // the jog's top speed (rpm × pitch / 60)
    double pollIntervalMs = 0;      // from the start of one position read to the next
    double readMs = 0;              // one position read, request to answer, on the wire
    double stopMs = 0;              // the stop: a transaction in flight first, then its own
    double brakeMs = 0;             // ramp down after the stop (0: the controller stops at once)
    double startUnitsPerSecond = 0; // where a ramp down ends (the start frequency's speed)
};

struct OverrunEstimate
{
    double reactionMs = 0; // from the crossing to the stop reaching the controller, worst case
    double distance = 0;   // axis units travelled beyond the limit, worst case
};

// Software travel limits per axis: a StepCom setting, not a controller register (the controller
// knows only its limit switches). Kept in profiles ("stepcom" → "travelLimits") and, later, with
// the saved connection. Pure: no device; the step jog, move-to and the jog page ask it.
class TravelLimits
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::TravelLimits)
public:
    // The position register of `motor` in `map` gives the unit, scale and range.
    static const Parameter *positionParameter(const RegisterMap &map, int motor);

    bool isEmpty() const;
    AxisTravel axis(int motor) const { return m_axes.value(motor); }
    const QMap<int, AxisTravel> &axes() const { return m_axes; }
    // Sets one axis after checking it (min below max, within the position register's range and
    // decimals); empty on success, else why not (nothing changes then).
    QString setAxis(const RegisterMap &map, int motor, std::optional<double> min,
                    std::optional<double> max);
    void clearAxis(int motor) { m_axes.remove(motor); }

    // A step or move-to from `current` to `target` (axis units): empty when allowed, else why
    // not. A target beyond a limit is refused, except a move that brings an axis standing
    // outside its travel closer to it (the way back in after a limit was changed).
    QString refuseTarget(const RegisterMap &map, int motor, double current, double target) const;
    // A hold-to-move jog toward + (`positive`) or − that may not start at `current`: why, or
    // empty (an axis at or beyond its limit may only jog back).
    QString refuseJog(const RegisterMap &map, int motor, bool positive, double current) const;
    // A polled position during a jog toward + or −: why the jog must stop now (the position
    // reached or crossed the limit in the jog's direction), or empty.
    QString crossed(const RegisterMap &map, int motor, bool positive, double polled) const;

    // How far a jog can run past a limit before it stops, worst case. The limit is crossed just
    // after a poll's sample; the next sample comes one poll interval later and reaches StepCom
    // one read later; the stop then waits for a transaction in flight and needs its own answer:
    //   reaction = poll interval + read + stop
    //   distance = speed × reaction + (speed + start speed) / 2 × brake
    // (times in seconds). The controller has no command watchdog: if the link dies during a
    // jog, nothing stops it but its limit switches -- no software limit bounds that case.
    static OverrunEstimate overrun(const OverrunInputs &in);
    // "up to 8.10 mm at 25.00 mm/s (reaction 324 ms: poll 200 ms, read 64 ms, stop 60 ms)".
    static QString describeOverrun(const OverrunInputs &in, const QString &unit);

    // {"motor1": {"min": 0, "max": 200}, ...} in axis units; open ends are left out.
    QJsonObject toJson(const RegisterMap &map) const;
    // Every problem names the axis and the field; nullopt then. `where` prefixes messages.
    static std::optional<TravelLimits> fromJson(const QJsonValue &value, const RegisterMap &map,
                                                QStringList *errors);

    bool operator==(const TravelLimits &o) const = default;

private:
    QMap<int, AxisTravel> m_axes; // by motor, only axes with a limit
};

} // namespace stepcom
