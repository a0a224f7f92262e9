#pragma once

#include "bus/linksettings.h"
#include "bus/serialadapter.h"

#include <QCoreApplication>
#include <QString>

namespace stepcom {

// What StepCom asks of a serial port's driver once it is open, on its file descriptor: low
// latency (ASYNC_LOW_LATENCY through TIOCSSERIAL, which needs no root: an FTDI adapter's
// latency timer goes to 1 ms) and the RS-485 direction (TIOCSRS485 for the kernel's mode; RTS
// low while receiving for StepCom's own switching). A refusal comes back as a message naming
// the driver and what to try; the caller sends nothing then.
class PortSetup
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::PortSetup)
public:
    // Empty when the driver took it; else why not.
    static QString requestLowLatency(int fd);
    // Sets `mode` on `fd`; empty when set, else a message naming the port, the driver
    // (`adapter`) and the option to try instead.
    static QString applyRs485(int fd, const LinkSettings &settings, const SerialAdapter &adapter);
    // Waits until the last byte written to `fd` has left the UART (tcdrain), then lets RTS
    // fall: the request is out, the answer may come.
    static void endOfSend(int fd);
    // RTS up (true) or down on `fd`; false when the driver refused.
    static bool setRts(int fd, bool on);
};

} // namespace stepcom
