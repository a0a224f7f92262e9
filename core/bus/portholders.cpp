#include "bus/portholders.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace stepcom {

namespace {

struct Roots
{
    QStringList lockDirs{QStringLiteral("/run/lock"), QStringLiteral("/var/lock")};
    QString proc = QStringLiteral("/proc");
};

Roots &roots()
{
    static Roots r;
    return r;
}

QString programOf(qint64 pid)
{
    QFile comm(QStringLiteral("%1/%2/comm").arg(roots().proc).arg(pid));
    if (!comm.open(QIODevice::ReadOnly))
        return {};
    return QString::fromLocal8Bit(comm.readAll()).trimmed();
}

bool alive(qint64 pid)
{
    return QFileInfo::exists(QStringLiteral("%1/%2").arg(roots().proc).arg(pid));
}

// The real device behind a by-id link or a relative path.
QString deviceOf(const QString &port)
{
    const QString canonical = QFileInfo(port).canonicalFilePath();
    return canonical.isEmpty() ? port : canonical;
}

} // namespace

void PortHolders::setRoots(const QStringList &lockDirs, const QString &procRoot)
{
    roots() = Roots{};
    if (!lockDirs.isEmpty())
        roots().lockDirs = lockDirs;
    if (!procRoot.isEmpty())
        roots().proc = procRoot;
}

QList<PortHolders::Holder> PortHolders::holders(const QString &port)
{
    const QString device = deviceOf(port);
    const qint64 self = QCoreApplication::applicationPid();
    QList<Holder> out;
    auto add = [&](qint64 pid) {
        if (pid <= 0 || pid == self || !alive(pid))
            return;
        for (const Holder &h : std::as_const(out))
            if (h.pid == pid)
                return;
        out << Holder{pid, programOf(pid)};
    };
    // The lock file: Qt's QLockFile writes the pid on its first line, UUCP locks pad it.
    // Named as Qt names it: the path below /dev with '/' as '_' (LCK..ttyUSB0, LCK..pts_5).
    QString base =
        device.startsWith(QLatin1String("/dev/")) ? device.mid(5) : QFileInfo(device).fileName();
    base.replace(QLatin1Char('/'), QLatin1Char('_'));
    const QString lockName = QStringLiteral("LCK..") + base;
    for (const QString &dir : std::as_const(roots().lockDirs)) {
        QFile lock(QDir(dir).filePath(lockName));
        if (lock.open(QIODevice::ReadOnly))
            add(QString::fromLatin1(lock.readLine()).trimmed().toLongLong());
    }
    // Every process with the port open (only our own user's are visible without root).
    const QDir proc(roots().proc);
    for (const QString &entry : proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        bool number = false;
        const qint64 pid = entry.toLongLong(&number);
        if (!number || pid == self)
            continue;
        const QDir fds(proc.filePath(entry + QStringLiteral("/fd")));
        for (const QFileInfo &fd :
             fds.entryInfoList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot)) {
            if (fd.symLinkTarget() == device) {
                add(pid);
                break;
            }
        }
    }
    return out;
}

QString PortHolders::inUseMessage(const QString &port, const QList<Holder> &holders)
{
    QStringList who;
    for (const Holder &h : holders)
        who << (h.program.isEmpty() ? tr("process %1").arg(h.pid)
                                    : tr("%1, process %2").arg(h.program).arg(h.pid));
    if (who.isEmpty())
        return tr("%1 is in use by another program").arg(port);
    return tr("%1 is in use by another program (%2)").arg(port, who.join(QStringLiteral("; ")));
}

QString PortHolders::openFailure(const QString &port, QSerialPort::SerialPortError error,
                                 const QString &errorString)
{
    const QList<Holder> found = holders(port);
    if (!found.isEmpty())
        return inUseMessage(port, found);
    // Qt says "Permission error while locking the device" when another program holds the
    // lock; a busy device (TIOCEXCL) is "Device or resource busy". A real permission error on
    // the device itself is told by the caller, with the dialout advice.
    const QFileInfo info(port);
    const bool accessible = info.isReadable() && info.isWritable();
    const bool locked = errorString.contains(QLatin1String("locking"), Qt::CaseInsensitive);
    const bool busy = errorString.contains(QLatin1String("busy"), Qt::CaseInsensitive);
    if (busy || (error == QSerialPort::PermissionError && locked && accessible))
        return inUseMessage(port, {});
    return errorString;
}

} // namespace stepcom
