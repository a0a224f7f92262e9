#include "proof/proofdrive.h"

#include "motion/motorderived.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/reconnector.h"

#include <QTimer>

#include <cmath>
#include <memory>

namespace stepcom {

double ProofSetup::pulsesPerUnit() const
{
    const auto perRev = motorderived::pulsesPerRevolution(stepAngle, microsteps);
    const auto perUnit = perRev ? motorderived::pulsesPerUnit(*perRev, pitch) : std::nullopt;
    return perUnit.value_or(0);
}

double ProofSetup::chunk() const
{
    const double perUnit = pulsesPerUnit();
    return perUnit > 0 ? 4 * microsteps / perUnit : 0;
}

double ProofSetup::resolution() const
{
    const double perUnit = pulsesPerUnit();
    return std::max(positionResolution, perUnit > 0 ? 1 / perUnit : 0.0);
}

double ProofSetup::rpmOfHz(double hz) const
{
    const auto perRev = motorderived::pulsesPerRevolution(stepAngle, microsteps);
    return perRev && *perRev > 0 ? hz * 60 / *perRev : 0;
}

ProofDrive::ProofDrive(DeviceSession *session, int motor, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_motor(motor)
{
    m_setup.motor = motor;
    connect(session, &DeviceSession::emergencyStopRequested, this, [this] {
        m_estopAnswered = false;
        setHalt(Halt::EmergencyStop);
    });
    const auto estopAnswered = [this] {
        if (m_estopAnswered)
            return;
        m_estopAnswered = true;
        if (auto next = std::exchange(m_afterEstop, {}))
            next();
    };
    connect(session, &DeviceSession::commandFinished, this,
            [estopAnswered](const QString &key, bool) {
                if (key == QLatin1String("estop"))
                    estopAnswered();
            });
    connect(session, &DeviceSession::emergencyStopFinished, this, estopAnswered);
    connect(session->connection(), &SessionConnection::linkLost, this, [this, estopAnswered] {
        setHalt(Halt::LinkLost);
        estopAnswered(); // no answer comes now: the restore says what it could not do
    });
    connect(session, &DeviceSession::controllerRestarted, this,
            [this] { setHalt(Halt::Restarted); });
    connect(session, &DeviceSession::controllerMayHaveRestarted, this,
            [this] { setHalt(Halt::Restarted); });
    connect(session->stepMove(), &StepMove::finished, this, [this](const StepMoveResult &r) {
        if (r.request.motor != m_motor)
            return;
        if (auto done = std::exchange(m_moveDone, {}))
            done(r);
    });
}

ProofDrive *ProofDrive::renew(ProofDrive *&slot, DeviceSession *session, int motor, QObject *owner)
{
    if (slot) {
        slot->disconnect(owner);
        slot->deleteLater();
    }
    slot = new ProofDrive(session, motor, owner);
    return slot;
}

const Parameter *ProofDrive::parameter(const char *local) const
{
    return m_session->map().blockParameter(kMotorBlock, m_motor, QLatin1String(local));
}

QString ProofDrive::refusal() const
{
    const int motors = m_session->map().blockCount(kMotorBlock);
    if (m_motor < 1 || m_motor > motors)
        return tr("There is no motor %1 (this controller has %2)").arg(m_motor).arg(motors);
    for (const char *local : {"step_angle", "microsteps", "start_frequency", "accel_frequency",
                              "speed", "pitch", "home_input", "position", "stop"}) {
        if (!parameter(local))
            return tr("This register map has no %1 for motor %2: the axis cannot be proven")
                .arg(QLatin1String(local))
                .arg(m_motor);
    }
    if (!m_session->connection()->isConnected())
        return tr("Not connected: nothing was sent");
    return {};
}

QString ProofDrive::homeInputRefusal() const
{
    if (m_setup.homeInput != 0)
        return {};
    return tr("Motor %1 has no home input set (%2 is 0): the test references on the home "
              "switch, so nothing was moved")
        .arg(m_motor)
        .arg(parameter("home_input")->key);
}

void ProofDrive::readSetup(std::function<void(const QString &)> done)
{
    QList<const Parameter *> params;
    for (const char *local : {"step_angle", "microsteps", "start_frequency", "accel_frequency",
                              "speed", "pitch", "home_input", "limit_negative", "position"}) {
        if (const Parameter *p = parameter(local))
            params << p;
    }
    m_session->parameters()->read(
        params,
        [this, self = QPointer<ProofDrive>(this), done](const ReadOutcome &r) {
            if (!self)
                return;
            if (!r.ok) {
                done(tr("Motor %1: its values could not be read (%2): nothing was moved")
                         .arg(m_motor)
                         .arg(r.errors.join(QLatin1String("; "))));
                return;
            }
            const auto eng = [&](const char *local) {
                const Parameter *p = parameter(local);
                return p ? p->toEngineering(r.values.value(p->key)) : 0.0;
            };
            const auto raw = [&](const char *local) {
                const Parameter *p = parameter(local);
                return p ? r.values.value(p->key) : 0;
            };
            m_setup.stepAngle = eng("step_angle");
            m_setup.microsteps = eng("microsteps");
            m_setup.startHz = eng("start_frequency");
            m_setup.accelRaw = raw("accel_frequency");
            m_setup.speedRpm = raw("speed");
            m_setup.pitch = eng("pitch");
            m_setup.homeInput = int(raw("home_input"));
            m_setup.limitNegative = int(raw("limit_negative"));
            m_setup.position = eng("position");
            m_setup.positionResolution = 1.0 / parameter("position")->scale;
            m_speedHeld = m_setup.speedRpm;
            m_accelHeld = m_setup.accelRaw;
            if (m_setup.pulsesPerUnit() <= 0) {
                done(tr("Motor %1: its step angle, microsteps or pitch is 0: the axis cannot be "
                        "proven")
                         .arg(m_motor));
                return;
            }
            done({});
        },
        Priority::Command);
}

void ProofDrive::setSpeed(qint64 rpm, std::optional<qint64> accel,
                          std::function<void(const QString &)> done)
{
    QList<ParameterWrite> writes;
    if (rpm != m_speedHeld)
        writes.append({parameter("speed"), rpm});
    if (accel && *accel != m_accelHeld)
        writes.append({parameter("accel_frequency"), *accel});
    if (writes.isEmpty()) {
        done({});
        return;
    }
    m_session->parameters()->write(
        writes, [this, self = QPointer<ProofDrive>(this), rpm, accel, done](const WriteOutcome &w) {
            if (!self)
                return;
            if (w.verified(parameter("speed")->key))
                m_speedHeld = rpm;
            if (accel && w.verified(parameter("accel_frequency")->key))
                m_accelHeld = *accel;
            if (!w.ok) {
                done(tr("Motor %1: the test speed could not be written (%2)")
                         .arg(m_motor)
                         .arg(w.errors.join(QLatin1String("; "))));
                return;
            }
            done({});
        });
}

void ProofDrive::moveBy(double units, std::function<void(const StepMoveResult &)> done)
{
    StepMoveRequest request;
    request.kind = StepMoveRequest::Kind::By;
    request.motor = m_motor;
    request.value = units;
    m_moveDone = std::move(done);
    if (const QString why = m_session->stepMove()->start(request); !why.isEmpty()) {
        StepMoveResult refused;
        refused.request = request;
        refused.text = why;
        if (auto next = std::exchange(m_moveDone, {}))
            next(refused);
    }
}

void ProofDrive::readHome(std::function<void(const QString &, bool, double)> done)
{
    const Parameter *input =
        m_session->map().find(QStringLiteral("io.in%1").arg(m_setup.homeInput));
    const Parameter *position = parameter("position");
    if (!input) {
        done(tr("This register map has no input %1").arg(m_setup.homeInput), false, 0);
        return;
    }
    m_session->parameters()->read(
        {input, position},
        [self = QPointer<ProofDrive>(this), input, position, done](const ReadOutcome &r) {
            if (!self)
                return;
            if (!r.ok) {
                done(tr("the home input could not be read (%1)")
                         .arg(r.errors.join(QLatin1String("; "))),
                     false, 0);
                return;
            }
            done({}, r.values.value(input->key) != 0,
                 position->toEngineering(r.values.value(position->key)));
        },
        Priority::Command);
}

void ProofDrive::restore(std::function<void(bool, const QString &)> done)
{
    if (!m_estopAnswered) {
        // The E-STOP goes first and alone: the registers are written once it was answered.
        m_afterEstop = [this, done] { writeBack(done); };
        return;
    }
    writeBack(std::move(done));
}

void ProofDrive::writeBack(std::function<void(bool, const QString &)> done)
{
    const Parameter *speed = parameter("speed");
    const Parameter *accel = parameter("accel_frequency");
    QList<ParameterWrite> writes;
    if (m_speedHeld != m_setup.speedRpm)
        writes.append({speed, m_setup.speedRpm});
    if (m_accelHeld != m_setup.accelRaw)
        writes.append({accel, m_setup.accelRaw});
    const QString values = tr("speed %1 %2, acceleration %3 %4")
                               .arg(speed->formatRaw(m_setup.speedRpm), speed->unit,
                                    accel->formatRaw(m_setup.accelRaw), accel->unit);
    if (writes.isEmpty()) {
        done(true, tr("Motor %1's own %2 are as they were.").arg(m_motor).arg(values));
        return;
    }
    if (!m_session->connection()->isConnected()) {
        const auto notBack = [this, values, done] {
            done(false, tr("Motor %1's own %2 could not be put back: not connected. Write them "
                           "again once the controller answers.")
                            .arg(m_motor)
                            .arg(values));
        };
        Reconnector *again = m_session->connection()->reconnector();
        if (!again->isEnabled() || m_waitedForLink) {
            notBack();
            return;
        }
        // The window tries the link again on its own: the registers go back once it is up,
        // within a while.
        m_waitedForLink = true;
        auto *timeout = new QTimer(this);
        timeout->setSingleShot(true);
        const auto once = std::make_shared<bool>(false);
        connect(m_session->connection(), &SessionConnection::connected, timeout,
                [this, done, timeout, once](bool ok) {
                    if (!ok || std::exchange(*once, true))
                        return;
                    timeout->deleteLater();
                    writeBack(done);
                });
        connect(timeout, &QTimer::timeout, this, [timeout, once, notBack] {
            if (std::exchange(*once, true))
                return;
            timeout->deleteLater();
            notBack();
        });
        timeout->start(kLinkWaitMs);
        return;
    }
    m_session->parameters()->write(
        writes, [this, self = QPointer<ProofDrive>(this), values, done](const WriteOutcome &w) {
            if (!self)
                return;
            if (!w.ok) {
                done(false, tr("Motor %1's own %2 could not be put back: %3")
                                .arg(m_motor)
                                .arg(values, w.errors.join(QLatin1String("; "))));
                return;
            }
            m_speedHeld = m_setup.speedRpm;
            m_accelHeld = m_setup.accelRaw;
            done(true, tr("Motor %1's own %2 are back (verified).").arg(m_motor).arg(values));
        });
}

void ProofDrive::stop()
{
    setHalt(Halt::Stopped);
    if (m_session && m_session->connection()->isConnected())
        m_session->command(parameter("stop")->key);
}

void ProofDrive::setHalt(Halt halt)
{
    if (m_halt != Halt::None)
        return;
    m_halt = halt;
    Q_EMIT halted();
}

QString ProofDrive::haltText() const
{
    switch (m_halt) {
    case Halt::None:
        return {};
    case Halt::Stopped:
        return tr("Stopped: the motor was stopped");
    case Halt::EmergencyStop:
        return tr("E-STOP: the test ended at once");
    case Halt::LinkLost:
        return tr("The link was lost: the test ended");
    case Halt::Restarted:
        return tr("The controller restarted: the test ended");
    }
    return {};
}

} // namespace stepcom
