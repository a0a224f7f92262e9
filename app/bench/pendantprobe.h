#pragma once

#include "benchreport.h"

#include <QList>
#include <QString>

namespace stepcom::bench {

// (n) the phone pendant on loopback: a WebSocket client as the page, a simulator with the
// wire-time model at `baud`. Per round: the page's jog message to the jog frame on the wire,
// its stop message to the stop frame, and (holds stopped) the last hold to the stop frame.
struct PendantResult
{
    int baud = 0;
    int answerDelayMs = 35; // the simulated controller's answer delay
    QString error;
    QList<double> pressMs;    // jog message -> motorN.forward frame
    QList<double> releaseMs;  // stop message -> motorN.stop frame
    QList<double> lastHoldMs; // last hold -> motorN.stop frame (the server's watchdog)
};

PendantResult measurePendant(int baud, int rounds, int answerDelayMs);
// Median and max of each against 50 ms, 50 ms and 350 ms (the max is judged); `judged` false:
// the same rows for information (a slow line, where the frame waits for the one in flight).
QList<Verdict> pendantVerdicts(const PendantResult &r, bool judged);

} // namespace stepcom::bench
