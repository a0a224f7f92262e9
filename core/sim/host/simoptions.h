#pragma once

#include "map/registermap.h"
#include "sim/model/machinesettings.h"
#include "sim/model/simmachine.h"
#include "sim/serve/faultinjector.h"

#include <QHash>
#include <QHostAddress>
#include <QList>
#include <QString>

#include <optional>

#include <utility>

namespace stepcom {

// Everything SimHost::start() needs: transports, identity, timing, faults, the machine.
struct SimOptions
{
    RegisterMap map = RegisterMap::builtin();

    bool rtu = false;      // Modbus RTU on a pseudo-terminal (Unix only)
    QString linkPath;      // a symlink to the pty, optional
    bool checkBaud = true; // silence when the client's baud differs from register 40213
    // Modbus RTU on this serial port instead of a pty (every platform): a USB-RS485 adapter,
    // or one end of a virtual null-modem pair (com0com on Windows, socat on Unix). It runs
    // at the device's baud rate (register 40213), 8N1, and follows it when it changes.
    QString serialPort;

    // The adapter hears itself: every byte the client sends on the pty (or over RTU over TCP)
    // comes straight back to it, as on half-duplex USB-RS485 adapters without echo suppression.
    bool echo = false;

    // A line of this many pseudo-terminals (stepcom-sim --line N): every byte one program sends
    // on its pty reaches the others and the controller, as on RS-485, so a master and a
    // listener share the line. 0: one pty for one client. With --link PATH the ptys get the
    // links PATH.1 .. PATH.N.
    int line = 0;
    // The parties of the line (1 .. line) that hear their own bytes back (--line-echo): an
    // adapter without echo suppression on that end.
    QList<int> lineEcho;

    // Modbus RTU frames over plain TCP, as behind a transparent RS-485/Ethernet converter.
    bool rtuTcp = false;
    quint16 rtuTcpPort = 0; // 0: any free port, see SimHost::rtuTcpPort()

    bool tcp = false; // Modbus TCP
    QHostAddress tcpAddress = QHostAddress(QHostAddress::LocalHost);
    quint16 tcpPort = 0; // 0: any free port, see SimHost::tcpPort()

    // Reads covering a reserved (unlisted) register get exception 02 instead of 0: only the
    // manual's listed registers can be read (--refuse-gaps, alias --strict-reads).
    bool strictReads = false;
    // Listed parameters this firmware lacks (keys or register numbers such as 40112, as typed):
    // reads and writes covering them get exception 02. Resolved against the map at start.
    QStringList lacks;

    int deviceId = 0; // 1-255 overrides the saved id; 0 keeps it
    // Several controllers on the one port (an RS-485 line), one per entry, each with its own
    // registers, state and motion, answering only frames addressed to its id. A repeated id is a
    // collision: both controllers act and answer at once, and the client gets garbage.
    // Empty: one controller (deviceId). The n-th (n > 1) saves to statePath + "-n".
    QList<int> ids;
    QString statePath; // the "flash" file; empty: saved values live in memory only

    // The controller's answer time, from the request's end: -1 the map's (the manual's 35 ms);
    // 0 answers as fast as it can, as other firmware does (2-20 ms).
    int answerDelayMs = -1;
    // Coils by PLC number (96 = 00096) whose answer leaves this many ms later still, as firmware
    // that writes its flash before it answers (--slow-coil 96:800); the command acts at once.
    QHash<int, int> slowCoils;
    int wireBaud = 0; // >0: add the bytes' time on a line at this baud
    FaultOptions faults;

    bool manualClock = false;  // time only moves by SimDevice::advance() (tests)
    double travel = 200;       // travel of every axis, distance units
    double startPosition = 50; // where the carriages stand at power-up
    // The machine's mechanics (stepcom-sim --machine FILE, MachineFile::load()), applied to
    // every controller after travel and startPosition; unset: the ideal machine.
    std::optional<MachineSettings> machine;
    // stepcom-sim --truth-out FILE: where the program keeps SimDevice::truthJson() of the first
    // controller (TruthWriter); SimHost itself does not write it.
    QString truthOut;
    QList<std::pair<int, SimMachine::InputForce>> inputs; // inputs set at start
    // The 24 V supply of every controller switched off (ms after start, ms off): --power-cycle.
    // The start counts on the host's event loop, the time off on the device's clock.
    QList<std::pair<int, int>> powerCycles;
};

} // namespace stepcom
