#include "pendant/pendantcontrol.h"

#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/stepmove.h"

namespace stepcom {

PendantControl::PendantControl(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    JogController *jog = session->jog();
    for (int n = 1; n <= jog->motorCount(); ++n) {
        Hold h;
        h.watchdog = std::make_unique<QTimer>();
        h.watchdog->setSingleShot(true);
        h.watchdog->setInterval(kHoldTimeoutMs);
        h.watchdog->setTimerType(Qt::PreciseTimer); // a coarse timer may add 5 %: 15 ms
        connect(h.watchdog.get(), &QTimer::timeout, this, [this, n] {
            stopMotor(n, tr("no hold from the pendant for %1 ms").arg(kHoldTimeoutMs));
        });
        m_holds.push_back(std::move(h));
    }
    connect(jog, &JogController::stateChanged, this,
            [this](int motor, JogController::State) { onJogState(motor); });
}

PendantControl::~PendantControl()
{
    // Going away with a motor held (the pendant stopped, the window closing): stop it first.
    for (int n = 1; n <= motors(); ++n)
        stopMotor(n, tr("the pendant stopped"));
}

int PendantControl::jogOwner(int motor) const
{
    return motor >= 1 && motor <= motors() ? m_holds.at(size_t(motor - 1)).owner : 0;
}

void PendantControl::setAllowed(bool allowed)
{
    if (m_allowed == allowed)
        return;
    m_allowed = allowed;
    if (!allowed) {
        stopJogsOf(0, tr("jogging from the pendant was turned off"));
        setHolder(0);
    }
    Q_EMIT allowedChanged(allowed);
}

void PendantControl::setHolder(int client)
{
    if (m_holder == client)
        return;
    m_holder = client;
    Q_EMIT holderChanged(client);
}

QString PendantControl::take(int client)
{
    if (!m_allowed)
        return tr("Jogging from the pendant is not allowed in the window");
    if (m_holder != 0 && m_holder != client)
        stopJogsOf(m_holder, tr("another phone took control"));
    setHolder(client);
    return {};
}

void PendantControl::giveUp(int client)
{
    if (m_holder != client)
        return;
    stopJogsOf(client, tr("the phone gave up control"));
    setHolder(0);
}

void PendantControl::takeBack()
{
    stopJogsOf(0, tr("the window took control back"));
    setHolder(0);
}

void PendantControl::clientGone(int client)
{
    stopJogsOf(client, tr("the phone's connection closed"));
    if (m_holder == client)
        setHolder(0);
}

QString PendantControl::mayMove(int client) const
{
    if (!m_allowed)
        return tr("Jogging from the pendant is not allowed in the window");
    if (m_holder != client)
        return m_holder == 0 ? tr("Take control first") : tr("Another phone holds control");
    return {};
}

QString PendantControl::jog(int client, int motor, bool forward)
{
    if (const QString no = mayMove(client); !no.isEmpty())
        return no;
    if (motor < 1 || motor > motors())
        return tr("There is no motor %1").arg(motor);
    JogController *jog = m_session->jog();
    // The controller says why it refuses in its messages; the phone hears the last of them.
    QString said;
    const auto listen = connect(jog, &JogController::message, this,
                                [&said](DeviceSession::Severity, const QString &t) { said = t; });
    const bool started = jog->press(
        motor, forward ? JogController::Direction::Forward : JogController::Direction::Reverse,
        JogController::Source::Pendant);
    disconnect(listen);
    if (!started)
        return said.isEmpty() ? tr("Motor %1 does not move").arg(motor) : said;
    Hold &h = m_holds[size_t(motor - 1)];
    h.owner = client;
    h.watchdog->start();
    Q_EMIT jogStarted(client, motor, forward);
    return {};
}

QString PendantControl::step(int client, int motor, bool forward, double size)
{
    if (const QString no = mayMove(client); !no.isEmpty())
        return no;
    if (!(size > 0))
        return tr("A step must be greater than 0");
    StepMoveRequest request;
    request.kind = StepMoveRequest::Kind::By;
    request.motor = motor;
    request.value = forward ? size : -size;
    return m_session->stepMove()->start(request);
}

void PendantControl::hold(int client, int motor)
{
    if (motor < 1 || motor > motors())
        return;
    Hold &h = m_holds[size_t(motor - 1)];
    if (h.owner != 0 && h.owner == client)
        h.watchdog->start();
}

void PendantControl::stop(int client, int motor, const QString &why)
{
    if (jogOwner(motor) == client && client != 0)
        stopMotor(motor, why);
}

void PendantControl::stopJogsOf(int client, const QString &why)
{
    for (int n = 1; n <= motors(); ++n) {
        const int owner = m_holds.at(size_t(n - 1)).owner;
        if (owner != 0 && (client == 0 || owner == client))
            stopMotor(n, why);
    }
}

void PendantControl::stopMotor(int motor, const QString &why)
{
    Hold &h = m_holds[size_t(motor - 1)];
    h.watchdog->stop();
    if (h.owner == 0 || !m_session)
        return;
    // The stop goes out through the jog controller (read back as every jog's), even when the
    // phone is gone: nothing here waits for the phone.
    m_session->jog()->release(motor, JogController::Source::Pendant, why);
    onJogState(motor);
}

void PendantControl::onJogState(int motor)
{
    if (motor < 1 || motor > motors() || !m_session)
        return;
    Hold &h = m_holds[size_t(motor - 1)];
    const JogController *jog = m_session->jog();
    if (h.owner == 0 || jog->isJogging(motor))
        return;
    // Ended, by us or by the window's rules (E-STOP, page change, focus loss, travel limit).
    const int owner = std::exchange(h.owner, 0);
    h.watchdog->stop();
    Q_EMIT jogEnded(owner, motor, jog->stopReason(motor));
}

} // namespace stepcom
