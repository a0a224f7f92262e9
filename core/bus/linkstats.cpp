#include "bus/linkstats.h"

#include <QCoreApplication>

#include <algorithm>

namespace stepcom {

void LinkStats::addRoundTrip(qint64 ms)
{
    lastRoundTripMs = ms;
    minRoundTripMs = minRoundTripMs < 0 ? ms : std::min(minRoundTripMs, ms);
    maxRoundTripMs = std::max(maxRoundTripMs, ms);
    // answers has already been counted for this round trip
    const double n = double(std::max<quint64>(answers, 1));
    meanRoundTripMs += (double(ms) - meanRoundTripMs) / n;
}

int LinkStats::suggestedTimeoutMs() const
{
    if (answers < 5 || maxRoundTripMs < 0)
        return -1;
    const qint64 raw = maxRoundTripMs * 3 / 2 + 50;
    return int(std::max<qint64>(100, (raw + 49) / 50 * 50));
}

QString LinkStats::summary(int timeoutMs) const
{
    const auto tr = [](const char *text) {
        return QCoreApplication::translate("stepcom::LinkStats", text);
    };
    QString text = tr("%1 requests, %2 answers; %3 timeouts, %4 CRC errors, %5 exceptions, "
                      "%6 stale or foreign answers discarded, %7 echoes")
                       .arg(requests)
                       .arg(answers)
                       .arg(timeouts)
                       .arg(crcErrors)
                       .arg(exceptions)
                       .arg(stale)
                       .arg(echoes);
    if (minRoundTripMs >= 0)
        text += tr("; round trips %1-%2 ms (mean %3 ms)")
                    .arg(minRoundTripMs)
                    .arg(maxRoundTripMs)
                    .arg(meanRoundTripMs, 0, 'f', 1);
    if (const int suggested = suggestedTimeoutMs(); suggested > 0)
        text += tr("; suggested timeout %1 ms (now %2 ms)").arg(suggested).arg(timeoutMs);
    return text;
}

} // namespace stepcom
