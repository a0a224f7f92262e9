#pragma once

#include <QCoreApplication>
#include <QList>
#include <QSerialPort>
#include <QString>

namespace stepcom {

// Who holds a serial port: the lock file Qt and other programs leave (LCK..ttyUSB0 in
// /run/lock or /var/lock, the holder's process id inside) and every process with the port open
// in /proc/*/fd. A second program on a port gets Qt's "Permission error while locking the
// device", which reads as a permission problem; this names the program instead. Everything is
// read below SystemRoot, so tests work on a fixture tree.
class PortHolders
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::PortHolders)
public:
    struct Holder
    {
        qint64 pid = 0;
        QString program;   // its /proc/PID/comm; empty when not known
        QString lockFile;  // the lock file naming it ("/run/lock/LCK..ttyUSB0"); empty: none
        bool open = false; // it has the device open (/proc/PID/fd)
        bool operator==(const Holder &o) const = default;
    };

    // The lock file's name for `device` ("/dev/ttyUSB0"), as Qt names it: the path below /dev
    // with '/' as '_' ("LCK..ttyUSB0", "LCK..pts_5").
    static QString lockName(const QString &device);
    // Every live process that holds `port` (a path, a /dev/serial/by-id link or a name such as
    // ttyUSB0), this process left out; the lock file's first. `incomplete` is set when some
    // process's open files could not be looked into (another user's): a holder may be missing.
    static QList<Holder> holders(const QString &port, bool *incomplete = nullptr);
    // "/dev/ttyUSB0 is in use by another program (stepcomctl, process 4242)"; without a holder
    // known, "... by another program".
    static QString inUseMessage(const QString &port, const QList<Holder> &holders);
    // Why opening `port` failed, in words: in use (a lock, a busy device, a holder found),
    // else the port's own error text.
    static QString openFailure(const QString &port, QSerialPort::SerialPortError error,
                               const QString &errorString);
};

} // namespace stepcom
