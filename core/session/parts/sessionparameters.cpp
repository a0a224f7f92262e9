#include "session/parts/sessionparameters.h"

#include "bus/modbuslink.h"
#include "device/parameterstore.h"
#include "session/devicesession.h"
#include "session/parts/sessionline.h"

namespace stepcom {

SessionParameters::SessionParameters(DeviceSession *session, ParameterStore *store)
    : QObject(session)
    , m_session(session)
    , m_store(store)
{}

void SessionParameters::readAll()
{
    const int id = m_session->m_line->deviceInView();
    m_session->m_client->readAll([this, id](const ReadOutcome &r) {
        if (id != m_session->m_line->deviceInView()) {
            // Another device was shown meanwhile: its blocks went to that one, none is sure.
            Q_EMIT readFinished(false);
            return;
        }
        m_store->setDeviceValues(r.values);
        if (!r.ok)
            m_session->say(
                DeviceSession::Severity::Error,
                DeviceSession::tr("Reading failed: %1").arg(r.errors.join(QLatin1String("; "))));
        else
            m_session->say(
                DeviceSession::Severity::Info,
                DeviceSession::tr("Read %1 in %2", "%1: n parameters, %2: n requests")
                    .arg(DeviceSession::tr("%n parameter(s)", nullptr, int(r.values.size())),
                         DeviceSession::tr("%n request(s)", nullptr, r.reads)));
        Q_EMIT readFinished(r.ok);
    });
}

void SessionParameters::read(const QList<const Parameter *> &params,
                             std::function<void(const ReadOutcome &)> done, Priority priority)
{
    m_session->m_client->read(params, priority, std::move(done));
}

void SessionParameters::readAll(std::function<void(const ReadOutcome &)> done)
{
    m_session->m_client->readAll(std::move(done));
}

void SessionParameters::writeChanges()
{
    write(m_store->pendingWrites());
}

void SessionParameters::write(const QList<ParameterWrite> &writes,
                              std::function<void(const WriteOutcome &)> done)
{
    if (writes.isEmpty())
        return;
    const LinkSettings before = m_session->m_link->settings();
    m_session->m_client->write(writes, [this, writes, before, done](const WriteOutcome &outcome) {
        m_store->applyWriteOutcome(writes, outcome);
        readBackUncertain(writes, outcome);
        if (outcome.ok) {
            m_session->say(DeviceSession::Severity::Info,
                           DeviceSession::tr("Wrote and verified %n parameter(s)", nullptr,
                                             int(outcome.written.size())));
        } else {
            for (const QString &e : outcome.errors)
                m_session->say(DeviceSession::Severity::Error, e);
        }
        // A write that carried device.id or device.baud (a profile applied with its link
        // settings) moved the link: tell the pages, as line()->changeLink() does.
        const LinkSettings now = m_session->m_link->settings();
        if (now.deviceId != before.deviceId || now.baud != before.baud)
            Q_EMIT m_session->m_line->linkChanged(now);
        if (done)
            done(outcome);
        Q_EMIT writeFinished(outcome);
    });
}

void SessionParameters::readBackUncertain(const QList<ParameterWrite> &writes,
                                          const WriteOutcome &outcome)
{
    QList<const Parameter *> uncertain; // sent, but failed: the store forgot their value
    for (const ParameterWrite &w : writes) {
        const QString &key = w.parameter->key;
        if (outcome.uncertain(key) || outcome.refused.contains(key))
            uncertain << w.parameter;
    }
    if (uncertain.isEmpty() || !m_session->m_link->isConnected() || !m_session->m_live)
        return;
    m_session->m_client->read(uncertain, Priority::Command,
                              [this](const ReadOutcome &r) { m_store->setDeviceValues(r.values); });
}

} // namespace stepcom
