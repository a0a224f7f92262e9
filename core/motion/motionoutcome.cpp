#include "motion/motionoutcome.h"

namespace stepcom {

QString MotionOutcome::verdictWord() const
{
    switch (verdict) {
    case Verdict::Done:
        return QStringLiteral("done");
    case Verdict::Referenced:
        return QStringLiteral("referenced");
    case Verdict::Stopped:
        return QStringLiteral("stopped");
    case Verdict::Interrupted:
        return QStringLiteral("interrupted");
    case Verdict::NoHomeInput:
        return QStringLiteral("not_referenced");
    case Verdict::NotKnown:
        return QStringLiteral("not_known");
    }
    return {};
}

QString MotionOutcome::causeWord() const
{
    switch (cause) {
    case MotionCause::Stop:
        return QStringLiteral("stop");
    case MotionCause::EmergencyStop:
        return QStringLiteral("estop");
    case MotionCause::LinkLost:
        return QStringLiteral("link_lost");
    case MotionCause::Silent:
        return QStringLiteral("silent");
    case MotionCause::Restarted:
        return QStringLiteral("restarted");
    case MotionCause::None:
        break;
    }
    if (ok())
        return QStringLiteral("none");
    for (const AxisEnd &a : axes) {
        // A move short of its target was going toward it: only the limit on that side can
        // have stopped it (the one behind may still read ON just after leaving its switch).
        const bool known = a.position && a.target && *a.position != *a.target;
        const bool towardPlus = known && *a.target > *a.position;
        const bool towardMinus = known && *a.target < *a.position;
        if ((a.limitPositiveOn && (!known || towardPlus)) ||
            (a.limitNegativeOn && (!known || towardMinus)))
            return QStringLiteral("limit");
    }
    return QStringLiteral("unknown");
}

const AxisEnd *MotionOutcome::axis(int motor) const
{
    for (const AxisEnd &a : axes) {
        if (a.motor == motor)
            return &a;
    }
    return nullptr;
}

} // namespace stepcom
