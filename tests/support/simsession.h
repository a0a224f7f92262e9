#pragma once

#include <QList>

namespace stepcom {
class DeviceSession;
class SimHost;
} // namespace stepcom

namespace stepcom::test {

// Hands the session the built-in simulator (stepcom_sim), as the programs with --sim do; does
// nothing when it has one.
void useBuiltinSimulator(DeviceSession &session);
// The same with several controllers on its one line, one per id (SimOptions::ids).
void useBuiltinSimulator(DeviceSession &session, const QList<int> &ids);
// The simulator the session started (null before useBuiltinSimulator()).
SimHost *simHost(const DeviceSession &session);

// The any-controller matrix: rows "2 ms at 9600" ... "35 ms at 38400" of the
// columns delayMs and baud, for a data function.
void addAnswerTimeRows();
// Starts `host` as a controller answering `delayMs` after a request on a wire modelled at
// `baud` (any baud it is asked at); false and a warning when it cannot.
bool startModelledController(SimHost &host, int delayMs, int baud);

// Connects the session to its built-in simulator and waits (up to 10 s) for the first
// read-all, which must succeed; a failure is recorded for the running test function.
void connectToSimulator(DeviceSession &session);

} // namespace stepcom::test
