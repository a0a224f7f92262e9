#pragma once

#include <QtGlobal>

namespace stepcom {

// Faults to rehearse with: shares are 0..1 of the requests the device would answer.
struct FaultOptions
{
    double drop = 0;       // executed, but the answer never leaves
    double corruptCrc = 0; // answered with a wrong CRC (RTU only)
    double late = 0;       // answered lateMs later than usual
    int lateMs = 0;
    double exception = 0; // not executed; answered with exceptionCode
    int exceptionCode = 4;
    int hangupAfter = 0;      // hang up after every N answered requests; 0 never
    int hangupPauseMs = 1000; // the port comes back after this pause
    quint32 seed = 1;

    bool any() const
    {
        return drop > 0 || corruptCrc > 0 || late > 0 || exception > 0 || hangupAfter > 0;
    }
};

} // namespace stepcom
