// Ports a person recognises: the adapter's name, maker and serial number, the stable by-id link
// found by where it leads, and ports that appear while watching reported as added.
#include "session/serialports.h"

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

SerialPortEntry ftdi(const QString &location)
{
    SerialPortEntry e;
    e.portName = QFileInfo(location).fileName();
    e.systemLocation = location;
    e.description = QStringLiteral("FT232R USB UART");
    e.manufacturer = QStringLiteral("FTDI");
    e.serialNumber = QStringLiteral("A10K3B5Q");
    e.vendorId = 0x0403;
    e.productId = 0x6001;
    return e;
}

} // namespace

class TestSerialPorts : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void texts_data()
    {
        QTest::addColumn<QString>("description");
        QTest::addColumn<QString>("manufacturer");
        QTest::addColumn<QString>("serial");
        QTest::addColumn<QString>("text");
        QTest::newRow("all") << "FT232R USB UART"
                             << "FTDI"
                             << "A10K3B5Q"
                             << "ttyUSB0 — FT232R USB UART (FTDI, S/N A10K3B5Q)";
        QTest::newRow("maker in description") << "CH340 serial converter (QinHeng)"
                                              << "QinHeng"
                                              << ""
                                              << "ttyUSB0 — CH340 serial converter (QinHeng)";
        QTest::newRow("no description") << ""
                                        << "Prolific"
                                        << "123"
                                        << "ttyUSB0 — Prolific, S/N 123";
        QTest::newRow("built-in port") << ""
                                       << ""
                                       << ""
                                       << "ttyUSB0";
    }
    void texts()
    {
        QFETCH(QString, description);
        QFETCH(QString, manufacturer);
        QFETCH(QString, serial);
        QFETCH(QString, text);
        SerialPortEntry e;
        e.portName = QStringLiteral("ttyUSB0");
        e.systemLocation = QStringLiteral("/dev/ttyUSB0");
        e.description = description;
        e.manufacturer = manufacturer;
        e.serialNumber = serial;
        QCOMPARE(e.text(), text);
    }

    // The by-id link of a port is found by where it leads; it is what gets opened.
    void stableNames()
    {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("by-id")));
        const QString tty0 = dir.filePath(QStringLiteral("ttyUSB0"));
        const QString tty1 = dir.filePath(QStringLiteral("ttyUSB1"));
        for (const QString &path : {tty0, tty1}) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
        }
        const QString link =
            dir.filePath(QStringLiteral("by-id/usb-FTDI_FT232R_USB_UART_A10K3B5Q-if00-port0"));
        QVERIFY(QFile::link(QStringLiteral("../ttyUSB1"), link));
        SerialPorts ports;
        ports.setByIdDirectory(dir.filePath(QStringLiteral("by-id")));
        ports.setLister([&] { return QList<SerialPortEntry>{ftdi(tty1), ftdi(tty0)}; });
        const QList<SerialPortEntry> list = ports.scan();
        QCOMPARE(list.size(), 2);
        QCOMPARE(list.at(0).systemLocation, tty0); // sorted
        QCOMPARE(list.at(0).byId, QString());
        QCOMPARE(list.at(0).path(), tty0);
        QCOMPARE(list.at(1).byId, link);
        QCOMPARE(list.at(1).path(), link);
        const QString details = list.at(1).details();
        QVERIFY2(details.contains(QStringLiteral("Stable name: ") + link), qPrintable(details));
        QVERIFY(details.contains(QStringLiteral("Serial number: A10K3B5Q")));
        QVERIFY(details.contains(QStringLiteral("USB id: 0403:6001")));
    }

    // Watching: a port that appears is reported as added; nothing changing says nothing.
    void watchReportsAddedPorts()
    {
        QList<SerialPortEntry> system{ftdi(QStringLiteral("/dev/ttyUSB0"))};
        SerialPorts ports;
        ports.setByIdDirectory(QStringLiteral("/nonexistent"));
        ports.setLister([&] { return system; });
        ports.scan();
        QSignalSpy changed(&ports, &SerialPorts::changed);
        ports.check();
        QCOMPARE(changed.count(), 0);
        SerialPortEntry other = ftdi(QStringLiteral("/dev/ttyUSB1"));
        other.serialNumber = QStringLiteral("B77");
        system << other;
        ports.check();
        QCOMPARE(changed.count(), 1);
        const auto added = changed.first().at(1).value<QList<SerialPortEntry>>();
        QCOMPARE(added.size(), 1);
        QCOMPARE(added.first().serialNumber, QStringLiteral("B77"));
        // Unplugged: a change with nothing added.
        system.removeFirst();
        ports.check();
        QCOMPARE(changed.count(), 2);
        QVERIFY(changed.last().at(1).value<QList<SerialPortEntry>>().isEmpty());
        QCOMPARE(ports.ports().size(), 1);
        // The timer does the same while watching.
        ports.setWatching(true, 10);
        QVERIFY(ports.isWatching());
        system << ftdi(QStringLiteral("/dev/ttyUSB0"));
        QTRY_COMPARE(changed.count(), 3);
        ports.setWatching(false);
        QVERIFY(!ports.isWatching());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestSerialPorts, Guiless)
#include "tst_serialports.moc"
