#pragma once

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QString>

#include <functional>

namespace stepcom {

// Who may talk to the pendant: the pairing token (128 random bits from the system's generator,
// new at every start) and the addresses refused after guessing. Ten wrong tokens from one
// address within a minute refuse that address for a minute, right token or not, so a token
// cannot be guessed from the Wi-Fi. The clock is injectable for the tests.
class PendantGate
{
public:
    static constexpr int kWrongLimit = 10;
    static constexpr qint64 kWindowMs = 60'000;
    static constexpr qint64 kRefusedMs = 60'000;

    using Clock = std::function<qint64()>; // milliseconds, steady
    explicit PendantGate(Clock clock = {});

    // A new token (32 hex digits); every address forgiven.
    void renew();
    QString token() const { return m_token; }
    // Whether `token` is the token (compared in constant time). A wrong one counts against
    // `address`; a refused address is never let in.
    bool admit(const QString &address, const QString &token);
    bool isRefused(const QString &address) const;

private:
    qint64 now() const;

    Clock m_clock;
    QString m_token;
    QHash<QString, QList<qint64>> m_wrong; // when each wrong token came, the last minute's
    QHash<QString, qint64> m_refusedUntil;
};

} // namespace stepcom
