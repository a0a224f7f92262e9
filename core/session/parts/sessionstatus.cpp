#include "session/parts/sessionstatus.h"

#include "device/parameterstore.h"
#include "device/poller.h"
#include "device/statusrecorder.h"

namespace stepcom {

SessionStatus::SessionStatus(Poller *poller, ParameterStore *store, QObject *parent)
    : QObject(parent)
    , m_poller(poller)
    , m_store(store)
{
    connect(m_poller, &Poller::fastChanged, this, &SessionStatus::statusFastChanged);
}

void SessionStatus::start()
{
    m_poller->start();
}

void SessionStatus::stop()
{
    m_poller->stop();
}

bool SessionStatus::isActive() const
{
    return m_poller->isActive();
}

QStringList SessionStatus::keys() const
{
    return m_poller->keys();
}

void SessionStatus::setIntervalMs(int ms)
{
    m_poller->setIntervalMs(ms);
}

int SessionStatus::intervalMs() const
{
    return m_poller->intervalMs();
}

double SessionStatus::rate() const
{
    return m_poller->rate();
}

bool SessionStatus::isFast() const
{
    return m_poller->isFast();
}

QString SessionStatus::error() const
{
    return m_poller->lastError();
}

const PollStats &SessionStatus::stats() const
{
    return m_poller->stats();
}

void SessionStatus::resetStats()
{
    m_poller->resetStats();
}

StatusRecorder *SessionStatus::recorder()
{
    if (!m_recorder) {
        m_recorder = new StatusRecorder(m_store->map(), m_store, this);
        m_recorder->attach(m_poller);
    }
    return m_recorder;
}

} // namespace stepcom
