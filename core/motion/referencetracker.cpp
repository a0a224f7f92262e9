#include "motion/referencetracker.h"

namespace stepcom {

ReferenceTracker::ReferenceTracker(int motors, QObject *parent)
    : QObject(parent)
    , m_motors(motors)
{}

ReferenceTracker::Reason ReferenceTracker::reasonOn(int device, int motor) const
{
    const QList<Reason> reasons = m_reasons.value(device);
    return motor >= 1 && motor <= reasons.size() ? reasons.at(motor - 1) : Reason::NeverHomed;
}

bool ReferenceTracker::isReferencedOn(int device, int motor) const
{
    return reasonOn(device, motor) == Reason::Homed;
}

QList<int> ReferenceTracker::referencedMotors(int device) const
{
    QList<int> motors;
    for (int n = 1; n <= m_motors; ++n)
        if (isReferencedOn(device, n))
            motors << n;
    return motors;
}

QString ReferenceTracker::textOn(int device, int motor) const
{
    switch (reasonOn(device, motor)) {
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
    case Reason::Restarted:
        return tr("not referenced (the controller restarted)");
    case Reason::Silent:
        return tr("reference not known (no answer while it moved: the controller may have "
                  "restarted)");
    }
    return {};
}

void ReferenceTracker::setReasonOn(int device, int motor, Reason reason)
{
    if (motor < 1 || motor > m_motors || reasonOn(device, motor) == reason)
        return;
    QList<Reason> &reasons = m_reasons[device];
    if (reasons.size() < m_motors)
        reasons.resize(m_motors, Reason::NeverHomed);
    reasons[motor - 1] = reason;
    if (device == m_view)
        Q_EMIT changed(motor);
    Q_EMIT deviceChanged(device);
}

void ReferenceTracker::loseAll(int device, Reason reason)
{
    for (int n = 1; n <= m_motors; ++n) {
        if (isReferencedOn(device, n))
            setReasonOn(device, n, reason);
    }
}

void ReferenceTracker::loseEverywhere(Reason reason)
{
    const QList<int> devices = m_reasons.keys();
    for (int device : devices)
        loseAll(device, reason);
}

void ReferenceTracker::setView(int device)
{
    if (device == m_view)
        return;
    m_view = device;
    for (int n = 1; n <= m_motors; ++n)
        Q_EMIT changed(n);
}

void ReferenceTracker::renameView(int device)
{
    if (device == m_view)
        return;
    m_reasons.insert(device, m_reasons.take(m_view));
    Q_EMIT deviceChanged(m_view);
    m_view = device;
    Q_EMIT deviceChanged(device);
}

} // namespace stepcom
