#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"

#include "session/motionsupervisor.h"

#include <QTimer>

#include <algorithm>

namespace stepcom {

namespace {

// A result that says the link itself is gone (closed or lost), not that the device refused.
bool linkGone(const Result &r)
{
    return r.error == QModbusDevice::ConnectionError;
}

} // namespace

JogController::JogController(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    m_motors.resize(session->map().blockCount(kMotorBlock));
    connect(session->connection(), &SessionConnection::disconnected, this,
            &JogController::onDisconnected);
    connect(session->connection(), &SessionConnection::connected, this,
            [this](bool ok, const QString &) { onConnected(ok); });
    // The E-STOP stopped every motor: the jogs end now (and are checked like any stop).
    connect(session->motion(), &MotionSupervisor::emergencyStopSent, this, [this] {
        stopAll(tr("E-STOP"));
        Q_EMIT heldControlsReset();
    });
    // A motor that kept running after its stop is cleared once the poller sees it idle.
    connect(session->status(), &SessionStatus::statusCycleFinished, this, [this] {
        stopAtTravelLimits();
        for (int n = 1; n <= motorCount(); ++n) {
            if (at(n).state == State::StillRunning &&
                m_session->parameters()->store()->deviceValue(
                    motorKey(n, QStringLiteral("running"))) == 0) {
                setState(n, State::Idle);
                say(DeviceSession::Severity::Info, tr("Motor %1 has stopped now").arg(n));
            }
        }
    });
}

JogController::~JogController()
{
    // Leaving with a motor held: the stop still goes out (nobody is left to check it).
    DeviceSession *session = m_session;
    if (!session || !session->connection()->isConnected())
        return;
    for (int n = 1; n <= motorCount(); ++n) {
        const Motor &m = at(n);
        if (m.state != State::Jogging && m.state != State::StillRunning && !m.stopWanted)
            continue;
        if (const Parameter *coil = session->map().find(motorKey(n, QStringLiteral("stop"))))
            session->command(*coil, [](const Result &) {});
    }
}

void JogController::stopAtTravelLimits()
{
    const TravelLimits &limits = m_session->travelLimits();
    if (limits.isEmpty())
        return;
    for (int n = 1; n <= motorCount(); ++n) {
        if (at(n).state != State::Jogging)
            continue;
        const auto pos =
            m_session->parameters()->store()->deviceValue(motorKey(n, QStringLiteral("position")));
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), n);
        if (!pos || !p)
            continue;
        const QString why = limits.crossed(
            m_session->map(), n, at(n).direction == Direction::Forward, p->toEngineering(*pos));
        if (!why.isEmpty()) {
            warn(n, why);
            stop(n, why);
        }
    }
}

QString JogController::motorKey(int motor, const QString &localKey) const
{
    const Parameter *p = m_session->map().blockParameter(kMotorBlock, motor, localKey);
    return p ? p->key : QString();
}

JogController::State JogController::state(int motor) const
{
    return validMotor(motor) ? at(motor).state : State::Idle;
}

std::optional<JogController::Direction> JogController::direction(int motor) const
{
    if (!validMotor(motor) || at(motor).state != State::Jogging)
        return std::nullopt;
    return at(motor).direction;
}

JogController::Source JogController::source(int motor) const
{
    return validMotor(motor) ? at(motor).source : Source::Pointer;
}

QString JogController::stopReason(int motor) const
{
    return validMotor(motor) ? at(motor).stopReason : QString();
}

bool JogController::isBusy() const
{
    if (m_checksInFlight > 0)
        return true;
    return std::any_of(m_motors.cbegin(), m_motors.cend(), [](const Motor &m) {
        return m.state == State::Jogging || m.startPending || m.stopWanted || m.stopsInFlight > 0;
    });
}

void JogController::setKeyboardEnabled(bool enabled)
{
    if (m_keyboard == enabled)
        return;
    m_keyboard = enabled;
    if (!enabled) {
        for (int n = 1; n <= motorCount(); ++n)
            release(n, Source::Keyboard);
    }
    say(DeviceSession::Severity::Info,
        enabled ? tr("Keyboard jogging is on") : tr("Keyboard jogging is off"));
    Q_EMIT keyboardEnabledChanged(enabled);
}

