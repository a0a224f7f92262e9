// The Connection page's port list: adapters a person recognises, the stable by-id name opened,
// and a port plugged in while the page is shown added and offered.
#include "pages/connectionpage.h"
#include "session/devicesession.h"
#include "session/serialports.h"

#include <QApplication>
#include <QComboBox>
#include <QStandardPaths>
#include <QTest>

using namespace stepcom;

namespace {

SerialPortEntry port(const QString &name, const QString &serial, const QString &byId = {})
{
    SerialPortEntry e;
    e.portName = name;
    e.systemLocation = QStringLiteral("/dev/") + name;
    e.description = QStringLiteral("USB-RS485 Cable");
    e.manufacturer = QStringLiteral("FTDI");
    e.serialNumber = serial;
    e.byId = byId;
    return e;
}

} // namespace

class TestPortList : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
    }

    void adaptersByNameAndPluggedInOffered()
    {
        DeviceSession session;
        ConnectionPage page(&session);
        QList<SerialPortEntry> system{port(QStringLiteral("ttyS0"), {})};
        const QString byId = QStringLiteral("/dev/serial/by-id/usb-FTDI_USB-RS485_Cable_FT9X-if00");
        page.serialPorts()->setByIdDirectory(QStringLiteral("/nonexistent"));
        // The fake listing carries its by-id link already (no /dev/serial here).
        page.serialPorts()->setLister([&] { return system; });
        page.refreshPorts();
        auto *combo = page.findChild<QComboBox *>(QStringLiteral("port"));
        QCOMPARE(combo->count(), 1);
        QCOMPARE(combo->itemText(0), QStringLiteral("ttyS0 — USB-RS485 Cable (FTDI)"));

        page.show();
        QVERIFY(page.serialPorts()->isWatching());
        system << port(QStringLiteral("ttyUSB3"), QStringLiteral("FT9X"), byId);
        page.serialPorts()->check(); // what the watch timer does every second
        QCOMPARE(combo->count(), 2);
        QCOMPARE(combo->currentText(),
                 QStringLiteral("ttyUSB3 — USB-RS485 Cable (FTDI, S/N FT9X)"));
        QVERIFY(combo->itemData(combo->currentIndex(), Qt::ToolTipRole).toString().contains(byId));
        QCOMPARE(page.currentSettings().portName, byId); // the stable name is opened
        QVERIFY2(page.statusText().contains(QStringLiteral("ttyUSB3")),
                 qPrintable(page.statusText()));

        page.hide();
        QVERIFY(!page.serialPorts()->isWatching());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestPortList, Gui)
#include "tst_portlist.moc"
