#pragma once

#include <QHash>
#include <QList>
#include <QString>

#include <optional>

namespace stepcom {

class RegisterMap;

// Raw register values by key, as read from the controller (a store snapshot or one read).
using StatusValues = QHash<QString, qint64>;

// The motion commands whose end StepCom judges (forward/reverse run until stopped: no end).
enum class MotionKind { SingleMove, Home, HomeInOrder, ReturnToZero, Arc, Line };

// Something from outside the motion that may have ended it, as StepCom saw it go out or happen.
// Silent: the controller did not answer for a while as it moved and then stood at 0: the motion
// may have ended there or the controller may have restarted -- how it ended is not known.
enum class MotionCause { None, Stop, EmergencyStop, LinkLost, Silent, Restarted };

// A motion command as it was acknowledged: which axes it moves and where they should end.
struct MotionStart
{
    MotionKind kind = MotionKind::SingleMove;
    QString command;           // the coil key ("motor1.move", "arc.start")
    QList<int> motors;         // the axes it moves, in order
    QHash<int, qint64> target; // expected end position per motor, raw counts (not for homing)
};

// One axis where the motion ended.
struct AxisEnd
{
    int motor = 0;
    std::optional<qint64> position;
    std::optional<qint64> target;
    bool atTarget = false;    // a move: within one count of the target
    bool referenced = false;  // homing: home input on where it stopped, position 0
    int homeInput = 0;        // 0: none set
    bool homeInputOn = false; // the home input read ON at the end
    int limitPositiveOn = 0;  // the positive-limit input number when it read ON, else 0
    int limitNegativeOn = 0;  // the same for the negative limit
};

// What a motion command came to, judged from the controller's registers when its running
// flags dropped. The controller has no "done" flag: this is StepCom's verdict, and it says why.
struct MotionOutcome
{
    enum class Verdict {
        Done,        // every axis within one count of its end point
        Referenced,  // homing ended on the home input at 0, nothing stopped it
        Stopped,     // a move ended elsewhere
        Interrupted, // homing was stopped (stop, E-STOP, link loss)
        NoHomeInput, // homing ended without the home input
        NotKnown,    // the controller fell silent as it moved: where and how it ended is not known
    };

    MotionStart start;
    Verdict verdict = Verdict::Stopped;
    MotionCause cause = MotionCause::None;
    QList<AxisEnd> axes;

    bool ok() const { return verdict == Verdict::Done || verdict == Verdict::Referenced; }
    // Stable English words for scripts: done, referenced, stopped, interrupted, not_referenced.
    QString verdictWord() const;
    // none, stop, estop, link_lost, limit, unknown.
    QString causeWord() const;
    const AxisEnd *axis(int motor) const;
};

} // namespace stepcom
