#pragma once

#include "motion/motionoutcome.h"

#include <QCoreApplication>
#include <QStringList>

namespace stepcom {

// Pure functions from register values to what a motion command will do and did. Used by the
// window (through MotionSupervisor) and by `stepcomctl command --wait`, so both say the same.
// The arc and line (their start, end and first direction) come from core/motion, the one
// reading of those registers.
class MotionJudge
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::MotionJudge)
public:
    // Whether `command` is a motion with an end StepCom judges.
    static std::optional<MotionKind> kindOf(const RegisterMap &map, const QString &command);
    // The axes and end points of `command` from the values held before it went out; nullopt
    // for a command that is not judged or when something needed is not known.
    static std::optional<MotionStart> plan(const RegisterMap &map, const QString &command,
                                           const StatusValues &before);
    // The verdict from the values read once every moved axis was idle.
    static MotionOutcome judge(const RegisterMap &map, const MotionStart &start,
                               const StatusValues &end, MotionCause cause);
    // A warning when the first direction of an axis (of the approach, or of the path when the
    // axis is already there) runs into a limit input that is already ON; empty when none.
    static QString limitWarning(const RegisterMap &map, const QString &command,
                                const StatusValues &now);
    // What must be read to judge the end: positions, running flags, inputs.
    static QStringList watchKeys(const RegisterMap &map);
    // Every register plan(), limitWarning() and judge() read for `command`, beyond the end's
    // watchKeys(): the moved axes' targets, limit and home inputs, the system mode, the
    // homing order, the arc or line. Every front-end reads these before the command goes out,
    // so a motion is judged on the same inputs whoever sent it.
    static QStringList inputKeys(const RegisterMap &map, const QString &command);

    // The outcome in words, in the installed language.
    static QString text(const RegisterMap &map, const MotionOutcome &outcome);
    // "Single move of motor 1", "Homing in order", "Arc" ...
    static QString name(const MotionStart &start);
    static QString causeText(MotionCause cause);
};

} // namespace stepcom
