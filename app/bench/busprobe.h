#pragma once

#include "benchtypes.h"

namespace stepcom::bench {

// (f) the status of three controllers on one line read in turn at full rate (BusPoller), and
// (g) the E-STOP to every controller of a line of 2, 3 and 8 while polling at full rate, over
// real Modbus RTU on a pseudo-terminal against the simulator's wire-time model at `baud`.
BusResult measureBus(int baud, const BenchConfig &config);

} // namespace stepcom::bench