QString JogController::directionText(Direction direction) const
{
    return direction == Direction::Forward ? tr("forward") : tr("reverse");
}

void JogController::setState(int motor, State state)
{
    Motor &m = at(motor);
    if (m.state == state)
        return;
    m.state = state;
    Q_EMIT stateChanged(motor, state);
}

void JogController::say(DeviceSession::Severity severity, const QString &text)
{
    Q_EMIT message(severity, text);
}

void JogController::warn(int motor, const QString &text)
{
    say(DeviceSession::Severity::Warning, text);
    Q_EMIT warning(motor, text);
}

bool JogController::press(int motor, Direction direction, Source source)
{
    using Severity = DeviceSession::Severity;
    if (!validMotor(motor)) {
        say(Severity::Error, tr("There is no motor %1").arg(motor));
        return false;
    }
    if (source == Source::Keyboard && !m_keyboard) {
        say(Severity::Info, tr("Keyboard jogging is off: motor %1 does not move").arg(motor));
        return false;
    }
    if (!m_session->connection()->isConnected()) {
        say(Severity::Warning, tr("Not connected: motor %1 does not move").arg(motor));
        return false;
    }
    Motor &m = at(motor);
    if (m.state == State::Jogging && m.source == Source::Gamepad && source != Source::Gamepad) {
        // A second hand on an axis the pad jogs: the pad lets go, and this press is not taken
        // either -- one hand at a time, the new one presses again.
        release(motor, Source::Gamepad, tr("another hand took over from the pad"));
        say(Severity::Warning,
            tr("Motor %1 was jogged from the pad: it stops; press again to jog it here")
                .arg(motor));
        return false;
    }
    if (m.state == State::Jogging) {
        say(Severity::Warning, tr("Motor %1 already jogs %2: let go of it first")
                                   .arg(motor)
                                   .arg(directionText(m.direction)));
        return false;
    }
    if (m.startPending) {
        say(Severity::Warning,
            tr("Motor %1: the last jog command is still on its way; press again").arg(motor));
        return false;
    }
    if (m.state == State::StillRunning || m.state == State::PossiblyRunning) {
        say(Severity::Warning,
            tr("Motor %1 may still be running after its stop: stop it before jogging").arg(motor));
        return false;
    }
    // A stop of ours in flight makes the last poll stale; otherwise trust it.
    if (m.state != State::Stopping && m_session->parameters()->store()->deviceValue(
                                          motorKey(motor, QStringLiteral("running"))) == 1) {
        say(Severity::Warning, tr("Motor %1 is moving (a single move, homing or another command): "
                                  "stop it before jogging")
                                   .arg(motor));
        return false;
    }
    // The software travel limits: an axis at or beyond one may only jog back.
    if (const auto pos = m_session->parameters()->store()->deviceValue(
            motorKey(motor, QStringLiteral("position")));
        pos && !m_session->travelLimits().isEmpty()) {
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), motor);
        const QString why = m_session->travelLimits().refuseJog(
            m_session->map(), motor, direction == Direction::Forward, p->toEngineering(*pos));
        if (!why.isEmpty()) {
            say(Severity::Warning, why);
            return false;
        }
    }
    const QString local =
        direction == Direction::Forward ? QStringLiteral("forward") : QStringLiteral("reverse");
    const Parameter *coil = m_session->map().find(motorKey(motor, local));
    if (!coil) {
        say(Severity::Error, tr("Motor %1 has no %2 command in this map").arg(motor).arg(local));
        return false;
    }
    m.direction = direction;
    m.source = source;
    m.startPending = true;
    m.stopWanted = false;
    const quint64 generation = ++m.generation;
    setState(motor, State::Jogging);
    say(Severity::Info, tr("Motor %1: jog %2").arg(motor).arg(directionText(direction)));
    m_session->command(*coil,
                       [self = QPointer<JogController>(this), motor, generation](const Result &r) {
                           if (self)
                               self->onStartFinished(motor, generation, r);
                       });
    return true;
}

