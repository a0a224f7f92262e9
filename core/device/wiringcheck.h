#pragma once

#include <QList>
#include <QString>

#include <optional>

namespace stepcom {

// Which inputs one motor's limit and home registers name: 0 = none, n = INn; nullopt while
// not known.
struct MotorWiring
{
    int motor = 0; // 1-based
    std::optional<int> positive;
    std::optional<int> negative;
    std::optional<int> home;
};

struct WiringWarning
{
    enum class Severity { Info, Warning, Error };
    enum class Kind {
        BothLimitsOneInput,  // one input is the positive and the negative limit of a motor
        InputSharedByMotors, // one input is a limit or home of two motors
        HomeNotALimit,       // a home input that is neither limit while limits are set
        HomeOnPositiveLimit, // homing reverses, so it never reaches a switch at the positive end
        OneSidedLimits,      // only one end has a limit
        NoHomeInput,         // limits but no home: homing runs to the limit and zeroes nothing
        LimitIgnoredInMode,  // system modes 2-5 ignore the limit settings and use IN1-IN4 otherwise
    };
    Severity severity = Severity::Warning;
    Kind kind = Kind::BothLimitsOneInput;
    int motor = 0;   // the motor concerned (the first of two for a shared input)
    QString message; // translated, names the motor, the input and the role
};

// Suspicious limit and home wiring, from the register values alone (pure, no device).
// `systemMode` is register 40300 (nullopt: unknown). Checks that need an unknown value skip.
QList<WiringWarning> checkWiring(const QList<MotorWiring> &motors, std::optional<int> systemMode);

// "IN2", or the translated "none" for 0.
QString inputName(int input);

} // namespace stepcom
