#include "bus/serialadapter.h"

#include "bus/systemroot.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace stepcom {

namespace {

QString readText(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).trimmed();
}

SerialAdapter::Family familyOf(const QString &driver, const QString &tty)
{
    if (driver == u"ftdi_sio")
        return SerialAdapter::Family::Ftdi;
    if (driver == u"ch341-uart" || driver == u"ch341")
        return SerialAdapter::Family::Ch34x;
    if (driver == u"cp210x")
        return SerialAdapter::Family::Cp210x;
    if (driver == u"pl2303")
        return SerialAdapter::Family::Pl2303;
    if (driver == u"cdc_acm")
        return SerialAdapter::Family::CdcAcm;
    if (driver.startsWith(u"serial8250") || driver.contains(u"uart") || driver == u"serial" ||
        tty.startsWith(u"ttyS") || tty.startsWith(u"ttyAMA"))
        return SerialAdapter::Family::NativeUart;
    return SerialAdapter::Family::Unknown;
}

} // namespace

const QList<SerialAdapter::Quirk> &SerialAdapter::quirks()
{
    static const QList<Quirk> table = {
        {Family::Ftdi, "ftdi_sio",
         QT_TRANSLATE_NOOP("stepcom::SerialAdapter",
                           "holds received bytes up to its latency timer (16 ms by default), "
                           "which adds up to 16 ms to every answer; StepCom asks for low "
                           "latency (1 ms) when it opens the port, and the package's udev rule "
                           "sets 1 ms; the kernel's RS-485 mode is supported by some chips")},
        {Family::Ch34x, "ch341-uart",
         QT_TRANSLATE_NOOP("stepcom::SerialAdapter",
                           "no latency timer to set; delivers bytes in small USB packets; the "
                           "driver refuses the kernel's RS-485 mode (use --rs485 auto with an "
                           "adapter that switches by itself, or rts)")},
        {Family::Cp210x, "cp210x",
         QT_TRANSLATE_NOOP("stepcom::SerialAdapter",
                           "no latency timer to set; RS-485 direction, when the adapter has "
                           "it, is switched by the chip itself (set in its configuration), "
                           "not by the kernel's RS-485 mode")},
        {Family::Pl2303, "pl2303",
         QT_TRANSLATE_NOOP("stepcom::SerialAdapter",
                           "copies of the chip are common and the driver may refuse them; no "
                           "kernel RS-485 mode; bytes come in USB packets")},
        {Family::CdcAcm, "cdc_acm",
         QT_TRANSLATE_NOOP("stepcom::SerialAdapter",
                           "a microcontroller's own USB serial: the baud set may mean nothing "
                           "to it and the line's timing is its firmware's")},
        {Family::NativeUart, "serial8250",
         QT_TRANSLATE_NOOP("stepcom::SerialAdapter",
                           "an on-board UART: no USB packets; RS-485 direction through the "
                           "kernel's RS-485 mode where the board wires it, else by RTS")},
    };
    return table;
}

