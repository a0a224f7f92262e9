#pragma once

#include "benchreport.h"

#include <QList>
#include <QString>

namespace stepcom::bench {

// (l) replay: a synthetic session log of `seconds` of status polling at `hz` (two reads a
// cycle, a write every minute, a timeout and an E-STOP now and then), opened with ReplayLog:
// the time to the first state shown (open + stateAt(0)), seeks to moments spread over the log,
// and the memory it takes (resident growth; the process's VmHWM).
struct ReplayResult
{
    QString error;
    int seconds = 0;
    int hz = 0;
    qint64 bytes = 0;
    qint64 lines = 0;
    double firstStateMs = 0;
    double seekMeanMs = 0;
    double seekMaxMs = 0;
    int seeks = 0;
    int snapshots = 0;
    qint64 events = 0;
    double residentGrowthMb = 0;
    double peakRssMb = 0;
};

// The synthetic log of (l) and (m): `seconds` of polling at `hz` as the session log writes it
// (motor 1 and 2 moving all the while), streamed to `path`, never held whole.
bool writeReplayLog(const QString &path, int seconds, int hz, QString *error);
ReplayResult measureReplay(int seconds, int hz);
QList<Verdict> replayVerdicts(const ReplayResult &r);

} // namespace stepcom::bench
