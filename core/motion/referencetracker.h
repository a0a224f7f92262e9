#pragma once

#include <QHash>
#include <QList>
#include <QObject>

namespace stepcom {

// Whether each axis is referenced: homed onto its home input with nothing in between, as
// judged by MotionJudge. Anything that may have cost steps or moved the zero takes it away.
// Kept per controller of the line (by device id); the calls without an id are about the device
// in view (setView), so the pages need not know there are several. The words are made when
// asked for, so they follow the language.
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
        Restarted, // the controller restarted: its position counters began again at 0
        Silent,    // no answer while an axis moved: it may have restarted, it is not known
    };
    Q_ENUM(Reason)

    explicit ReferenceTracker(int motors, QObject *parent = nullptr);

    int motorCount() const { return m_motors; }
    bool isReferenced(int motor) const { return reason(motor) == Reason::Homed; }
    // Whether StepCom knows if it is referenced: not after a silence while it moved.
    bool isKnown(int motor) const { return reason(motor) != Reason::Silent; }
    Reason reason(int motor) const { return reasonOn(m_view, motor); }
    // "referenced" / "not referenced (E-STOP)", in the installed language.
    QString text(int motor) const { return textOn(m_view, motor); }

    // The same for any device of the line.
    bool isReferencedOn(int device, int motor) const;
    Reason reasonOn(int device, int motor) const;
    QString textOn(int device, int motor) const;
    QList<int> referencedMotors(int device) const;

    void setReason(int motor, Reason reason) { setReasonOn(m_view, motor, reason); }
    void setReasonOn(int device, int motor, Reason reason);
    // Every axis of `device` loses its reference for `reason` (only referenced ones change).
    void loseAll(int device, Reason reason);
    void loseAll(Reason reason) { loseAll(m_view, reason); }
    // Every axis of every device (the link is gone).
    void loseEverywhere(Reason reason);

    // The device the calls without an id are about; every motor's view changes.
    int view() const { return m_view; }
    void setView(int device);
    // The controller in view got a new id: what was known of it goes with it.
    void renameView(int device);

Q_SIGNALS:
    // A motor of the device in view (also for every motor when the view moves).
    void changed(int motor);
    // Something of `device` changed, in view or not.
    void deviceChanged(int device);

private:
    QHash<int, QList<Reason>> m_reasons; // by device id; a device never seen: never homed
    int m_motors;
    int m_view = 1;
};

} // namespace stepcom
