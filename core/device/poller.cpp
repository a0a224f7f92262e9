#include "device/poller.h"

#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/parameterstore.h"

namespace stepcom {

namespace {

// A closed link fails every request at once: without a pause an interval of 0 would spin.
constexpr int kDisconnectedPauseMs = 250;

bool isRunningKey(const QString &key)
{
    return key.startsWith(QLatin1String("motor")) && key.endsWith(QLatin1String(".running"));
}

} // namespace

Poller::Poller(DeviceClient *client, ParameterStore *store, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_store(store)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &Poller::runCycle);
    for (const Parameter *coil : m_client->map().coils()) {
        if (coil->command == CommandClass::Motion)
            m_motionCoils.insert(coil->address);
    }
    connect(m_client->link(), &ModbusLink::finished, this,
            [this](quint64, const Request &request, const Result &result) {
                onLinkFinished(request, result);
            });
}

QStringList Poller::statusKeys(const RegisterMap &map)
{
    QStringList keys;
    for (const Parameter *p : map.inGroup(QStringLiteral("status")))
        keys << p->key;
    return keys;
}

QStringList Poller::motionKeys(const RegisterMap &map)
{
    QStringList keys;
    for (const QString &key : statusKeys(map)) {
        if (key.endsWith(QLatin1String(".position")) || isRunningKey(key))
            keys << key;
    }
    return keys;
}

void Poller::useStatusKeys()
{
    setKeys(statusKeys(m_client->map()));
    setFastKeys(motionKeys(m_client->map()));
}

int Poller::intervalFromEnvironment(int fallback)
{
    bool ok = false;
    const int ms = qEnvironmentVariableIntValue("STEPCOM_POLL_INTERVAL_MS", &ok);
    return ok && ms >= 0 ? ms : fallback;
}

void Poller::setKeys(const QStringList &keys)
{
    m_keys = keys;
    setFastKeys(m_fastKeys); // recompute the running keys
}

void Poller::setFastKeys(const QStringList &keys)
{
    m_fastKeys = keys;
    m_runningKeys.clear();
    for (const QString &key : m_keys + m_fastKeys) {
        if (isRunningKey(key) && !m_runningKeys.contains(key))
            m_runningKeys << key;
    }
}

void Poller::start()
{
    if (m_active)
        return;
    m_active = true;
    m_rate = 0.0;
    m_sinceLastStart.invalidate();
    // A request of a stopped cycle still out: the first cycle follows its answer.
    if (!m_inCycle && !m_outstanding)
        m_timer.start(0);
}

void Poller::stop()
{
    m_active = false;
    m_timer.stop();
    ++m_generation; // a cycle still on the wire reports into nothing
    m_inCycle = false;
}

QList<const Parameter *> Poller::resolve(const QStringList &keys) const
{
    QList<const Parameter *> params;
    for (const QString &key : keys) {
        if (const Parameter *p = m_client->map().find(key); p && p->readable())
            params << p;
    }
    return params;
}

bool Poller::anyRunning() const
{
    return std::any_of(m_runningKeys.cbegin(), m_runningKeys.cend(), [this](const QString &key) {
        return m_store->deviceValue(key).value_or(0);
    });
}

void Poller::onLinkFinished(const Request &request, const Result &result)
{
    // A motion command was acknowledged: poll fast at once rather than a full cycle later.
    if (result.ok && request.type == Request::Type::WriteCoil && request.coilOn &&
        m_motionCoils.contains(request.address))
        m_motionHint = true;
}

