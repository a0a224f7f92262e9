#include "widgets/jogactivity.h"

#include "device/devicesession.h"

namespace stepcom {

JogActivity::JogActivity(DeviceSession *session, const QStringList &runningKeys, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_keys(runningKeys)
{
    connect(session, &DeviceSession::statusCycleFinished, this,
            [this](bool ok, qint64) { onCycle(ok); });
    connect(session, &DeviceSession::disconnected, this, &JogActivity::clear);
}

void JogActivity::start(const QString &what)
{
    m_what = what;
    m_active = true;
    m_cycles = 0;
    m_idleCycles = 0;
    Q_EMIT changed();
}

void JogActivity::clear()
{
    if (!m_active)
        return;
    m_active = false;
    Q_EMIT changed();
}

QList<int> JogActivity::running() const
{
    QList<int> on;
    for (int i = 0; i < m_keys.size(); ++i) {
        if (m_session->parameters()->deviceValue(m_keys.at(i)).value_or(0) != 0)
            on << i + 1;
    }
    return on;
}

void JogActivity::onCycle(bool ok)
{
    if (!m_active || !ok)
        return;
    // The first cycle to finish may have read the flags before the command was answered.
    if (++m_cycles < 2) {
        Q_EMIT changed();
        return;
    }
    // Idle in two cycles running: one cycle's positions may predate its running flags, and a
    // sequence may pause between two motors.
    m_idleCycles = running().isEmpty() ? m_idleCycles + 1 : 0;
    if (m_idleCycles < 2) {
        Q_EMIT changed();
        return;
    }
    m_active = false;
    Q_EMIT changed();
    Q_EMIT finished(m_what);
}

} // namespace stepcom
