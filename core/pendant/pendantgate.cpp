#include "pendant/pendantgate.h"

#include <QElapsedTimer>
#include <QRandomGenerator>

namespace stepcom {

namespace {

qint64 steadyMs()
{
    static QElapsedTimer clock = [] {
        QElapsedTimer t;
        t.start();
        return t;
    }();
    return clock.elapsed();
}

} // namespace

PendantGate::PendantGate(Clock clock)
    : m_clock(std::move(clock))
{
    renew();
}

qint64 PendantGate::now() const
{
    return m_clock ? m_clock() : steadyMs();
}

void PendantGate::renew()
{
    quint32 words[4];
    QRandomGenerator::system()->fillRange(words);
    QByteArray bytes(reinterpret_cast<const char *>(words), sizeof(words));
    m_token = QString::fromLatin1(bytes.toHex());
    m_wrong.clear();
    m_refusedUntil.clear();
}

bool PendantGate::isRefused(const QString &address) const
{
    const auto it = m_refusedUntil.constFind(address);
    return it != m_refusedUntil.cend() && now() < *it;
}

bool PendantGate::admit(const QString &address, const QString &token)
{
    if (isRefused(address))
        return false;
    // Constant time: how much of a guess was right must not show in the answer's time.
    const QByteArray a = token.toLatin1();
    const QByteArray b = m_token.toLatin1();
    unsigned diff = a.size() == b.size() ? 0u : 1u;
    for (qsizetype i = 0; i < b.size(); ++i)
        diff |= unsigned(quint8(b.at(i)) ^ quint8(i < a.size() ? a.at(i) : 0));
    if (diff == 0)
        return true;
    const qint64 t = now();
    QList<qint64> &times = m_wrong[address];
    times.removeIf([t](qint64 at) { return t - at >= kWindowMs; });
    times << t;
    if (times.size() >= kWrongLimit) {
        m_refusedUntil.insert(address, t + kRefusedMs);
        times.clear();
    }
    return false;
}

} // namespace stepcom
