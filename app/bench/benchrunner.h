#pragma once

#include "benchtypes.h"

#include <functional>

namespace stepcom::bench {

// Runs until `done` holds or `timeoutMs` passed, serving events meanwhile. The benchmark is a
// script told top to bottom, not product code: a local event loop keeps it readable.
bool waitUntil(const std::function<bool()> &done, int timeoutMs);

// Measures (a) to (d) against a simulator with the wire-time model at `baud`, over real
// Modbus RTU on a pseudo-terminal, with StepCom's own DeviceSession and Poller.
// (a)-(d) at `baud`; `answerDelayMs` >= 0: a controller answering that soon instead of the
// manual's 35 ms, and with `cyclesOnly` only (a) and (b) (row (k)).
BaudResult measureBaud(int baud, const BenchConfig &config, int answerDelayMs = -1,
                       bool cyclesOnly = false);

// Measures (i): (a) and (b) against a simulator that refuses reads covering reserved
// registers, after the session learnt it, held against the gap-free plans it then makes.
GapResult measureGapRefusing(int baud, const BenchConfig &config);

} // namespace stepcom::bench
