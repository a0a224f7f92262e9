#pragma once

#include "bus/answertimefit.h"

#include <QList>
#include <QMap>
#include <QString>

namespace stepcom {

// Measured round trips (request sent to answer complete) of one controller, or of the line.
struct RoundTrips
{
    // The median is taken over this many of the latest round trips.
    static constexpr int kWindow = 32;
    QList<qint64> recent; // the latest, oldest first
    quint64 count = 0;
    qint64 min = -1;
    qint64 max = -1;

    void add(qint64 ms);
    qint64 median() const; // -1 with none measured
    // "4-6 ms (median 5 ms)"; empty with none measured.
    QString text() const;
};

// Counters of one link since it was opened (or reset).
struct LinkStats
{
    quint64 requests = 0; // attempts put on the wire
    quint64 answers = 0;  // valid answers (including exception answers)
    quint64 timeouts = 0;
    quint64 crcErrors = 0;
    quint64 mismatches = 0; // answers that did not fit the request (wrong count, wrong function)
    quint64 exceptions = 0;
    quint64 stale = 0; // stale/foreign answers discarded (late, another device, wrong content)
    // What the line showed of the adapter's echo: -1 not known yet, 0 none, 1 it echoes.
    int echo = -1;
    QMap<int, quint64> exceptionsByCode;
    quint64 failed = 0; // transactions that ended in an error after all retries
    quint64 bytesSent = 0;
    quint64 bytesReceived = 0;
    qint64 lastRoundTripMs = -1;
    qint64 minRoundTripMs = -1;
    qint64 maxRoundTripMs = -1;
    double meanRoundTripMs = 0.0;
    RoundTrips roundTrips;                // every controller on the line
    QMap<int, RoundTrips> byUnit;         // per device id
    QMap<int, AnswerTimeFit> answerTimes; // per device id: its own time, apart from the wire
    int timeoutMs = -1;                   // the answer timeout the link uses now (-1 not yet known)
    QString adapter; // the adapter behind the line ("FTDI FT232R, latency timer 1 ms"), if known

    // `characters`: the request's and the answer's on the wire with the silence between them
    // (0: not known).
    void addRoundTrip(qint64 ms, int unit = 0, int characters = 0);
    quint64 errors() const { return timeouts + crcErrors + mismatches + exceptions + stale; }
    // An answer timeout that fits the round trips measured so far (the slowest with half
    // again plus 50 ms, in steps of 50 ms, at least 100 ms); -1 until 5 answers were timed.
    int suggestedTimeoutMs() const;
    // What the line showed, in one line: "answers in 4-6 ms (median 5 ms), no echo, timeout
    // 60 ms"; `unit` > 0: that controller's round trips.
    QString lineText(int unit = 0) const;
    // One line for a log or a terminal: the counts, the round trips and, once known, the
    // suggested timeout against `timeoutMs` (the one set).
    QString summary(int timeoutMs) const;
};

} // namespace stepcom
