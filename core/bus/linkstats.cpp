#include "bus/linkstats.h"

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

} // namespace stepcom
