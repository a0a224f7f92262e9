#include "device/wiringcheck.h"

#include "i18n/translators.h"

#include <QCoreApplication>
#include <QMap>

namespace stepcom {

namespace {

using Severity = WiringWarning::Severity;
using WarningKind = WiringWarning::Kind;

enum class Role { Positive, Negative, Home };

QString roleName(Role role)
{
    switch (role) {
    case Role::Positive:
        return QCoreApplication::translate("stepcom::WiringCheck", "positive limit");
    case Role::Negative:
        return QCoreApplication::translate("stepcom::WiringCheck", "negative limit");
    case Role::Home:
        return QCoreApplication::translate("stepcom::WiringCheck", "home input");
    }
    return {};
}

QString modeName(int mode)
{
    switch (mode) {
    case 2:
        return QCoreApplication::translate("stepcom::WiringCheck", "single trigger");
    case 3:
        return QCoreApplication::translate("stepcom::WiringCheck", "forward/reverse trigger");
    case 4:
        return QCoreApplication::translate("stepcom::WiringCheck", "hold-to-jog");
    case 5:
        return QCoreApplication::translate("stepcom::WiringCheck", "fixed-distance trigger");
    }
    return {};
}

// What an input does in special modes 2-5 (the manual, 40300): always motor 1.
QString modeUse(int mode, int input)
{
    if (input == 3 && mode >= 3)
        return QCoreApplication::translate("stepcom::WiringCheck", "as motor 1's positive limit");
    if (input == 4 && mode >= 3)
        return QCoreApplication::translate("stepcom::WiringCheck", "as motor 1's negative limit");
    switch (mode * 10 + input) {
    case 21:
        return QCoreApplication::translate("stepcom::WiringCheck", "to start motor 1");
    case 22:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to stop motor 1 (the next start keeps the direction)");
    case 23:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to stop motor 1 (the next start reverses)");
    case 24:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to stop motor 1 (the next start goes forward)");
    case 31:
        return QCoreApplication::translate("stepcom::WiringCheck", "to run motor 1 forward");
    case 32:
        return QCoreApplication::translate("stepcom::WiringCheck", "to run motor 1 in reverse");
    case 41:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to jog motor 1 forward while it is on");
    case 42:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to jog motor 1 in reverse while it is on");
    case 51:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to move motor 1 forward by its move distance");
    case 52:
        return QCoreApplication::translate("stepcom::WiringCheck",
                                           "to move motor 1 in reverse by its move distance");
    }
    return {};
}

WiringWarning make(Severity severity, WarningKind kind, int motor, const QString &message)
{
    WiringWarning w;
    w.severity = severity;
    w.kind = kind;
    w.motor = motor;
    w.message = message;
    return w;
}

void checkMotor(const MotorWiring &m, QList<WiringWarning> *out)
{
    const int pos = m.positive.value_or(0);
    const int neg = m.negative.value_or(0);
    const bool limitsKnown = m.positive && m.negative;
    if (pos != 0 && pos == neg) {
        out->append(make(
            Severity::Error, WarningKind::BothLimitsOneInput, m.motor,
            QCoreApplication::translate("stepcom::WiringCheck",
                                        "Motor %1: %2 is both the positive and the negative limit")
                .arg(m.motor)
                .arg(inputName(pos))));
    }
    if (limitsKnown && (pos == 0) != (neg == 0)) {
        out->append(make(
            Severity::Warning, WarningKind::OneSidedLimits, m.motor,
            pos != 0 ? QCoreApplication::translate("stepcom::WiringCheck",
                                                   "Motor %1: only the positive limit is set (%2); "
                                                   "nothing stops the motor at the negative end")
                           .arg(m.motor)
                           .arg(inputName(pos))
                     : QCoreApplication::translate("stepcom::WiringCheck",
                                                   "Motor %1: only the negative limit is set (%2); "
                                                   "nothing stops the motor at the positive end")
                           .arg(m.motor)
                           .arg(inputName(neg))));
    }
    if (!m.home || !limitsKnown || (pos == 0 && neg == 0))
        return;
    const int home = *m.home;
    if (home == 0) {
        out->append(make(
            Severity::Info, WarningKind::NoHomeInput, m.motor,
            QCoreApplication::translate("stepcom::WiringCheck",
                                        "Motor %1: no home input; homing runs in reverse until the "
                                        "negative limit or a stop and does not zero the position")
                .arg(m.motor)));
    } else if (home == pos && home != neg) {
        out->append(make(Severity::Error, WarningKind::HomeOnPositiveLimit, m.motor,
                         QCoreApplication::translate(
                             "stepcom::WiringCheck",
                             "Motor %1: the home input %2 is the positive limit, but homing "
                             "runs in reverse, away from it; use the negative limit's input")
                             .arg(m.motor)
                             .arg(inputName(home))));
    } else if (home != pos && home != neg) {
        out->append(make(
            Severity::Warning, WarningKind::HomeNotALimit, m.motor,
            QCoreApplication::translate("stepcom::WiringCheck",
                                        "Motor %1: the home input %2 is neither of its limits; "
                                        "usually the home input is the negative limit (%3)")
                .arg(m.motor)
                .arg(inputName(home), inputName(neg))));
    }
}

} // namespace

QString inputName(int input)
{
    if (input <= 0)
        return QCoreApplication::translate("stepcom::WiringCheck", "none");
    return QStringLiteral("IN%1").arg(input);
}

QList<WiringWarning> checkWiring(const QList<MotorWiring> &motors, std::optional<int> systemMode)
{
    QList<WiringWarning> out;
    for (const MotorWiring &m : motors)
        checkMotor(m, &out);

    // Every use of every input, in motor order, to find inputs shared by motors.
    struct Use
    {
        int motor;
        Role role;
    };
    QMap<int, QList<Use>> uses;
    for (const MotorWiring &m : motors) {
        const std::pair<std::optional<int>, Role> roles[] = {
            {m.positive, Role::Positive}, {m.negative, Role::Negative}, {m.home, Role::Home}};
        for (const auto &[input, role] : roles) {
            if (input && *input > 0)
                uses[*input].append({m.motor, role});
        }
    }
    for (auto it = uses.cbegin(); it != uses.cend(); ++it) {
        const QList<Use> &list = it.value();
        QStringList parts;
        QList<int> seenMotors;
        for (const Use &u : list) {
            if (!seenMotors.contains(u.motor))
                seenMotors << u.motor;
            parts << QCoreApplication::translate("stepcom::WiringCheck", "motor %1 %2")
                         .arg(u.motor)
                         .arg(roleName(u.role));
        }
        if (seenMotors.size() < 2)
            continue;
        out.append(make(Severity::Warning, WarningKind::InputSharedByMotors, seenMotors.first(),
                        QCoreApplication::translate(
                            "stepcom::WiringCheck",
                            "%1 is wired to more than one motor (%2): its switch acts on "
                            "all of them")
                            .arg(inputName(it.key()), Translators::joinList(parts))));
    }

    const int mode = systemMode.value_or(0);
    if (mode >= 2 && mode <= 5) {
        for (const MotorWiring &m : motors) {
            const std::pair<std::optional<int>, Role> limits[] = {{m.positive, Role::Positive},
                                                                  {m.negative, Role::Negative}};
            for (const auto &[input, role] : limits) {
                if (!input || *input <= 0)
                    continue;
                const QString use = modeUse(mode, *input);
                const QString text =
                    use.isEmpty() ? QCoreApplication::translate(
                                        "stepcom::WiringCheck",
                                        "Motor %1: %2 is set as the %3, but system mode %4 (%5) "
                                        "ignores the limit settings")
                                        .arg(m.motor)
                                        .arg(inputName(*input), roleName(role))
                                        .arg(mode)
                                        .arg(modeName(mode))
                                  : QCoreApplication::translate(
                                        "stepcom::WiringCheck",
                                        "Motor %1: %2 is set as the %3, but system mode %4 (%5) "
                                        "ignores the limit settings and uses %2 %6")
                                        .arg(m.motor)
                                        .arg(inputName(*input), roleName(role))
                                        .arg(mode)
                                        .arg(modeName(mode), use);
                out.append(make(Severity::Warning, WarningKind::LimitIgnoredInMode, m.motor, text));
            }
        }
    }
    return out;
}

} // namespace stepcom
