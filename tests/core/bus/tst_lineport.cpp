// The adapter behind a port, from a fixture sysfs tree: FTDI FT232R/FT232H, CH340, CP210x,
// PL2303, a native UART, a microcontroller's USB serial; the quirks table names each driver.
// On a pseudo-terminal the low-latency request and the RS-485 modes are refused with a
// message naming the driver and the option to try, and nothing is sent.
#include "bus/portsetup.h"
#include "bus/serialadapter.h"
#include "bus/systemroot.h"
#include "programrun.h"

#include <QDir>
#include <QFile>
#include <QSocketNotifier>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

using namespace stepcom;
using namespace stepcom::test;

namespace {

bool writeSysfsFile(const QString &path, const QByteArray &content)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(content) == content.size();
}

// /sys/class/tty/TTY/device -> the port's folder under the USB device (or a platform device),
// its driver link, and the USB device's descriptors.
bool makeTty(const QString &sys, const QString &tty, const QString &driver, const QString &ids,
             const QString &product, const QString &serial, int latency)
{
    const bool usb = !ids.isEmpty();
    const QString usbDevice = sys + QStringLiteral("/devices/pci0000:00/usb1/1-1");
    const QString port = usb ? usbDevice + QStringLiteral("/1-1:1.0/") + tty
                             : sys + QStringLiteral("/devices/platform/serial8250/") + tty;
    QDir().mkpath(port);
    QDir().mkpath(sys + QStringLiteral("/class/tty"));
    QDir().mkpath(sys + QStringLiteral("/bus/drivers/") + driver);
    bool ok = QFile::link(port, sys + QStringLiteral("/class/tty/%1/device").arg(tty)) ||
              (QDir().mkpath(sys + QStringLiteral("/class/tty/") + tty) &&
               QFile::link(port, sys + QStringLiteral("/class/tty/%1/device").arg(tty)));
    ok = ok && QFile::link(sys + QStringLiteral("/bus/drivers/") + driver,
                           port + QStringLiteral("/driver"));
    if (latency >= 0)
        ok = ok &&
             writeSysfsFile(port + QStringLiteral("/latency_timer"), QByteArray::number(latency));
    if (usb) {
        ok = ok &&
             writeSysfsFile(usbDevice + QStringLiteral("/idVendor"),
                            ids.section(u':', 0, 0).toLatin1()) &&
             writeSysfsFile(usbDevice + QStringLiteral("/idProduct"),
                            ids.section(u':', 1, 1).toLatin1()) &&
             writeSysfsFile(usbDevice + QStringLiteral("/product"), product.toUtf8()) &&
             writeSysfsFile(usbDevice + QStringLiteral("/serial"), serial.toUtf8());
    }
    return ok;
}

} // namespace

