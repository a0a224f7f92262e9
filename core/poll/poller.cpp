#include "poll/poller.h"

#include "device/deviceclient.h"
#include "device/parameterstore.h"

namespace stepcom {

Poller::Poller(DeviceClient *client, ParameterStore *store, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_store(store)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &Poller::runCycle);
}

void Poller::setKeys(const QStringList &keys)
{
    m_keys = keys;
}

void Poller::start()
{
    if (m_active)
        return;
    m_active = true;
    m_rate = 0.0;
    m_sinceLastStart.invalidate();
    if (!m_inCycle)
        m_timer.start(0);
}

void Poller::stop()
{
    m_active = false;
    m_timer.stop();
    ++m_generation; // a cycle still on the wire reports into nothing
    m_inCycle = false;
}

void Poller::runCycle()
{
    if (!m_active || m_inCycle)
        return;
    QList<const Parameter *> params;
    for (const QString &key : std::as_const(m_keys)) {
        if (const Parameter *p = m_client->map().find(key))
            params << p;
    }
    if (params.isEmpty())
        return;
    m_inCycle = true;
    if (m_sinceLastStart.isValid()) {
        // achieved rate: start to start, including any wait for the interval
        const double instant = 1000.0 / double(std::max<qint64>(m_sinceLastStart.elapsed(), 1));
        m_rate = m_rate <= 0.0 ? instant : 0.8 * m_rate + 0.2 * instant;
    }
    m_sinceLastStart.start();
    m_cycleClock.start();
    const quint64 generation = m_generation;
    m_client->read(params, Priority::Poll, [this, generation](const ReadOutcome &r) {
        if (generation != m_generation)
            return;
        m_inCycle = false;
        const qint64 ms = m_cycleClock.elapsed();
        m_store->setDeviceValues(r.values);
        Q_EMIT cycleFinished(r.ok, ms);
        if (m_active) // the next cycle only after this one, and not before the interval
            m_timer.start(int(std::max<qint64>(0, m_intervalMs - ms)));
    });
}

} // namespace stepcom