void JogController::release(int motor, Source source, const QString &reason)
{
    const QString why = reason.isEmpty() ? tr("released") : reason;
    if (!validMotor(motor))
        return;
    Motor &m = at(motor);
    if (m.state != State::Jogging || m.source != source)
        return; // nothing held by this hand
    if (m.startPending) {
        // A stop now could overtake the queued start (stops jump the queue): stop right after.
        m.stopWanted = true;
        m.stopReason = why;
        setState(motor, State::Stopping);
        return;
    }
    sendStop(motor, why);
}

void JogController::stop(int motor, const QString &reason)
{
    if (!validMotor(motor))
        return;
    Motor &m = at(motor);
    if (m.startPending)
        m.stopWanted = true; // and once more after the start, in case it overtakes it
    sendStop(motor, reason.isEmpty() ? tr("stop button") : reason);
}

int JogController::stopAll(const QString &reason, bool spareGamepad)
{
    int stops = 0;
    for (int n = 1; n <= motorCount(); ++n) {
        Motor &m = at(n);
        if (spareGamepad && m.source == Source::Gamepad && m.state == State::Jogging)
            continue;
        if (m.state == State::StillRunning) {
            sendStop(n, reason);
            ++stops;
        } else if (m.state == State::Jogging) {
            if (m.startPending) {
                m.stopWanted = true;
                m.stopReason = reason;
                setState(n, State::Stopping);
            } else {
                sendStop(n, reason);
            }
            ++stops;
        }
    }
    return stops;
}

void JogController::sendStop(int motor, const QString &reason)
{
    Motor &m = at(motor);
    m.stopReason = reason;
    const Parameter *coil = m_session->map().find(motorKey(motor, QStringLiteral("stop")));
    if (!coil) {
        warn(motor,
             tr("Motor %1 has no stop command in this map: use the emergency stop").arg(motor));
        return;
    }
    if (!m_session->connection()->isConnected()) {
        if (m.state == State::Jogging || m.state == State::Stopping ||
            m.state == State::StillRunning)
            markPossiblyRunning(motor, tr("not connected, the stop could not be sent"));
        else
            say(DeviceSession::Severity::Warning,
                tr("Not connected: the stop for motor %1 was not sent").arg(motor));
        return;
    }
    ++m.stopsInFlight;
    setState(motor, State::Stopping);
    const quint64 generation = m.generation;
    m_session->command(*coil,
                       [self = QPointer<JogController>(this), motor, generation](const Result &r) {
                           if (self)
                               self->onStopFinished(motor, generation, r);
                       });
}

void JogController::onStartFinished(int motor, quint64 generation, const Result &result)
{
    Motor &m = at(motor);
    if (generation != m.generation)
        return;
    m.startPending = false;
    const bool stopWanted = std::exchange(m.stopWanted, false);
    if (result.ok) {
        if (stopWanted)
            sendStop(motor, m.stopReason);
        maybeSettled();
        return;
    }
    if (result.exceptionCode != 0 || result.attempts == 0) {
        // Refused by the controller, or never sent (cancelled, not connected): it did not start.
        setState(motor, State::Idle);
        say(result.error == QModbusDevice::ReplyAbortedError ? DeviceSession::Severity::Info
                                                             : DeviceSession::Severity::Error,
            tr("Motor %1: jog %2 not done: %3")
                .arg(motor)
                .arg(directionText(m.direction), result.errorText));
    } else if (linkGone(result)) {
        markPossiblyRunning(motor, result.errorText);
    } else {
        // Sent, but the answer was lost or aborted: it may well run. Stop to be sure.
        say(DeviceSession::Severity::Error, tr("Motor %1: jog %2 failed: %3")
                                                .arg(motor)
                                                .arg(directionText(m.direction), result.errorText));
        sendStop(motor, tr("the jog command failed"));
    }
    maybeSettled();
}

void JogController::onStopFinished(int motor, quint64 generation, const Result &result)
{
    Motor &m = at(motor);
    m.stopsInFlight = std::max(0, m.stopsInFlight - 1);
    if (linkGone(result)) {
        markPossiblyRunning(motor, result.errorText);
        maybeSettled();
        return;
    }
    if (!result.ok)
        warn(motor, tr("Motor %1: the stop failed: %2").arg(motor).arg(result.errorText));
    // Either way, ask the controller whether it still runs once the motor had time to stop.
    ++m_checksInFlight;
    QTimer::singleShot(m_settleMs, this, [this, motor, generation] {
        --m_checksInFlight;
        checkRunning(motor, generation, 1);
    });
}

