#pragma once

#include <QCoreApplication>
#include <QList>
#include <QSerialPort>
#include <QString>

namespace stepcom {

// Who holds a serial port: the lock file Qt and other programs leave (LCK..ttyUSB0 in
// /run/lock or /var/lock, the holder's process id inside) and every process with the port open
// in /proc/*/fd. A second program on a port gets Qt's "Permission error while locking the
// device", which reads as a permission problem; this names the program instead. The roots are
// injectable, so tests work on a fixture tree.
class PortHolders
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::PortHolders)
public:
    struct Holder
    {
        qint64 pid = 0;
        QString program; // its /proc/PID/comm; empty when not known
        bool operator==(const Holder &o) const { return pid == o.pid && program == o.program; }
    };

    // Defaults: {"/run/lock", "/var/lock"} and "/proc". Empty list / string: the defaults.
    static void setRoots(const QStringList &lockDirs, const QString &procRoot);
    // Every live process that holds `port` (a path or a /dev/serial/by-id link), this process
    // left out; the lock file's first.
    static QList<Holder> holders(const QString &port);
    // "/dev/ttyUSB0 is in use by another program (stepcomctl, process 4242)"; without a holder
    // known, "... by another program".
    static QString inUseMessage(const QString &port, const QList<Holder> &holders);
    // Why opening `port` failed, in words: in use (a lock, a busy device, a holder found),
    // else the port's own error text.
    static QString openFailure(const QString &port, QSerialPort::SerialPortError error,
                               const QString &errorString);
};

} // namespace stepcom
