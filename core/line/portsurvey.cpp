#include "line/portsurvey.h"

#include "bus/portholders.h"
#include "bus/serialadapter.h"
#include "bus/systemroot.h"

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

void PortSurvey::setSystemRoot(const QString &root)
{
    SystemRoot::set(root);
}

QList<PortSurvey::Port> PortSurvey::ports()
{
    QList<Port> out;
    const QDir ttys(SystemRoot::path(QStringLiteral("/sys/class/tty")));
    if (SystemRoot::root().isEmpty() && !ttys.exists()) {
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
        QDir(SystemRoot::path(QStringLiteral("/dev/serial/by-id")))
            .entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot);
    for (const QString &name : ttys.entryList(QDir::Dirs | QDir::System | QDir::NoDotAndDotDot)) {
        const QString location = QStringLiteral("/dev/") + name;
        // Virtual terminals and ptys have no device behind them.
        if (!QFileInfo::exists(ttys.filePath(name) + QStringLiteral("/device")) ||
            !QFileInfo::exists(SystemRoot::path(location)))
            continue;
        // The kernel's placeholders for 8250 UARTs that are not there: type 0, PORT_UNKNOWN.
        if (readLine(ttys.filePath(name) + QStringLiteral("/type")) == QLatin1String("0"))
            continue;
        Port port;
        const SerialAdapter adapter = SerialAdapter::identify(location);
        port.driver = adapter.driver;
        port.entry.portName = name;
        port.entry.systemLocation = location;
        port.entry.vendorId = adapter.vendorId.toUShort(nullptr, 16);
        port.entry.productId = adapter.productId.toUShort(nullptr, 16);
        port.entry.manufacturer = adapter.manufacturer;
        port.entry.description = adapter.product;
        port.entry.serialNumber = adapter.serial;
        for (const QFileInfo &link : links) {
            if (QFileInfo(link.symLinkTarget()).fileName() == name) {
                port.entry.byId = QStringLiteral("/dev/serial/by-id/") + link.fileName();
                break;
            }
        }
        const QFileInfo node(SystemRoot::path(location));
        port.accessible = node.isReadable() && node.isWritable();
        port.holders = holders(location, &port.holdersIncomplete);
        out << port;
    }
    std::sort(out.begin(), out.end(), [](const Port &a, const Port &b) {
        return a.entry.systemLocation < b.entry.systemLocation;
    });
    return out;
}

QList<PortSurvey::Holder> PortSurvey::holders(const QString &devicePath, bool *incomplete)
{
    QList<Holder> out;
    for (const PortHolders::Holder &h : PortHolders::holders(devicePath, incomplete)) {
        QStringList how;
        if (!h.lockFile.isEmpty())
            how << tr("lock file %1").arg(h.lockFile);
        if (h.open)
            how << tr("has it open");
        out << Holder{h.pid, h.program, how.join(QStringLiteral(", "))};
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