class TestLinePort : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cleanup() { SystemRoot::set({}); }

    void identifies_data()
    {
        QTest::addColumn<QString>("driver");
        QTest::addColumn<QString>("ids");
        QTest::addColumn<int>("latency");
        QTest::addColumn<QString>("tty");
        QTest::addColumn<QString>("summary");
        QTest::addColumn<int>("family");
        QTest::newRow("FTDI FT232R") << "ftdi_sio"
                                     << "0403:6001" << 16 << "ttyUSB0"
                                     << "FTDI FT232R, latency timer 16 ms, serial A5XK3RJT"
                                     << int(SerialAdapter::Family::Ftdi);
        QTest::newRow("FTDI FT232H") << "ftdi_sio"
                                     << "0403:6014" << 1 << "ttyUSB0"
                                     << "FTDI FT232H, latency timer 1 ms, serial A5XK3RJT"
                                     << int(SerialAdapter::Family::Ftdi);
        QTest::newRow("CH340") << "ch341-uart"
                               << "1a86:7523" << -1 << "ttyUSB1"
                               << "CH340 (ch341-uart), serial A5XK3RJT"
                               << int(SerialAdapter::Family::Ch34x);
        QTest::newRow("CP210x") << "cp210x"
                                << "10c4:ea60" << -1 << "ttyUSB2"
                                << "CP210x (cp210x), serial A5XK3RJT"
                                << int(SerialAdapter::Family::Cp210x);
        QTest::newRow("PL2303") << "pl2303"
                                << "067b:2303" << -1 << "ttyUSB3"
                                << "PL2303 (pl2303), serial A5XK3RJT"
                                << int(SerialAdapter::Family::Pl2303);
        QTest::newRow("a microcontroller's USB serial")
            << "cdc_acm"
            << "2e8a:000a" << -1 << "ttyACM0"
            << "Pico (cdc_acm), serial A5XK3RJT" << int(SerialAdapter::Family::CdcAcm);
        QTest::newRow("native UART")
            << "serial8250"
            << "" << -1 << "ttyS0"
            << "native UART (serial8250)" << int(SerialAdapter::Family::NativeUart);
    }

    void identifies()
    {
        QFETCH(QString, driver);
        QFETCH(QString, ids);
        QFETCH(int, latency);
        QFETCH(QString, tty);
        QFETCH(QString, summary);
        QFETCH(int, family);
        QTemporaryDir dir;
        const QString sys = dir.filePath(QStringLiteral("sys"));
        QVERIFY(makeTty(sys, tty, driver, ids, QStringLiteral("Pico"), QStringLiteral("A5XK3RJT"),
                        latency));
        SystemRoot::set(dir.path());
        const SerialAdapter a = SerialAdapter::identify(QStringLiteral("/dev/") + tty);
        QCOMPARE(a.driver, driver);
        QCOMPARE(int(a.family), family);
        QCOMPARE(a.summary(), summary);
        QCOMPARE(a.latencyTimerMs, latency);
        QVERIFY(!a.quirk().isEmpty()); // every family here has its line in the table
    }

    // Nothing in sysfs: nothing said, never guessed.
    void unknownWithoutSysfs()
    {
        QTemporaryDir dir;
        SystemRoot::set(dir.path());
        const SerialAdapter a = SerialAdapter::identify(QStringLiteral("/dev/ttyUSB9"));
        QCOMPARE(a.family, SerialAdapter::Family::Unknown);
        QVERIFY(a.summary().isEmpty());
        QCOMPARE(a.latencyTimerMs, -1);
    }

    // Newer kernels put the serial core's "port" and "ctrl" devices between an on-board UART's
    // tty and its platform device: the driver named is the UART's, not theirs.
    void driverBehindTheSerialCore()
    {
        QTemporaryDir dir;
        const QString sys = dir.filePath(QStringLiteral("sys"));
        const QString uart = sys + QStringLiteral("/devices/platform/serial8250");
        const QString ctrl = uart + QStringLiteral("/serial8250:0");
        const QString port = ctrl + QStringLiteral("/serial8250:0.0");
        QVERIFY(QDir().mkpath(port + QStringLiteral("/tty/ttyS0")));
        QVERIFY(QDir().mkpath(sys + QStringLiteral("/class/tty/ttyS0")));
        QVERIFY(QFile::link(port, sys + QStringLiteral("/class/tty/ttyS0/device")));
        for (const auto &[folder, driver] :
             {std::pair{port, "port"}, std::pair{ctrl, "ctrl"}, std::pair{uart, "serial8250"}}) {
            const QString driverDir = sys + QStringLiteral("/bus/drivers/") + driver;
            QVERIFY(QDir().mkpath(driverDir));
            QVERIFY(QFile::link(driverDir, folder + QStringLiteral("/driver")));
        }
        SystemRoot::set(dir.path());
        const SerialAdapter a = SerialAdapter::identify(QStringLiteral("ttyS0"));
        QCOMPARE(a.driver, QStringLiteral("serial8250"));
        QCOMPARE(a.family, SerialAdapter::Family::NativeUart);
        QCOMPARE(a.summary(), QStringLiteral("native UART (serial8250)"));
    }

    // Every driver the guide names has one row in the quirks table.
    void quirksTable()
    {
        QStringList drivers;
        for (const SerialAdapter::Quirk &q : SerialAdapter::quirks())
            drivers << QLatin1String(q.driver);
        QCOMPARE(drivers, (QStringList{"ftdi_sio", "ch341-uart", "cp210x", "pl2303", "cdc_acm",
                                       "serial8250"}));
    }

    // A pty has neither low latency nor RS-485: refused, said, and nothing reaches the line.
    void rs485RefusedOnAPty_data()
    {
        QTest::addColumn<QString>("mode");
        QTest::addColumn<QString>("message");
        QTest::newRow("kernel") << "kernel"
                                << "the driver (pty) has no kernel RS-485 mode";
        QTest::newRow("rts") << "rts"
                             << "the driver (pty) refused to switch RTS";
    }

    void rs485RefusedOnAPty()
    {
        QFETCH(QString, mode);
        QFETCH(QString, message);
        int master = -1;
        int slave = -1;
        char name[256] = {};
        QVERIFY(::openpty(&master, &slave, name, nullptr, nullptr) == 0);
        const QString pty = QString::fromLocal8Bit(name);
        QVERIFY(!PortSetup::requestLowLatency(slave).isEmpty());
        const ProgramRun run =
            runProgram(QStringLiteral("stepcomctl"),
                       {QStringLiteral("read"), QStringLiteral("--port"), pty,
                        QStringLiteral("--rs485"), mode, QStringLiteral("motor1.speed")});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains(message), qPrintable(run.err));
        QVERIFY2(run.err.contains(QStringLiteral("try --rs485")), qPrintable(run.err));
        // Nothing was sent: the master side has no byte to read.
        ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
        char byte = 0;
        QCOMPARE(::read(master, &byte, 1), -1);
        QCOMPARE(errno, EAGAIN);
        ::close(slave);
        ::close(master);
    }

    void badOptions()
    {
        const ProgramRun run = runProgram(QStringLiteral("stepcomctl"),
                                          {QStringLiteral("read"), QStringLiteral("--port"),
                                           QStringLiteral("/dev/null"), QStringLiteral("--rs485"),
                                           QStringLiteral("half")});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("--rs485: 'half' is not auto, kernel or rts")),
                 qPrintable(run.err));
        const ProgramRun delays = runProgram(
            QStringLiteral("stepcomctl"),
            {QStringLiteral("read"), QStringLiteral("--port"), QStringLiteral("/dev/null"),
             QStringLiteral("--rs485"), QStringLiteral("kernel"), QStringLiteral("--rs485-delays"),
             QStringLiteral("500")});
        QCOMPARE(delays.exitCode, 2);
        QVERIFY2(delays.err.contains(QStringLiteral("--rs485-delays: '500'")),
                 qPrintable(delays.err));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestLinePort, Guiless)
#include "tst_lineport.moc"
