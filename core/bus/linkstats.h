#pragma once

#include <QMap>
#include <QString>

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
    quint64 stale = 0;  // stale/foreign answers discarded (late, another device, wrong content)
    quint64 echoes = 0; // the request's own bytes came back and the echo option was off
    QMap<int, quint64> exceptionsByCode;
    quint64 failed = 0; // transactions that ended in an error after all retries
    quint64 bytesSent = 0;
    quint64 bytesReceived = 0;
    qint64 lastRoundTripMs = -1;
    qint64 minRoundTripMs = -1;
    qint64 maxRoundTripMs = -1;
    double meanRoundTripMs = 0.0;

    void addRoundTrip(qint64 ms);
    quint64 errors() const
    {
        return timeouts + crcErrors + mismatches + exceptions + stale + echoes;
    }
    // An answer timeout that fits the round trips measured so far (the slowest with half
    // again plus 50 ms, in steps of 50 ms, at least 100 ms); -1 until 5 answers were timed.
    int suggestedTimeoutMs() const;
    // One line for a log or a terminal: the counts, the round trips and, once known, the
    // suggested timeout against `timeoutMs` (the one in use).
    QString summary(int timeoutMs) const;
};

} // namespace stepcom
