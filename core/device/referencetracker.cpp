#include "device/referencetracker.h"

namespace stepcom {

ReferenceTracker::ReferenceTracker(int motors, QObject *parent)
    : QObject(parent)
{
    m_reasons.fill(Reason::NeverHomed, motors);
}

ReferenceTracker::Reason ReferenceTracker::reason(int motor) const
{
    return motor >= 1 && motor <= m_reasons.size() ? m_reasons.at(motor - 1) : Reason::NeverHomed;
}

QString ReferenceTracker::text(int motor) const
{
    switch (reason(motor)) {
    case Reason::Homed:
        return tr("referenced");
    case Reason::NeverHomed:
        return tr("not referenced (not homed yet)");
    case Reason::HomingFailed:
        return tr("not referenced (homing ended without the home input)");
    case Reason::HomingStopped:
        return tr("not referenced (homing was interrupted)");
    case Reason::EmergencyStop:
        return tr("not referenced (E-STOP)");
    case Reason::Zeroed:
        return tr("not referenced (coordinates zeroed)");
    case Reason::LinkLost:
        return tr("not referenced (link lost)");
    }
    return {};
}

void ReferenceTracker::setReason(int motor, Reason reason)
{
    if (motor < 1 || motor > m_reasons.size() || m_reasons.at(motor - 1) == reason)
        return;
    m_reasons[motor - 1] = reason;
    Q_EMIT changed(motor);
}

void ReferenceTracker::loseAll(Reason reason)
{
    for (int n = 1; n <= m_reasons.size(); ++n) {
        if (isReferenced(n))
            setReason(n, reason);
    }
}

} // namespace stepcom
