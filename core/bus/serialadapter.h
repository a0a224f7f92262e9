#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace stepcom {

// The adapter behind a serial port, from sysfs (/sys/class/tty/NAME/device): its driver, the
// USB vendor and product, the maker's names and serial number, and an FTDI's latency timer. A
// USB adapter is not a wire: FTDI chips hold received bytes up to their latency timer (16 ms
// by default), CH340/CH341, CP210x and PL2303 each have their quirks -- one table, quirks().
// Read below SystemRoot, so tests work on a fixture tree.
struct SerialAdapter
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::SerialAdapter)
public:
    enum class Family {
        Unknown,
        Ftdi,       // ftdi_sio
        Ch34x,      // ch341-uart (CH340, CH341)
        Cp210x,     // cp210x
        Pl2303,     // pl2303
        CdcAcm,     // cdc_acm: a microcontroller's own USB serial
        NativeUart, // serial8250 and other on-board UARTs
        PseudoTerminal,
    };
    struct Quirk
    {
        Family family;
        const char *driver; // the kernel driver's name
        const char *text;   // what it does to a Modbus line (English source, translated)
    };

    QString tty;    // "ttyUSB0"
    QString driver; // "ftdi_sio"
    Family family = Family::Unknown;
    QString vendorId; // "0403"
    QString productId;
    QString manufacturer;
    QString product;
    QString serial;
    int latencyTimerMs = -1; // FTDI only; -1 not known

    // The adapter of `port` (a path, a by-id link, or a name such as ttyUSB0); what sysfs
    // does not say stays empty. The driver is the first one up from the tty that is not the
    // serial core's own ("port", "ctrl"), so an on-board UART is named by its own driver.
    static SerialAdapter identify(const QString &port);
    // Each driver's known quirks.
    static const QList<Quirk> &quirks();

    // "FTDI FT232R", "CH340", "CP210x", "native UART", "pseudo-terminal", or the maker's names.
    QString name() const;
    // "FTDI FT232R, latency timer 16 ms", "CH340 (ch341-uart)"; empty when nothing is known
    // and for a pseudo-terminal.
    QString summary() const;
    // This family's quirks, translated; empty when none are known.
    QString quirk() const;
    bool isUsb() const { return !vendorId.isEmpty(); }
    // Reads the latency timer again (after asking for low latency).
    void refreshLatency();
};

} // namespace stepcom