void Poller::runCycle()
{
    if (!m_active || m_inCycle || m_outstanding)
        return;
    const bool fast = !m_fastKeys.isEmpty() && m_fullEvery > 1 && (m_motionHint || anyRunning());
    m_motionHint = false;
    if (fast != m_fast) {
        m_fast = fast;
        m_fastStreak = 0;
        Q_EMIT fastChanged(fast);
    }
    // The first cycle of a run is fast; then fullEvery - 1 fast ones per full one.
    const bool full = !fast || m_fastStreak >= m_fullEvery - 1;
    m_fastStreak = full ? 0 : m_fastStreak + 1;
    m_cycleParams = resolve(full ? m_keys : m_fastKeys);
    m_cycleBlocks = m_client->planRead(m_cycleParams);
    if (m_cycleBlocks.isEmpty())
        return;
    m_inCycle = true;
    m_cycleFull = full;
    m_cycleOk = true;
    m_cycleValues.clear();
    if (m_sinceLastStart.isValid()) {
        // achieved rate: start to start, including any wait for the interval
        const double instant = 1000.0 / double(std::max<qint64>(m_sinceLastStart.elapsed(), 1));
        m_rate = m_rate <= 0.0 ? instant : 0.8 * m_rate + 0.2 * instant;
    }
    m_sinceLastStart.start();
    m_cycleClock.start();
    readBlock(0);
}

void Poller::readBlock(int index)
{
    const ReadBlock &block = m_cycleBlocks.at(index);
    Request request = Request::read(block.address, block.count, Priority::Poll);
    // Name what the block reads, so a failing poll says which values are missing.
    QStringList names;
    for (const Parameter *p : std::as_const(m_cycleParams)) {
        if (p->address >= block.address && p->address <= block.lastAddress())
            names << p->key;
    }
    if (names.size() > 4)
        names = names.mid(0, 3) << tr("… %n in all", nullptr, int(names.size()));
    request.what = tr("poll %1/%2 (%3)")
                       .arg(index + 1)
                       .arg(m_cycleBlocks.size())
                       .arg(names.join(QStringLiteral(", ")));
    const quint64 generation = m_generation;
    m_outstanding = true;
    m_client->submit(
        request, [this, generation, index](const Result &r) { onBlockRead(generation, index, r); },
        this);
}

void Poller::onBlockRead(quint64 generation, int index, const Result &result)
{
    m_outstanding = false;
    if (generation != m_generation) {
        if (m_active && !m_inCycle) // restarted while this request was out
            m_timer.start(0);
        return;
    }
    const ReadBlock block = m_cycleBlocks.at(index);
    if (result.ok && result.values.size() == block.count) {
        for (const Parameter *p : std::as_const(m_cycleParams)) {
            if (p->address >= block.address && p->lastAddress() <= block.lastAddress())
                m_cycleValues.insert(
                    p->key, p->decode(result.values.constData() + (p->address - block.address)));
        }
    } else if (m_client->noteRefused(block, result) != ReadLimits::Lesson::None) {
        // The controller lacks something this block covered: read its parameters again
        // within what it accepts, in this same cycle.
        QList<const Parameter *> inside;
        for (const Parameter *p : std::as_const(m_cycleParams)) {
            if (p->address >= block.address && p->lastAddress() <= block.lastAddress())
                inside << p;
        }
        const QList<ReadBlock> again = m_client->planRead(inside);
        for (qsizetype i = 0; i < again.size(); ++i)
            m_cycleBlocks.insert(index + 1 + i, again.at(i));
    } else {
        m_cycleOk = false;
        m_lastError = result.errorText;
    }
    if (index + 1 < m_cycleBlocks.size())
        readBlock(index + 1);
    else
        finishCycle();
}

void Poller::finishCycle()
{
    m_inCycle = false;
    const qint64 ms = m_cycleClock.elapsed();
    if (!m_cycleValues.isEmpty())
        m_store->setDeviceValues(m_cycleValues);
    ++m_stats.cycles;
    if (!m_cycleOk)
        ++m_stats.failed;
    if (!m_cycleFull)
        ++m_stats.fastCycles;
    m_stats.lastMs = ms;
    m_stats.minMs = m_stats.minMs < 0 ? ms : std::min(m_stats.minMs, ms);
    m_stats.maxMs = std::max(m_stats.maxMs, ms);
    m_stats.totalMs += ms;
    Q_EMIT cycleFinished(m_cycleOk, ms);
    if (!m_active || m_inCycle) // stopped, or restarted from a slot of cycleFinished
        return;
    // The next cycle only after this one, and not before the interval.
    qint64 delay = std::max<qint64>(0, m_intervalMs - ms);
    if (!m_client->link()->isConnected())
        delay = std::max<qint64>(delay, kDisconnectedPauseMs);
    m_timer.start(int(delay));
}

} // namespace stepcom
