#pragma once

#include "sim/faultinjector.h"

#include <QModbusPdu>

#include <atomic>

namespace stepcom {

class SimDevice;

// Between a transport and the device: applies the faults and works out when the answer may
// leave (the controller's answer delay plus, optionally, the bytes' time on the wire).
// Lives in the simulator's thread; the counters may be read from anywhere.
class SimResponder
{
public:
    struct Outcome
    {
        QModbusResponse response; // invalid: say nothing
        int delayMs = 0;          // after the request arrived
        bool corruptCrc = false;
        bool hangUp = false;
        bool linkChanged = false;
    };
    struct Counters
    {
        std::atomic<int> requests{0};
        std::atomic<int> answers{0};
        std::atomic<int> exceptions{0};
        std::atomic<int> dropped{0};
        std::atomic<int> corrupted{0};
        std::atomic<int> late{0};
        std::atomic<int> wrongBaud{0};
    };

    SimResponder(SimDevice *device, int answerDelayMs, int wireBaud, const FaultOptions &faults);

    Outcome respond(const QModbusRequest &request);
    // The bytes of an RTU request and answer plus 7 characters of silence at `baud`,
    // 10 bits a byte, in whole milliseconds rounded up.
    static int wireTimeMs(int requestPduBytes, int answerPduBytes, int baud);

    SimDevice *device() const { return m_device; }
    Counters &counters() { return m_counters; }

private:
    SimDevice *m_device;
    int m_answerDelayMs;
    int m_wireBaud;
    FaultInjector m_faults;
    Counters m_counters;
};

} // namespace stepcom
