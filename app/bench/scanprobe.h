#pragma once

#include "benchtypes.h"

namespace stepcom::bench {

// (h) the bus scan when nobody answers: ids 1-`ids` at `baud` over real Modbus RTU on a
// pseudo-terminal (the simulator's only controller sits at id 250), with the BusScanner that
// `stepcomctl scan` and the scan dialog run and its fitted probe timeout. 247 ids show the
// cost of each probe; 40 the wait after the last one as well.
ScanResult measureScan(int baud, int ids = 247);

} // namespace stepcom::bench
