#pragma once

#include "benchtypes.h"

namespace stepcom::bench {

// (e): the Traffic dock holding an hour of polling at full rate. Feeds `framesPerSecond` ×
// `seconds` real poll frames (TrafficLog::addFrame, as the link logs them) into a shown
// TrafficView in batches of one update interval, and measures the time of each update with
// the view painted, the memory the frames take, and how long a filter change over all of them
// takes. Needs a QApplication (offscreen is fine).
// The frames are those of the live status plan at `baud`.
TrafficResult measureTrafficView(int baud, double framesPerSecond, int seconds);

} // namespace stepcom::bench
