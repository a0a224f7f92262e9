#pragma once

namespace stepcom {

class Shooter;

// The Jog page's game pad: the guide's picture of a pad connected and jogging.
namespace padscenes {

// SDL's virtual pad attached and the Jog page's "Jog with a game pad" ticked; the dead-man held
// and the stick to the right, shot while motor 1 jogs; the pad let go, detached and the box
// unticked afterwards.
void jogging(Shooter &s);

} // namespace padscenes
} // namespace stepcom
