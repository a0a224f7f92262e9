#pragma once

#include "benchtypes.h"

#include <QByteArray>

namespace stepcom {
class SimHost;
}

namespace stepcom::bench {

// (d): runs the real `stepcom` window offscreen, polling at full rate (STEPCOM_POLL_INTERVAL_MS
// = 0), and measures its CPU share of one core (utime + stime from /proc/<pid>/stat) and its
// peak resident memory (VmHWM). With a `host` the window connects to that simulator -- it runs
// in this process, so its cost is not the window's -- at `baud`, and motor 1 moves back and
// forth meanwhile so the plots and the fast poll path work too. Without one the window starts
// its built-in simulator (`--sim`), which then runs inside the measured process.
WindowResult measureWindow(const BenchConfig &config, SimHost *host, int baud);
// A line of /proc/<pid>/status in MB ("VmHWM:   81234 kB"); -1 when missing.
double statusMb(qint64 pid, const QByteArray &field);

} // namespace stepcom::bench
