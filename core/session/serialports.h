#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>

namespace stepcom {

// One serial port as the system lists it (the fields of QSerialPortInfo a person recognises).
struct SerialPortEntry
{
    QString portName;       // "ttyUSB0"
    QString systemLocation; // "/dev/ttyUSB0"
    QString description;    // "FT232R USB UART"
    QString manufacturer;   // "FTDI"
    QString serialNumber;   // "A10K3B5Q"
    quint16 vendorId = 0;   // 0: none (not USB)
    quint16 productId = 0;
    // Filled by SerialPorts: the udev link that keeps its name when the adapter comes back as
    // another ttyUSB ("/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A10K3B5Q-if00-port0").
    QString byId;

    // What to open and to remember: the stable link when there is one.
    QString path() const { return byId.isEmpty() ? systemLocation : byId; }
    // "ttyUSB0 — FT232R USB UART (FTDI, S/N A10K3B5Q)"
    QString text() const;
    // Every detail, one a line, for a tooltip.
    QString details() const;
};

// The serial ports of this computer, with their adapters, watched for ports that appear. The
// listing is injectable: tests hand in a fake list and a fake by-id directory.
class SerialPorts : public QObject
{
    Q_OBJECT
public:
    using Lister = std::function<QList<SerialPortEntry>()>;

    explicit SerialPorts(QObject *parent = nullptr);

    // The system's ports (QSerialPortInfo::availablePorts()).
    static QList<SerialPortEntry> systemPorts();
    void setLister(Lister lister);
    // Where the stable links are (/dev/serial/by-id).
    void setByIdDirectory(const QString &directory);

    // Lists the ports now (sorted by name, each with its by-id link) and remembers them.
    QList<SerialPortEntry> scan();
    const QList<SerialPortEntry> &ports() const { return m_ports; }

    // While watching, the list is taken again every `intervalMs`; a change emits `changed`
    // with the ports that were not there before (the ones just plugged in).
    void setWatching(bool watching, int intervalMs = 1000);
    bool isWatching() const { return m_timer.isActive(); }
    // One watch step now (what the timer does).
    void check();

Q_SIGNALS:
    void changed(const QList<stepcom::SerialPortEntry> &ports,
                 const QList<stepcom::SerialPortEntry> &added);

private:
    Lister m_lister;
    QString m_byIdDirectory;
    QList<SerialPortEntry> m_ports;
    QTimer m_timer;
};

} // namespace stepcom
