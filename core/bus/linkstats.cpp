#include "bus/linkstats.h"

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

} // namespace stepcom
