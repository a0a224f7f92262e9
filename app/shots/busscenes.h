#pragma once

namespace stepcom {
class Shooter;
}

// Scenes of a line of several controllers: the device list with three of them.
namespace stepcom::busscenes {

void deviceList(Shooter &s);

} // namespace stepcom::busscenes
