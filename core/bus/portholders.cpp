#include "bus/portholders.h"

#include "bus/systemroot.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QtEndian>

#include <algorithm>

namespace stepcom {

namespace {

QString programOf(qint64 pid)
{
    QFile comm(SystemRoot::path(QStringLiteral("/proc/%1/comm").arg(pid)));
    if (!comm.open(QIODevice::ReadOnly))
        return {};
    return QString::fromLocal8Bit(comm.readLine()).trimmed();
}

bool alive(qint64 pid)
{
    return QFileInfo::exists(SystemRoot::path(QStringLiteral("/proc/%1").arg(pid)));
}

// The pid in a lock file: Qt's QLockFile writes it on the first line (the program and host
// after it), UUCP locks pad it to ten columns, old programs wrote 4 binary bytes.
qint64 lockPid(QFile &lock)
{
    const QByteArray data = lock.read(64);
    bool ok = false;
    const qint64 pid = data.left(data.indexOf('\n')).trimmed().toLongLong(&ok);
    if (ok)
        return pid;
    return data.size() == 4 ? qFromUnaligned<qint32>(data.constData()) : 0;
}

} // namespace

QString PortHolders::lockName(const QString &device)
{
    QString base =
        device.startsWith(QLatin1String("/dev/")) ? device.mid(5) : QFileInfo(device).fileName();
    base.replace(QLatin1Char('/'), QLatin1Char('_'));
    return QStringLiteral("LCK..") + base;
}

QList<PortHolders::Holder> PortHolders::holders(const QString &port, bool *incomplete)
{
    if (incomplete)
        *incomplete = false;
    const QString device = SystemRoot::device(port);
    const qint64 self = QCoreApplication::applicationPid();
    QList<Holder> out;
    const auto known = [&out](qint64 pid) {
        return std::find_if(out.begin(), out.end(),
                            [pid](const Holder &h) { return h.pid == pid; });
    };
    // A lock whose process is gone is stale: nobody holds the port by it.
    const QString name = lockName(device);
    for (const QString &dir : {QStringLiteral("/run/lock"), QStringLiteral("/var/lock")}) {
        const QString lockFile = dir + QLatin1Char('/') + name;
        QFile lock(SystemRoot::path(lockFile));
        if (!lock.open(QIODevice::ReadOnly))
            continue;
        const qint64 pid = lockPid(lock);
        if (pid <= 0 || pid == self || !alive(pid) || known(pid) != out.end())
            continue;
        out << Holder{pid, programOf(pid), lockFile, false};
    }
    // Every process with the port open (only our own user's are visible without root).
    const QDir proc(SystemRoot::path(QStringLiteral("/proc")));
    for (const QString &entry : proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        bool number = false;
        const qint64 pid = entry.toLongLong(&number);
        if (!number || pid == self)
            continue;
        const QString fdDir = proc.filePath(entry + QStringLiteral("/fd"));
        const QFileInfo fdInfo(fdDir);
        if (!fdInfo.exists())
            continue;
        if (!fdInfo.isReadable() || !fdInfo.isExecutable()) {
            if (incomplete)
                *incomplete = true; // another user's process: its files cannot be seen
            continue;
        }
        const QFileInfoList fds =
            QDir(fdDir).entryInfoList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot);
        const bool holds = std::any_of(fds.cbegin(), fds.cend(), [&](const QFileInfo &fd) {
            const QString target = fd.symLinkTarget();
            return target == device || target == SystemRoot::path(device);
        });
        if (!holds)
            continue;
        const auto holder = known(pid);
        if (holder != out.end())
            holder->open = true;
        else
            out << Holder{pid, programOf(pid), QString(), true};
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
