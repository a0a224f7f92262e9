#pragma once

#include "benchtypes.h"

namespace stepcom::bench {

// (j) time to first status: a fresh session connects `runs` times to a simulator with the
// wire-time model at `baud`; each run is timed from the port opened (`connected(true)`) to the
// first status cycle finished with every axis' position in the store.
FirstStatusResult measureFirstStatus(int baud, int runs);

} // namespace stepcom::bench
