#pragma once

namespace stepcom {

class Shooter;

// Scenes of working without the machine; they run with no controller connected.
namespace offlinescenes {

// A profile file edited on a motor page: the banner, the title, the blue status bar.
void editing(Shooter &s);
// File → Compare profiles: two files row by row, the differing rows highlighted.
void compareFiles(Shooter &s);
// File → Open session log…: a session recorded against the simulator (a write, a
// move), replayed at a moment of the move: the banner, the replay bar with its markers; then
// at its end on the Plots page with the device list open (scene-replay-plots).
void replay(Shooter &s);

} // namespace offlinescenes
} // namespace stepcom
