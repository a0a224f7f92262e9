#pragma once

#include <QList>
#include <QObject>

namespace stepcom {

// Whether each axis is referenced: homed onto its home input with nothing in between, as
// judged by MotionJudge. Anything that may have cost steps or moved the zero takes it away.
// The words are made when asked for, so they follow the language.
class ReferenceTracker : public QObject
{
    Q_OBJECT
public:
    // Why an axis is (not) referenced.
    enum class Reason {
        NeverHomed,
        Homed,
        HomingFailed,  // the last homing ended without the home input
        HomingStopped, // a stop, E-STOP or link loss cut the homing short
        EmergencyStop,
        Zeroed, // "zero the coordinates" moved the zero
        LinkLost,
    };
    Q_ENUM(Reason)

    explicit ReferenceTracker(int motors, QObject *parent = nullptr);

    int motorCount() const { return int(m_reasons.size()); }
    bool isReferenced(int motor) const { return reason(motor) == Reason::Homed; }
    Reason reason(int motor) const;
    // "referenced" / "not referenced (E-STOP)", in the installed language.
    QString text(int motor) const;

    void setReason(int motor, Reason reason);
    // Every axis loses its reference for `reason` (only referenced ones change).
    void loseAll(Reason reason);

Q_SIGNALS:
    void changed(int motor);

private:
    QList<Reason> m_reasons;
};

} // namespace stepcom
