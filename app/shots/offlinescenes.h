#pragma once

namespace stepcom {

class Shooter;

// Scenes of working without the machine (issue 18); they run with no controller connected.
namespace offlinescenes {

// A profile file edited on a motor page: the banner, the title, the blue status bar.
void editing(Shooter &s);
// File → Compare profiles: two files row by row, the differing rows highlighted.
void compareFiles(Shooter &s);

} // namespace offlinescenes
} // namespace stepcom
