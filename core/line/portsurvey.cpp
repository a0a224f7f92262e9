#include "line/portsurvey.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace stepcom {

namespace {

QString readLine(const QString &file)
{
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readLine()).trimmed();
}

} // namespace

PortSurvey::PortSurvey(const QString &root)
    : m_root(root)
    , m_ownPid(QCoreApplication::applicationPid())
{
    while (m_root.endsWith(QLatin1Char('/')))
        m_root.chop(1);
}

QList<PortSurvey::Port> PortSurvey::ports() const
{
    QList<Port> out;
    const QDir ttys(path(QStringLiteral("/sys/class/tty")));
    if (m_root.isEmpty() && !ttys.exists()) {
        // No sysfs (Windows, macOS): what Qt lists, with nobody known to hold it.
        for (const SerialPortEntry &entry : SerialPorts::systemPorts()) {
            Port port;
            port.entry = entry;
            port.holdersKnown = false;
            out << port;
        }
        return out;
    }
    const QFileInfoList links =
        QDir(path(QStringLiteral("/dev/serial/by-id")))
            .entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot);
    for (const QString &name : ttys.entryList(QDir::Dirs | QDir::System | QDir::NoDotAndDotDot)) {
        const QString device = ttys.filePath(name) + QStringLiteral("/device");
        // Virtual terminals and ptys have no device behind them.
        if (!QFileInfo::exists(device) || !QFileInfo::exists(path(QStringLiteral("/dev/") + name)))
            continue;
        // The kernel's placeholders for 8250 UARTs that are not there: type 0, PORT_UNKNOWN.
        if (readLine(ttys.filePath(name) + QStringLiteral("/type")) == QLatin1String("0"))
            continue;
        Port port;
        // The serial core's own "port" and "ctrl" devices sit between the tty and the UART's
        // driver.
        QDir up(QFileInfo(device).canonicalFilePath());
        const auto serialCore = [](const QString &driver) {
            return driver.isEmpty() || driver == QLatin1String("port") ||
                   driver == QLatin1String("ctrl");
        };
        for (int i = 0; i < 4 && serialCore(port.driver); ++i) {
            port.driver = QFileInfo(up.filePath(QStringLiteral("driver")))
                              .symLinkTarget()
                              .section(QLatin1Char('/'), -1);
            if (!up.cdUp())
                break;
        }
        port.entry.portName = name;
        port.entry.systemLocation = QStringLiteral("/dev/") + name;
        readAdapter(name, &port);
        for (const QFileInfo &link : links) {
            if (QFileInfo(link.symLinkTarget()).fileName() == name) {
                port.entry.byId = QStringLiteral("/dev/serial/by-id/") + link.fileName();
                break;
            }
        }
        const QFileInfo node(path(port.entry.systemLocation));
        port.accessible = node.isReadable() && node.isWritable();
        port.holders = holders(port.entry.systemLocation, &port.holdersIncomplete);
        out << port;
    }
    std::sort(out.begin(), out.end(), [](const Port &a, const Port &b) {
        return a.entry.systemLocation < b.entry.systemLocation;
    });
    return out;
}

void PortSurvey::readAdapter(const QString &ttyName, Port *port) const
{
    // The USB device is a few folders above the tty's interface: the first with an idVendor.
    QDir dir(QFileInfo(path(QStringLiteral("/sys/class/tty/%1/device").arg(ttyName)))
                 .canonicalFilePath());
    for (int up = 0; up < 6 && !dir.isRoot(); ++up) {
        if (dir.exists(QStringLiteral("idVendor"))) {
            bool ok = false;
            port->entry.vendorId =
                readLine(dir.filePath(QStringLiteral("idVendor"))).toUShort(&ok, 16);
            port->entry.productId =
                readLine(dir.filePath(QStringLiteral("idProduct"))).toUShort(&ok, 16);
            port->entry.manufacturer = readLine(dir.filePath(QStringLiteral("manufacturer")));
            port->entry.description = readLine(dir.filePath(QStringLiteral("product")));
            port->entry.serialNumber = readLine(dir.filePath(QStringLiteral("serial")));
            return;
        }
        if (!dir.cdUp())
            return;
    }
}

QString PortSurvey::programOf(qint64 pid) const
{
    return readLine(path(QStringLiteral("/proc/%1/comm").arg(pid)));
}

QList<PortSurvey::Holder> PortSurvey::holders(const QString &devicePath, bool *incomplete) const
{
    QList<Holder> out;
    if (incomplete)
        *incomplete = false;
    const QString name = QFileInfo(devicePath).fileName();
    // UUCP lock files: the pid as text (or, from old programs, as 4 binary bytes).
    for (const QString &folder : {QStringLiteral("/run/lock"), QStringLiteral("/var/lock")}) {
        const QString lock = folder + QStringLiteral("/LCK..") + name;
        QFile f(path(lock));
        if (!f.open(QIODevice::ReadOnly))
            continue;
        const QByteArray data = f.read(64);
        bool ok = false;
        qint64 pid = data.trimmed().toLongLong(&ok);
        if (!ok && data.size() == 4)
            pid = *reinterpret_cast<const qint32 *>(data.constData());
        // A lock whose process is gone is stale: nobody holds the port by it.
        if (pid <= 0 || pid == m_ownPid ||
            !QFileInfo::exists(path(QStringLiteral("/proc/%1").arg(pid))) ||
            std::any_of(out.cbegin(), out.cend(), [pid](const Holder &h) { return h.pid == pid; }))
            continue;
        out << Holder{pid, programOf(pid), tr("lock file %1").arg(lock)};
    }
    const QDir proc(path(QStringLiteral("/proc")));
    for (const QString &entry : proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        bool numeric = false;
        const qint64 pid = entry.toLongLong(&numeric);
        if (!numeric || pid == m_ownPid)
            continue;
        const QString fdDir = proc.filePath(entry) + QStringLiteral("/fd");
        const QFileInfo fdInfo(fdDir);
        if (!fdInfo.exists())
            continue;
        if (!fdInfo.isReadable() || !fdInfo.isExecutable()) {
            if (incomplete)
                *incomplete = true; // another user's process: its files cannot be seen
            continue;
        }
        const QFileInfoList fds = QDir(fdDir).entryInfoList(QDir::System | QDir::NoDotAndDotDot);
        const bool holds = std::any_of(fds.cbegin(), fds.cend(), [&](const QFileInfo &fd) {
            const QString target = fd.symLinkTarget();
            return target == devicePath || target == path(devicePath);
        });
        if (!holds)
            continue;
        const auto known =
            std::find_if(out.begin(), out.end(), [pid](const Holder &h) { return h.pid == pid; });
        if (known != out.end())
            known->how += QStringLiteral(", ") + tr("has it open");
        else
            out << Holder{pid, programOf(pid), tr("has it open")};
    }
    return out;
}

QString PortSurvey::holdersText(const Port &port)
{
    if (!port.holdersKnown)
        return tr("whether another program holds it is not known here");
    if (port.holders.isEmpty())
        return port.holdersIncomplete ? tr("free, as far as this user can see") : tr("free");
    QStringList parts;
    for (const Holder &h : port.holders)
        parts << tr("%1 (pid %2, %3)")
                     .arg(h.program.isEmpty() ? tr("a program") : h.program)
                     .arg(h.pid)
                     .arg(h.how);
    return tr("held by %1").arg(parts.join(QLatin1String("; ")));
}

} // namespace stepcom
