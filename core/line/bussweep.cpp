#include "line/bussweep.h"

#include "session/devicesession.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

namespace stepcom {

BusSweep::BusSweep(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    connect(session, &DeviceSession::emergencyStopRequested, this, [this] {
        if (!m_busy)
            return;
        ++m_generation; // the read on its way belongs to nothing now
        for (qsizetype i = m_index; i < m_ids.size(); ++i) {
            ReadOutcome stopped;
            stopped.errors << tr("id %1 was not read: E-STOP").arg(m_ids.at(i));
            m_outcomes.insert(m_ids.at(i), stopped);
        }
        m_busy = false;
        Q_EMIT finished(false);
    });
}

void BusSweep::start(const QList<int> &ids, const QList<const Parameter *> &params)
{
    if (m_busy)
        return;
    m_ids = ids;
    m_params = params;
    m_outcomes.clear();
    m_index = 0;
    m_busy = true;
    next();
}

void BusSweep::next()
{
    if (m_index >= m_ids.size() || !m_session) {
        m_busy = false;
        Q_EMIT finished(allOk());
        return;
    }
    const int id = m_ids.at(m_index);
    const quint64 generation = m_generation;
    QPointer<BusSweep> self(this); // its owner may be gone by the answer
    m_session->line()->readDevice(id, m_params, [this, self, id, generation](const ReadOutcome &r) {
        if (!self || generation != m_generation)
            return;
        m_outcomes.insert(id, r);
        ++m_index;
        Q_EMIT deviceRead(id, r.ok);
        next();
    });
}

bool BusSweep::allOk() const
{
    for (int id : m_ids) {
        if (!m_outcomes.value(id).ok)
            return false;
    }
    return !m_ids.isEmpty();
}

} // namespace stepcom
