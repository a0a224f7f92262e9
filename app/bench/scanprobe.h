#pragma once

#include "benchtypes.h"

namespace stepcom::bench {

// (h) the bus scan when nobody answers: ids 1-247 at `baud` over real Modbus RTU on a
// pseudo-terminal (the simulator's only controller sits at id 250), with the BusScanner that
// `stepcomctl scan` and the scan dialog run and its fitted probe timeout.
ScanResult measureScan(int baud);

} // namespace stepcom::bench
