#pragma once

#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"

#include <QList>
#include <QObject>
#include <QPointer>

#include <optional>

namespace stepcom {

struct Result;

// Hold-to-move jogging, the user's hands on the machine: a press starts motorN.forward or
// motorN.reverse, the release sends motorN.stop (an emergency-priority coil), and so does
// stopAll() -- which the window calls on focus loss, deactivation, page change and exit. After
// every stop the running flag is read back and a motor that still runs is reported. A jog cut
// off by a lost link is reported as possibly still running and stopped as soon as the link is
// back. No widgets here: the UI (and tests) call press/release.
class JogController : public QObject
{
    Q_OBJECT
public:
    enum class Direction { Forward, Reverse };
    Q_ENUM(Direction)
    // Who holds the jog: a release only ends a jog started by the same hand. Pendant: a phone
    // through core/pendant, whose hold messages keep it going. Gamepad: a pad through
    // core/gamepad, held by its dead-man; any other hand pressing on that motor ends it.
    enum class Source { Pointer, Keyboard, Pendant, Gamepad };
    Q_ENUM(Source)
    enum class State {
        Idle,
        Jogging,         // started (or being started) and held
        Stopping,        // stop sent or waiting to be sent, running flag not checked yet
        StillRunning,    // the stop went out but the running flag still says 1
        PossiblyRunning, // the link went away while it moved; a stop is due on reconnect
    };
    Q_ENUM(State)

    explicit JogController(DeviceSession *session, QObject *parent = nullptr);
    ~JogController() override;

    DeviceSession *session() const { return m_session; }
    int motorCount() const { return int(m_motors.size()); }

    // Start a hold-to-move jog. Does nothing but say why (message()) when not connected, when
    // this motor already jogs, when it moves on its own, or for keys while keyboard jogging is
    // off; returns whether the jog started.
    bool press(int motor, Direction direction, Source source = Source::Pointer);
    // The hand let go: stops the motor if this source holds its jog (`reason` for the messages;
    // "released" when empty).
    void release(int motor, Source source = Source::Pointer, const QString &reason = QString());
    // The stop button: send the stop now, whoever started the motion.
    void stop(int motor, const QString &reason = QString());
    // Stop every jog this controller started (focus loss, page change, exit ...). Returns how
    // many stops it sent or scheduled. `spareGamepad`: a pad's jogs go on (the pad is held at
    // the machine, whatever the window does; its dead-man and its silence stop them).
    int stopAll(const QString &reason, bool spareGamepad = false);

    State state(int motor) const;
    std::optional<Direction> direction(int motor) const; // of the jog held, if any
    // Who started the jog held or stopping now (meaningless while Idle).
    Source source(int motor) const;
    // Why the last stop of this motor was sent ("released", "E-STOP", "page changed" ...).
    QString stopReason(int motor) const;
    bool isJogging(int motor) const { return state(motor) == State::Jogging; }
    // Something is held, or a stop is still on its way or unverified.
    bool isBusy() const;

    void setKeyboardEnabled(bool enabled);
    bool keyboardEnabled() const { return m_keyboard; }
    // How long after a stop's answer the running flag is read back.
    void setSettleMs(int ms) { m_settleMs = ms; }
    int settleMs() const { return m_settleMs; }

    QString motorKey(int motor, const QString &localKey) const;

Q_SIGNALS:
    void stateChanged(int motor, stepcom::JogController::State state);
    void keyboardEnabledChanged(bool enabled);
    // Everything the controller did or refused, for the messages dock.
    void message(stepcom::DeviceSession::Severity severity, const QString &text);
    // A motor that may still run: it kept running after a stop, or the link broke while it
    // moved, or a stop failed. Show this where the user looks.
    void warning(int motor, const QString &text);
    // An E-STOP went out: whatever holds a jog (buttons, keys) must let go now, not on release.
    void heldControlsReset();
    // No stop is in flight any more (emitted after the last one is answered and checked).
    void settled();

private:
    struct Motor
    {
        State state = State::Idle;
        Direction direction = Direction::Forward;
        Source source = Source::Pointer;
        bool startPending = false; // the forward/reverse coil is not answered yet
        bool stopWanted = false;   // released before the start was answered
        int stopsInFlight = 0;
        quint64 generation = 0; // bumps on every press, so stale checks do nothing
        QString stopReason;
    };

    bool validMotor(int motor) const { return motor >= 1 && motor <= m_motors.size(); }
    Motor &at(int motor) { return m_motors[motor - 1]; }
    const Motor &at(int motor) const { return m_motors[motor - 1]; }
    void setState(int motor, State state);
    void say(DeviceSession::Severity severity, const QString &text);
    void warn(int motor, const QString &text);
    void sendStop(int motor, const QString &reason);
    void onStartFinished(int motor, quint64 generation, const Result &result);
    void onStopFinished(int motor, quint64 generation, const Result &result);
    void checkRunning(int motor, quint64 generation, int retries);
    void onRunningRead(int motor, quint64 generation, int retries, const QString &key,
                       const ReadOutcome &outcome);
    void markPossiblyRunning(int motor, const QString &why);
    void onDisconnected(const QString &reason);
    void onConnected(bool ok);
    void maybeSettled();
    // A polled position at or past a software travel limit in the jog's direction: stop now.
    void stopAtTravelLimits();
    QString directionText(Direction direction) const;

    QPointer<DeviceSession> m_session; // null when we die as the session's child
    QList<Motor> m_motors;
    bool m_keyboard = false;
    int m_settleMs = 150;
    int m_checksInFlight = 0;
};

} // namespace stepcom
