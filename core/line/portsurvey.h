#pragma once

#include "session/serialports.h" // SerialPortEntry

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace stepcom {

// Every serial port of this computer as a technician needs it before the first connection:
// its stable /dev/serial/by-id name, the adapter's vendor, product and serial number
// (SerialAdapter), and whether another program holds it -- a lock file naming a living process,
// or a process with the device open (PortHolders). Everything is read below SystemRoot, so
// tests hand in a fake system. Without sysfs (Windows, macOS) the ports are Qt's list, their
// holders unknown.
class PortSurvey
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::PortSurvey)

public:
    struct Holder
    {
        qint64 pid = 0;
        QString program; // /proc/PID/comm; empty when it cannot be read
        QString how;     // "lock file /run/lock/LCK..ttyUSB0" or "has it open"
    };
    struct Port
    {
        SerialPortEntry entry;
        QString driver;        // "ftdi_sio", "cp210x", "ch341-uart"
        QList<Holder> holders; // other programs using it (this one left out)
        // /proc of some processes could not be read (another user's): holders may be missing.
        bool holdersIncomplete = false;
        // Nothing could be looked at (no /proc, no lock folders): held or not is unknown.
        bool holdersKnown = true;
        bool accessible = true; // read and write permission for this user
    };

    // Where the system is read (SystemRoot): "" (the default) is this computer; else a folder
    // with sys/, dev/, proc/, run/lock/. For the front-ends, which include no bus/ header.
    static void setSystemRoot(const QString &root);

    // The ports, sorted by their device path.
    static QList<Port> ports();
    // Who holds the device at `devicePath` ("/dev/ttyUSB0"), this process left out.
    static QList<Holder> holders(const QString &devicePath, bool *incomplete = nullptr);
    // "held by minicom (pid 1234, lock file ...)" or "free".
    static QString holdersText(const Port &port);
};

} // namespace stepcom
