#pragma once

#include "sim/serve/faultinjector.h"

#include <QHash>
#include <QList>
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
        bool collision = false; // two or more controllers answered at once: garbage on the wire
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
        std::atomic<int> collisions{0};
    };

    // `devices`: every controller on the line (at least one), in their order.
    SimResponder(QList<SimDevice *> devices, int answerDelayMs, int wireBaud,
                 const FaultOptions &faults);

    // Coils (by PLC number, 1 = 00001) whose answer leaves this many ms later than others',
    // as firmware that writes its flash before it answers: the command acts at once.
    void setSlowCoils(const QHash<int, int> &msByPlc) { m_slowCoils = msByPlc; }

    // A request addressed to `unit`: every controller with that id acts on it; none is silence,
    // two or more answer at once (a collision). Unit 0 (broadcast) is acted on by all, unanswered.
    Outcome respond(int unit, const QModbusRequest &request);
    // The bytes of an RTU request and answer plus 7 characters of silence at `baud`,
    // 10 bits a byte, in whole milliseconds rounded up.
    static int wireTimeMs(int requestPduBytes, int answerPduBytes, int baud);

    // The first controller on the line.
    SimDevice *device() const { return m_devices.first(); }
    const QList<SimDevice *> &devices() const { return m_devices; }
    // The powered controllers that currently have this id (more than one: a collision); one
    // switched off hears nothing.
    QList<SimDevice *> devicesAt(int unit) const;
    bool hasDevice(int unit) const { return !devicesAt(unit).isEmpty(); }
    Counters &counters() { return m_counters; }

private:
    // The controller's own time to answer this request: the answer delay, and a slow coil's.
    int answerDelayMs(const QModbusRequest &request) const;

    QList<SimDevice *> m_devices;
    int m_answerDelayMs;
    int m_wireBaud;
    QHash<int, int> m_slowCoils;
    FaultInjector m_faults;
    Counters m_counters;
};

} // namespace stepcom
