#pragma once

#include <QList>
#include <QString>

#include <algorithm>

namespace stepcom::bench {

// How long to measure; --smoke makes every phase short and skips the verdicts.
struct BenchConfig
{
    int cycles = 50;        // (a) status cycles measured
    int readAlls = 5;       // (b) read-alls measured
    int estopRounds = 8;    // (c) emergency stops, and (g) for each number of controllers
    int busRounds = 10;     // (f) rounds over the three controllers
    bool bus = true;        // (f) and (g): several controllers on the line
    int windowSeconds = 10; // (d) CPU is averaged over this long
    bool smoke = false;
    bool traffic = true;       // (e) the Traffic dock with an hour of frames
    int trafficSeconds = 3600; // (e) how much polling it holds
    QString stepcomPath;       // the window binary for (d); empty: (d) skipped
    bool gaps = true;          // (i) a controller that refuses reads covering reserved registers
    bool firstStatus = true;   // (j) time to the first status after the port opened
    int firstStatusRuns = 10;  // (j) connects measured
};

struct Span
{
    double mean = 0;
    double min = 0;
    double max = 0;
    int count = 0;
    void add(double v)
    {
        min = count == 0 ? v : std::min(min, v);
        max = count == 0 ? v : std::max(max, v);
        mean = (mean * count + v) / (count + 1);
        ++count;
    }
};

struct WindowResult
{
    bool measured = false;
    QString note;           // why not measured, or what was measured
    double cpuPercent = 0;  // of one core, averaged over the measurement
    double peakRssMb = 0;   // VmHWM
    double pollsPerSec = 0; // requests the simulator answered, per second
    double seconds = 0;
};

// (e) the Traffic dock after an hour of polling at full rate
struct TrafficResult
{
    bool measured = false;
    int baud = 0;
    double framesPerSecond = 0; // the full polling rate fed
    int seconds = 0;
    qint64 kept = 0; // frames the view still holds at the end
    int capacity = 0;
    Span batchMs;           // one update of the view (a batch of frames, painted), view full
    double memoryMb = 0;    // resident memory the frames took
    double showPollsMs = 0; // ticking "Polls" over all of them
    double searchMs = 0;    // a search over all of them
    int rowsShown = 0;
};

// (h) a bus scan of ids 1-247 at one baud when nobody answers
struct ScanResult
{
    bool measured = false;
    QString error;
    int baud = 0;
    int ids = 0;
    int probeTimeoutMs = 0; // the fitted one
    double elapsedMs = 0;   // start to finished, opening the port included
    double limitMs = 0;     // ids x (request frame + 35 ms + answer frame): the wire's limit
    int found = 0;          // must be 0
};

struct BaudResult
{
    int baud = 0;
    int answerDelayMs = 35; // the simulated controller's answer time
    QString error;          // the measurement itself failed

    // (a) live status cycle at full rate
    double statusOptimumMs = 0;
    int statusOptimumReads = 0;
    Span cycleMs;
    double readsPerCycle = 0;
    int fastCycles = 0;

    // (b) read-all
    double readAllOptimumMs = 0;
    int readAllOptimumReads = 0;
    Span readAllMs;
    int readAllReads = 0; // requests on the wire per read-all (the most seen)

    // (c) emergency stop while polling at full rate
    double longestPollMs = 0; // the longest single poll transaction seen, dispatch to answer
    Span estopDispatchMs;     // request -> on its way to the wire
    Span estopStoppedMs;      // request -> the simulator's motor stopped
    bool estopAlwaysNext = true;
    double estopFrameMs = 0; // the E-STOP request's own time on the wire (8 + 3.5 characters)

    // (d) the window at full rate
    WindowResult window;
};

// (g) E-STOP to every controller of a line, polling at full rate
struct EstopAllResult
{
    int devices = 0;
    double longestPollMs = 0;  // the longest poll transaction seen, dispatch to answer
    double longestEstopMs = 0; // the longest E-STOP transaction seen, dispatch to answer
    double modelEstopMs = 0;   // one E-STOP transaction by the wire-time model
    double frameMs = 0;        // an E-STOP request's own time on the wire
    Span lastDispatchMs;       // request -> the last controller's E-STOP on its way to the wire
    Span allStoppedMs;         // request -> every simulated motor stopped
    bool inOrderNext = true;   // the E-STOPs were the next requests, in the order of the list
    bool allAcknowledged = true;
};

// (f) and (g): several controllers on one line
struct BusResult
{
    int baud = 0;
    QString error;
    int devices = 0;           // (f) controllers polled in turn
    double cycleOptimumMs = 0; // the sum of each one's status optimum
    int cycleOptimumReads = 0;
    Span roundMs;          // every controller's status read once, at full rate
    int readsPerRound = 0; // the most seen on the link
    QList<EstopAllResult> estops;
};

// (i) a controller that refuses reads covering reserved registers, once that was learnt: its
// status cycle and read-all against the wire-time model of the gap-free plans the client uses.
struct GapResult
{
    bool learnt = false; // the session's read limits say gaps are refused
    BaudResult r;        // (a) and (b) fields; the optima are those of the gap-free plans
};

// (j) from the port opened (`connected(true)`) to the first status cycle finished with the
// positions in the store
struct FirstStatusResult
{
    int baud = 0;
    QString error;
    Span ms;
    bool beforeReadAll = true; // the status came before any read-all request went out
};

} // namespace stepcom::bench
