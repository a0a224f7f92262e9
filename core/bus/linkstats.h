#pragma once

#include <QMap>

namespace stepcom {

// Counters of one link since it was opened (or reset).
struct LinkStats
{
    quint64 requests = 0; // attempts put on the wire
    quint64 answers = 0;  // valid answers (including exception answers)
    quint64 timeouts = 0;
    quint64 crcErrors = 0;
    quint64 mismatches = 0; // answers that did not fit the request (wrong count, wrong function)
    quint64 exceptions = 0;
    QMap<int, quint64> exceptionsByCode;
    quint64 failed = 0; // transactions that ended in an error after all retries
    quint64 bytesSent = 0;
    quint64 bytesReceived = 0;
    qint64 lastRoundTripMs = -1;
    qint64 minRoundTripMs = -1;
    qint64 maxRoundTripMs = -1;
    double meanRoundTripMs = 0.0;

    void addRoundTrip(qint64 ms);
    quint64 errors() const { return timeouts + crcErrors + mismatches + exceptions; }
};

} // namespace stepcom