void JogController::checkRunning(int motor, quint64 generation, int retries)
{
    Motor &m = at(motor);
    // A new jog since this stop, or another stop still to come: that one checks.
    if (generation != m.generation || m.state != State::Stopping || m.stopsInFlight > 0 ||
        m.stopWanted) {
        maybeSettled();
        return;
    }
    const QString key = motorKey(motor, QStringLiteral("running"));
    const Parameter *running = m_session->map().find(key);
    if (!running || !m_session->connection()->isConnected()) {
        if (!running)
            setState(motor, State::Idle);
        maybeSettled();
        return;
    }
    ++m_checksInFlight;
    m_session->parameters()->read(
        {running},
        [self = QPointer<JogController>(this), motor, generation, key,
         retries](const ReadOutcome &o) {
            if (self)
                self->onRunningRead(motor, generation, retries, key, o);
        },
        Priority::Command);
}

void JogController::onRunningRead(int motor, quint64 generation, int retries, const QString &key,
                                  const ReadOutcome &outcome)
{
    --m_checksInFlight;
    Motor &m = at(motor);
    if (generation != m.generation || m.state != State::Stopping) {
        maybeSettled();
        return;
    }
    if (outcome.ok && outcome.values.contains(key)) {
        const qint64 value = outcome.values.value(key);
        m_session->parameters()->store()->setDeviceValues({{key, value}});
        if (value == 0) {
            setState(motor, State::Idle);
            say(DeviceSession::Severity::Info,
                tr("Motor %1 stopped (%2)").arg(motor).arg(m.stopReason));
        } else {
            setState(motor, State::StillRunning);
            warn(motor, tr("Motor %1 still runs after its stop (%2)! Use the emergency stop, "
                           "then check the controller.")
                            .arg(motor)
                            .arg(m.stopReason));
        }
    } else if (m_session->connection()->isConnected() && retries > 0) {
        // An emergency stop cancels queued reads: ask once more before raising the alarm.
        ++m_checksInFlight;
        QTimer::singleShot(m_settleMs, this, [this, motor, generation, retries] {
            --m_checksInFlight;
            checkRunning(motor, generation, retries - 1);
        });
        return;
    } else if (m_session->connection()->isConnected()) {
        setState(motor, State::StillRunning);
        warn(motor, tr("Motor %1: could not check that it stopped: %2")
                        .arg(motor)
                        .arg(outcome.errors.join(QLatin1String("; "))));
    }
    maybeSettled();
}

void JogController::markPossiblyRunning(int motor, const QString &why)
{
    Motor &m = at(motor);
    m.startPending = false;
    m.stopWanted = false;
    if (m.state == State::PossiblyRunning)
        return;
    setState(motor, State::PossiblyRunning);
    warn(motor, tr("Motor %1 is possibly still running (%2). The stop goes out as soon as the "
                   "link is back; if needed now, use the machine's own emergency stop.")
                    .arg(motor)
                    .arg(why));
}

void JogController::onDisconnected(const QString &reason)
{
    for (int n = 1; n <= motorCount(); ++n) {
        const Motor &m = at(n);
        if (m.state == State::Jogging || m.state == State::Stopping ||
            m.state == State::StillRunning || m.startPending)
            markPossiblyRunning(n, tr("the link was lost while it moved: %1").arg(reason));
    }
    maybeSettled();
}

void JogController::onConnected(bool ok)
{
    if (!ok)
        return;
    // First thing on the new link: emergency priority puts it ahead of the session's reads.
    for (int n = 1; n <= motorCount(); ++n) {
        if (at(n).state != State::PossiblyRunning)
            continue;
        say(DeviceSession::Severity::Warning,
            tr("The link is back: stopping motor %1, which was possibly still running").arg(n));
        sendStop(n, tr("link back"));
    }
}

void JogController::maybeSettled()
{
    if (!isBusy())
        Q_EMIT settled();
}

} // namespace stepcom
