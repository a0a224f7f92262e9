#pragma once

#include "motion/motionoutcome.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>

#include <optional>

namespace stepcom {

class DeviceSession;

// What a step, a move-to or a checklist's move asks for. The controller has one single move per
// motor (move distance and direction registers, then the move coil): every kind ends up there.
struct StepMoveRequest
{
    enum class Kind {
        By,  // `value` axis units from where the axis stands, + or −
        To,  // to the position `value`
        Raw, // `value` (≥ 0) units with the direction register at `direction` (the checklist's
             // direction step moves the way the user's register says)
    };
    Kind kind = Kind::By;
    int motor = 1;
    double value = 0;
    qint64 direction = 0; // Raw only
};

// How one step ended: whether it was sent, arrived, and whether the user's own single-move
// values are back and verified. `text` says it in the installed language.
struct StepMoveResult
{
    StepMoveRequest request;
    bool started = false;  // the move coil went out and was acknowledged
    bool arrived = false;  // MotionSupervisor judged it "done" (or nothing needed to move)
    bool restored = false; // the user's distance and direction are back, verified
    std::optional<MotionOutcome> outcome;
    std::optional<double> startPosition; // axis units, as read before the move
    std::optional<double> target;
    QString warning; // a limit already ON in the step's direction, said before it went out
    QString text;
    bool ok() const { return arrived && restored; }
};

// A step jog or a move-to over the controller's single move: reads the position and the user's
// move distance and direction, refuses a target beyond the software travel limits, writes the
// step's distance and direction (verified), pulses the move coil, lets MotionSupervisor judge
// where it ended (the status poll runs for it, started if it was off), then writes the user's
// values back and verifies them. It never runs over a pending edit of those two fields.
class StepMove : public QObject
{
    Q_OBJECT
public:
    explicit StepMove(DeviceSession *session);
    ~StepMove() override;

    // The registers a step uses and puts back: motorN.move_distance, motorN.direction.
    static QStringList usedKeys(const DeviceSession &session, int motor);
    // Why this request cannot start now (not connected, busy, pending edits, motor moving ...);
    // empty when it can.
    QString refusal(const StepMoveRequest &request) const;
    // Starts it; returns the refusal (nothing was sent) or empty, then `finished` follows once.
    QString start(const StepMoveRequest &request);
    bool isBusy() const { return m_busy; }

Q_SIGNALS:
    void started(const stepcom::StepMoveRequest &request);
    // Before the move coil goes out: the step runs into a limit that is already ON.
    void warned(const QString &warning);
    void finished(const stepcom::StepMoveResult &result);

private:
    void onRead(bool ok, const QHash<QString, qint64> &values, const QStringList &errors);
    void onCommand(const QString &key, bool ok);
    void onOutcome(const MotionOutcome &outcome);
    // Writes the user's values back (those that differ), then finishes.
    void restore(const QString &why);
    void finish(const QString &text);
    QString key(const char *local) const;

    QPointer<DeviceSession> m_session;
    bool m_busy = false;
    bool m_waitingCommand = false;
    bool m_startedPoll = false;
    bool m_unsavedBefore = false;
    StepMoveResult m_result;
    qint64 m_userDistance = 0;
    qint64 m_userDirection = 0;
};

} // namespace stepcom