SerialAdapter SerialAdapter::identify(const QString &port)
{
    SerialAdapter a;
    const QString path = SystemRoot::device(port);
    a.tty = QFileInfo(path).fileName();
    if (path.startsWith(QLatin1String("/dev/pts/"))) {
        a.family = Family::PseudoTerminal;
        a.driver = QStringLiteral("pty");
        return a;
    }
    const QString device =
        QFileInfo(SystemRoot::path(QStringLiteral("/sys/class/tty/%1/device").arg(a.tty)))
            .canonicalFilePath();
    if (device.isEmpty())
        return a;
    // The serial core's own "port" and "ctrl" devices sit between the tty and the UART's driver.
    QDir up(device);
    const auto serialCore = [](const QString &driver) {
        return driver.isEmpty() || driver == u"port" || driver == u"ctrl";
    };
    for (int i = 0; i < 4 && serialCore(a.driver); ++i) {
        a.driver = QFileInfo(up.filePath(QStringLiteral("driver"))).symLinkTarget();
        a.driver = a.driver.section(QLatin1Char('/'), -1);
        if (!up.cdUp())
            break;
    }
    if (serialCore(a.driver))
        a.driver.clear();
    a.family = familyOf(a.driver, a.tty);
    const QString latency = readText(device + QStringLiteral("/latency_timer"));
    bool ok = false;
    const int ms = latency.toInt(&ok);
    a.latencyTimerMs = ok ? ms : -1;
    // Up from the port to the USB device: the first folder with the vendor's id.
    QDir dir(device);
    for (int level = 0; level < 7; ++level) {
        if (QFileInfo::exists(dir.filePath(QStringLiteral("idVendor")))) {
            a.vendorId = readText(dir.filePath(QStringLiteral("idVendor")));
            a.productId = readText(dir.filePath(QStringLiteral("idProduct")));
            a.manufacturer = readText(dir.filePath(QStringLiteral("manufacturer")));
            a.product = readText(dir.filePath(QStringLiteral("product")));
            a.serial = readText(dir.filePath(QStringLiteral("serial")));
            break;
        }
        if (dir.isRoot() || !dir.cdUp())
            break;
    }
    return a;
}

void SerialAdapter::refreshLatency()
{
    const QString text = readText(
        SystemRoot::path(QStringLiteral("/sys/class/tty/%1/device/latency_timer").arg(tty)));
    bool ok = false;
    const int ms = text.toInt(&ok);
    if (ok)
        latencyTimerMs = ms;
}

QString SerialAdapter::name() const
{
    const QString id = vendorId.toLower() + QLatin1Char(':') + productId.toLower();
    static const QList<std::pair<const char *, const char *>> known = {
        {"0403:6001", "FTDI FT232R"}, {"0403:6014", "FTDI FT232H"}, {"0403:6015", "FTDI FT-X"},
        {"0403:6010", "FTDI FT2232"}, {"0403:6011", "FTDI FT4232"}, {"1a86:7523", "CH340"},
        {"1a86:5523", "CH341"},       {"1a86:55d4", "CH9102"},      {"10c4:ea60", "CP210x"},
        {"067b:2303", "PL2303"},      {"067b:23a3", "PL2303GC"},
    };
    for (const auto &[ids, label] : known)
        if (id == QLatin1String(ids))
            return QLatin1String(label);
    switch (family) {
    case Family::Ftdi:
        return QStringLiteral("FTDI");
    case Family::Ch34x:
        return QStringLiteral("CH34x");
    case Family::Cp210x:
        return QStringLiteral("CP210x");
    case Family::Pl2303:
        return QStringLiteral("PL2303");
    case Family::NativeUart:
        return tr("native UART");
    case Family::PseudoTerminal:
        return tr("pseudo-terminal");
    case Family::CdcAcm:
    case Family::Unknown:
        break;
    }
    const QString maker = QStringList{manufacturer, product}.join(QLatin1Char(' ')).trimmed();
    return maker.isEmpty() ? driver : maker;
}

QString SerialAdapter::summary() const
{
    // A pseudo-terminal is no adapter: the line's summary stays as it was.
    const QString n = family == Family::PseudoTerminal ? QString() : name();
    if (n.isEmpty())
        return {};
    QString text = n;
    if (!driver.isEmpty() && family != Family::Ftdi)
        text += QStringLiteral(" (%1)").arg(driver);
    if (latencyTimerMs >= 0)
        text += tr(", latency timer %1 ms").arg(latencyTimerMs);
    if (!serial.isEmpty())
        text += tr(", serial %1").arg(serial);
    return text;
}

QString SerialAdapter::quirk() const
{
    for (const Quirk &q : quirks())
        if (q.family == family)
            return tr(q.text);
    return {};
}

} // namespace stepcom
