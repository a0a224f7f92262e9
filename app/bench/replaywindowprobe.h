#pragma once

#include "benchreport.h"

#include <QList>
#include <QString>

namespace stepcom::bench {

// (m) the replay in the window: the synthetic log of (l) opened in the real window's replay
// mode (MainWindow offscreen, in a process of its own so its memory is the window's alone, with
// the Plots page in view and the docks shown): the time from File → Open session log to the
// first frame shown, seeks to moments spread over the log each until every view is updated and
// the window painted, and the process's peak memory.
struct ReplayWindowResult
{
    QString error;
    int seconds = 0;
    int hz = 0;
    qint64 bytes = 0;
    double firstFrameMs = 0;
    QList<double> seeksMs;
    double peakRssMb = 0;
    int trafficRows = 0; // the traffic view's rows at the last moment
    int tracePoints = 0; // the XY trace's points at the last moment
};

ReplayWindowResult measureReplayWindow(int seconds, int hz, int seeks);
QList<Verdict> replayWindowVerdicts(const ReplayWindowResult &r);

// The measured process (`stepcom-bench --replay-window-child LOG`): prints the result as one
// line of JSON; the exit code is 0 when it measured.
int runReplayWindowChild(const QString &logPath, int seeks);

} // namespace stepcom::bench
