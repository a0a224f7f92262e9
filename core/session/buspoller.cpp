#include "session/buspoller.h"

#include "device/deviceclient.h"
#include "device/parameterstore.h"

#include <algorithm>

namespace stepcom {

BusPoller::BusPoller(ModbusLink *link, const RegisterMap &map, QObject *parent)
    : BusPoller(map, {}, parent)
{
    m_client = new DeviceClient(link, map, this);
    m_map = &m_client->map();
    m_read = [this](int id, const QList<const Parameter *> &params,
                    std::function<void(const ReadOutcome &)> done) {
        m_client->setUnitId(id); // one turn at a time: the id is this turn's until it ends
        m_client->read(params, Priority::Poll, std::move(done));
    };
}

BusPoller::BusPoller(const RegisterMap &map, Reader read, QObject *parent)
    : QObject(parent)
    , m_map(&map)
    , m_read(std::move(read))
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &BusPoller::turn);
}

void BusPoller::setDevices(const QList<int> &ids)
{
    m_ids = ids;
    m_next = 0;
    for (int id : ids)
        if (!m_status.contains(id))
            m_status.insert(id, BusDeviceStatus::of(id));
    if (m_active && !m_busy && !m_timer.isActive())
        arm();
}

void BusPoller::setIntervalMs(int ms)
{
    m_intervalMs = std::max(0, ms); // 0: each turn as the last one ends
}

int BusPoller::intervalMs() const
{
    // Rounds are what a command line asked for; the window's background never hogs the line.
    if (m_pacing == Pacing::Rounds || m_intervalMs == 0)
        return m_intervalMs;
    return std::max(50, m_intervalMs);
}

void BusPoller::start()
{
    m_active = true;
    if (!m_busy)
        arm();
}

void BusPoller::stop()
{
    m_active = false;
    m_busy = false;
    ++m_generation;
    m_timer.stop();
}

BusDeviceStatus BusPoller::status(int id) const
{
    return m_status.value(id, BusDeviceStatus::of(id));
}

void BusPoller::noteLiveCycle(int id, bool ok, const ParameterStore &store, const QString &error)
{
    BusDeviceStatus &s = m_status[id];
    s.id = id;
    ++s.cycles;
    if (ok) {
        s.state = BusDeviceStatus::State::Answering;
        for (const QString &key : std::as_const(m_keys))
            if (const auto raw = store.deviceValue(key))
                s.values.insert(key, *raw);
    } else {
        ++s.errors;
        s.state = BusDeviceStatus::State::NotAnswering;
        s.lastError = error;
    }
}

void BusPoller::arm()
{
    if (!m_active || m_ids.isEmpty())
        return;
    if (m_pacing == Pacing::Rounds) {
        const qint64 wait = m_next == 0 && m_round.isValid()
                                ? std::max<qint64>(0, m_intervalMs - m_round.elapsed())
                                : 0;
        m_timer.start(int(wait));
        return;
    }
    // Spread the turns so every device comes round once per interval.
    m_timer.start(intervalMs() / int(m_ids.size()));
}

void BusPoller::turn()
{
    if (!m_active || m_ids.isEmpty())
        return;
    if (m_next == 0)
        m_round.start();
    const int id = m_ids.at(m_next % m_ids.size());
    m_next = (m_next + 1) % int(m_ids.size());
    QList<const Parameter *> params;
    for (const QString &key : std::as_const(m_keys))
        if (const Parameter *p = m_map->find(key))
            params << p;
    m_busy = true;
    const quint64 generation = m_generation;
    m_read(id, params, [this, id, generation](const ReadOutcome &r) {
        if (generation != m_generation)
            return;
        m_busy = false;
        BusDeviceStatus &s = m_status[id];
        s.id = id;
        ++s.cycles;
        if (r.ok) {
            s.state = BusDeviceStatus::State::Answering;
            for (auto it = r.values.begin(); it != r.values.end(); ++it)
                s.values.insert(it.key(), it.value());
        } else {
            ++s.errors;
            s.state = BusDeviceStatus::State::NotAnswering;
            s.lastError = r.errors.value(0);
        }
        Q_EMIT statusChanged(id);
        arm();
    });
}

} // namespace stepcom
