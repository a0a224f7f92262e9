#pragma once

#include "device/wiringcheck.h"

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QMap>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;

// What the inputs did while the technician pressed a switch: a baseline (the last poll before
// "press it now"), then every poll after it; an input that differed from the baseline in any
// poll counts as changed, so a short press between polls that reaches one sample is seen.
class InputObservation
{
public:
    // IN1..INn from polled raw values (io.in1 ...); nullopt when one of them is missing.
    static std::optional<QMap<int, bool>> inputs(const RegisterMap &map,
                                                 const QHash<QString, qint64> &values);

    void start(const QMap<int, bool> &baseline);
    void add(const QMap<int, bool> &sample);
    bool started() const { return m_started; }
    QList<int> changed() const; // ascending input numbers
    const QMap<int, bool> &baseline() const { return m_baseline; }

private:
    QMap<int, bool> m_baseline;
    QMap<int, bool> m_changed; // used as an ordered set
    bool m_started = false;
};

// A register write that would make the configuration match the wiring.
struct InputFix
{
    QString key; // motor1.limit_positive
    qint64 raw = 0;
    bool operator==(const InputFix &o) const = default;
};

struct InputJudgement
{
    enum class Verdict {
        Matches,      // the configured input answered, and only it
        OtherInput,   // another input answered: the configuration (or the wiring) is wrong
        NoneAnswered, // no input changed
        Several,      // more than one input changed: press again, alone
    };
    Verdict verdict = Verdict::NoneAnswered;
    int configured = 0; // the input the register names, 0 none
    int answered = 0;   // the one input that changed, 0 none or several
    QList<int> changed;
    QList<InputFix> fixes; // for OtherInput: the registers to write
    QString message;       // for people: what happened and what to do
    QStringList notes;     // the answered input also serves another role or motor
    bool passed() const { return verdict == Verdict::Matches; }
};

// The limit and home input step: "press the positive limit of motor 1"; which input changed,
// does it match the configuration, which register value would fix it. Pure.
class InputTest
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::InputTest)
public:
    enum class Role { PositiveLimit, NegativeLimit, Home };

    // "limit_positive", "limit_negative", "home_input": the block key of the role's register.
    static QString localKey(Role role);
    // "positive limit", translated.
    static QString roleName(Role role);
    // `wiring` holds every motor's configured inputs (as the wiring check reads them).
    static InputJudgement judge(const RegisterMap &map, int motor, Role role,
                                const QList<MotorWiring> &wiring, const QList<int> &changed);
};

} // namespace stepcom
