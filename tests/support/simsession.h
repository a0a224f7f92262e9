#pragma once

namespace stepcom {
class DeviceSession;
}

namespace stepcom::test {

// Connects the session to its built-in simulator and waits (up to 10 s) for the first
// read-all, which must succeed; a failure is recorded for the running test function.
void connectToSimulator(DeviceSession &session);

} // namespace stepcom::test
