#pragma once

#include "session/stepmove.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

namespace stepcom {

class DeviceSession;
struct Parameter;

// One motor's values as a proof read them before it moved, in the registers' units.
struct ProofSetup
{
    int motor = 1;
    double stepAngle = 0;  // degrees
    double microsteps = 0; // pulses per full step
    double startHz = 0;
    qint64 accelRaw = 0; // the acceleration register as read (Hz gained per ms)
    qint64 speedRpm = 0; // the speed register as read
    double pitch = 0;    // distance units a turn
    int homeInput = 0;   // 1-4, 0 none
    int limitNegative = 0;
    double position = 0; // distance units, the count
    double positionResolution = 0.01;

    double pulsesPerUnit() const;
    // 4 full steps: the electrical cycle a stalled hybrid motor relocks in.
    double chunk() const;
    // What a count can tell: the position register's step or a pulse, the larger.
    double resolution() const;
    // The speed (rpm) of a pulse rate.
    double rpmOfHz(double hz) const;
};

// The moves, reads and register writes a proof of one axis is made of, over the session: a
// single move through StepMove (judged, the user's distance and direction put back), the home
// input read with the count, the speed and acceleration registers written and put back as they
// were read. It notes what ended the proof from outside (an E-STOP, the link, a restart) and
// stops the motor when the user asks; after that only the stop and the restore go out.
class ProofDrive : public QObject
{
    Q_OBJECT
public:
    enum class Halt { None, Stopped, EmergencyStop, LinkLost, Restarted };
    static constexpr int kLinkWaitMs = 30000;

    ProofDrive(DeviceSession *session, int motor, QObject *parent = nullptr);
    // A new drive for `owner`'s next test in `slot`: the one before is let go (its callbacks
    // may still be on the stack, so it is deleted later) and no longer talks to `owner`.
    static ProofDrive *renew(ProofDrive *&slot, DeviceSession *session, int motor, QObject *owner);

    // What keeps this motor from being proven at all (no such motor, not connected); empty if
    // nothing.
    QString refusal() const;
    // After readSetup(): why a test that references on the home switch cannot run (no home
    // input set); empty when it can.
    QString homeInputRefusal() const;
    // Reads the motor's values into setup(); `done(error)` with an empty error on success.
    void readSetup(std::function<void(const QString &error)> done);
    const ProofSetup &setup() const { return m_setup; }
    DeviceSession *session() const { return m_session; }
    const Parameter *parameter(const char *local) const;

    // Writes the speed (and, given, the acceleration register), verified; only what differs
    // from what it holds goes out.
    void setSpeed(qint64 rpm, std::optional<qint64> accel,
                  std::function<void(const QString &error)> done);
    // A single move by `units` (+ or −) from where the count stands.
    void moveBy(double units, std::function<void(const StepMoveResult &)> done);
    // The home input and the count, read together.
    void readHome(std::function<void(const QString &error, bool on, double position)> done);
    // The speed and acceleration registers back as readSetup() found them, verified; after an
    // E-STOP it waits for the E-STOP's own answer first, after a lost link for the reconnect
    // (when the session tries again on its own, at most kLinkWaitMs). `done(restored, text)`.
    void restore(std::function<void(bool restored, const QString &text)> done);

    // Stops the motor at once (its stop coil); the proof ends with what it knows.
    void stop();
    Halt halt() const { return m_halt; }
    // What ended the proof from outside, in words; empty while nothing did.
    QString haltText() const;

Q_SIGNALS:
    // An E-STOP, the link lost, a restart or stop(): the proof must end.
    void halted();

private:
    void setHalt(Halt halt);
    void writeBack(std::function<void(bool, const QString &)> done);

    QPointer<DeviceSession> m_session;
    int m_motor;
    ProofSetup m_setup;
    Halt m_halt = Halt::None;
    bool m_estopAnswered = true;
    std::function<void()> m_afterEstop;
    std::function<void(const StepMoveResult &)> m_moveDone;
    qint64 m_speedHeld = 0; // what the registers hold now, as the proof wrote them
    qint64 m_accelHeld = 0;
    bool m_waitedForLink = false;
};

} // namespace stepcom
