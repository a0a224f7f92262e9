#pragma once

#include "session/serialports.h" // SerialPortEntry

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace stepcom {

// Every serial port of this computer as a technician needs it before the first connection:
// its stable /dev/serial/by-id name, the adapter's vendor, product and serial number (from
// sysfs, as QSerialPortInfo reads them), and whether another program holds it -- a UUCP lock
// file (/run/lock/LCK..ttyUSB0, /var/lock) naming a living process, or a process with the device
// open (/proc/PID/fd). Everything is read under a root folder, so tests hand in a fake system.
// Without sysfs (Windows, macOS) the ports are Qt's list, their holders unknown.
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

    // `root`: "" (the default) is this system; else a folder with sys/, dev/, proc/, run/lock/.
    explicit PortSurvey(const QString &root = QString());

    // The ports, sorted by their device path.
    QList<Port> ports() const;
    // Who holds the device at `devicePath` ("/dev/ttyUSB0"), this process left out.
    QList<Holder> holders(const QString &devicePath, bool *incomplete = nullptr) const;
    // "held by minicom (pid 1234, lock file ...)" or "free".
    static QString holdersText(const Port &port);

    // The process to leave out of the holders (this program's own).
    void setOwnPid(qint64 pid) { m_ownPid = pid; }

private:
    QString path(const QString &absolute) const { return m_root + absolute; }
    QString programOf(qint64 pid) const;
    void readAdapter(const QString &ttyName, Port *port) const;

    QString m_root;
    qint64 m_ownPid = 0;
};

} // namespace stepcom
