#include "session/serialports.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSerialPortInfo>

#include <algorithm>

namespace stepcom {

QString SerialPortEntry::text() const
{
    QStringList about;
    if (!manufacturer.isEmpty() && !description.contains(manufacturer))
        about << manufacturer;
    if (!serialNumber.isEmpty())
        about << QCoreApplication::translate("stepcom::SerialPorts", "S/N %1").arg(serialNumber);
    QString text = portName.isEmpty() ? systemLocation : portName;
    if (!description.isEmpty())
        text += QStringLiteral(" — ") + description;
    if (!about.isEmpty())
        text += (description.isEmpty() ? QStringLiteral(" — %1") : QStringLiteral(" (%1)"))
                    .arg(about.join(QLatin1String(", ")));
    return text;
}

QString SerialPortEntry::details() const
{
    QStringList lines;
    lines << systemLocation;
    if (!byId.isEmpty())
        lines << QCoreApplication::translate("stepcom::SerialPorts", "Stable name: %1").arg(byId);
    if (!description.isEmpty())
        lines
            << QCoreApplication::translate("stepcom::SerialPorts", "Adapter: %1").arg(description);
    if (!manufacturer.isEmpty())
        lines << QCoreApplication::translate("stepcom::SerialPorts", "Manufacturer: %1")
                     .arg(manufacturer);
    if (!serialNumber.isEmpty())
        lines << QCoreApplication::translate("stepcom::SerialPorts", "Serial number: %1")
                     .arg(serialNumber);
    if (vendorId || productId)
        lines << QCoreApplication::translate("stepcom::SerialPorts", "USB id: %1:%2")
                     .arg(vendorId, 4, 16, QLatin1Char('0'))
                     .arg(productId, 4, 16, QLatin1Char('0'));
    return lines.join(QLatin1Char('\n'));
}

SerialPorts::SerialPorts(QObject *parent)
    : QObject(parent)
    , m_lister(&SerialPorts::systemPorts)
    , m_byIdDirectory(QStringLiteral("/dev/serial/by-id"))
{
    connect(&m_timer, &QTimer::timeout, this, &SerialPorts::check);
}

QList<SerialPortEntry> SerialPorts::systemPorts()
{
    QList<SerialPortEntry> out;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        SerialPortEntry e;
        e.portName = info.portName();
        e.systemLocation = info.systemLocation();
        e.description = info.description();
        e.manufacturer = info.manufacturer();
        e.serialNumber = info.serialNumber();
        e.vendorId = info.hasVendorIdentifier() ? info.vendorIdentifier() : 0;
        e.productId = info.hasProductIdentifier() ? info.productIdentifier() : 0;
        out << e;
    }
    return out;
}

void SerialPorts::setLister(Lister lister)
{
    m_lister = std::move(lister);
}

void SerialPorts::setByIdDirectory(const QString &directory)
{
    m_byIdDirectory = directory;
}

QList<SerialPortEntry> SerialPorts::scan()
{
    QList<SerialPortEntry> ports = m_lister ? m_lister() : QList<SerialPortEntry>();
    // by-id holds symlinks to ../../ttyUSB0: match them by where they lead.
    const QFileInfoList links =
        QDir(m_byIdDirectory).entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot);
    for (SerialPortEntry &port : ports) {
        const QString target = QFileInfo(port.systemLocation).canonicalFilePath();
        for (const QFileInfo &link : links) {
            if (!target.isEmpty() && link.canonicalFilePath() == target) {
                port.byId = link.absoluteFilePath();
                break;
            }
        }
    }
    std::sort(ports.begin(), ports.end(), [](const SerialPortEntry &a, const SerialPortEntry &b) {
        return a.systemLocation < b.systemLocation;
    });
    m_ports = ports;
    return m_ports;
}

void SerialPorts::setWatching(bool watching, int intervalMs)
{
    if (watching)
        m_timer.start(intervalMs);
    else
        m_timer.stop();
}

void SerialPorts::check()
{
    const QList<SerialPortEntry> before = m_ports;
    const QList<SerialPortEntry> now = scan();
    QList<SerialPortEntry> added;
    bool same = before.size() == now.size();
    for (int i = 0; i < now.size(); ++i) {
        const auto known = std::find_if(before.begin(), before.end(), [&](const auto &b) {
            return b.systemLocation == now.at(i).systemLocation &&
                   b.serialNumber == now.at(i).serialNumber;
        });
        if (known == before.end()) {
            added << now.at(i);
            same = false;
        }
    }
    if (!same)
        Q_EMIT changed(now, added);
}

} // namespace stepcom
