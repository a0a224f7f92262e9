#pragma once

namespace stepcom {

class Shooter;

// The Sequence page: the guide's picture of a run-in under way.
namespace sequencescenes {

// A pick-and-place cycle for motor 1 (home, then load and unload points with the part sensor
// IN3 held ON by the simulator), run for 5 cycles and shot on the first cycle's way back; the run
// is stopped and the input let go afterwards.
void running(Shooter &s);

} // namespace sequencescenes
} // namespace stepcom
