#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/devicelistdock.h"

#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>

using namespace stepcom;

// The window's list of the controllers on the line: one row per id, a click shows that
// device without reconnecting, "Add device" puts another id on the list.
class TestDeviceList : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_devicelist"));
        QSettings().clear();
    }

    // The user sets how often the devices not in view are read; it is kept for the next time.
    void theOthersRateIsTheUsers()
    {
        {
            DeviceSession session;
            DeviceListDock dock(&session);
            QCOMPARE(dock.backgroundIntervalBox()->value(), 1000);
            QCOMPARE(session.line()->backgroundIntervalMs(), 1000);
            dock.backgroundIntervalBox()->setValue(2500);
            QCOMPARE(session.line()->backgroundIntervalMs(), 2500);
        }
        DeviceSession session;
        DeviceListDock dock(&session);
        QCOMPARE(dock.backgroundIntervalBox()->value(), 2500);
        QCOMPARE(session.line()->backgroundIntervalMs(), 2500);
        QSettings().clear();
    }

    void clickingADeviceShowsItWithoutReconnecting()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session, {1, 2, 3});
        session.line()->setDeviceIds({1, 2});
        test::connectToSimulator(session);
        DeviceListDock dock(&session);
        QCOMPARE(dock.table()->rowCount(), 2);
        QCOMPARE(dock.rowTexts(0).first(), QStringLiteral("1"));

        // Add device 3 by id; a second time is refused with a reason.
        dock.idBox()->setValue(3);
        dock.addButton()->click();
        QCOMPARE(session.line()->deviceIds(), (QList<int>{1, 2, 3}));
        QCOMPARE(dock.table()->rowCount(), 3);
        QVERIFY(!dock.addDevice(3));

        // Its background status arrives and shows.
        QTRY_COMPARE_WITH_TIMEOUT(dock.rowTexts(2).at(2), QStringLiteral("answering"), 15000);
        QCOMPARE(dock.rowTexts(2).at(4), QStringLiteral("0"));

        QSignalSpy connected(session.connection(), &SessionConnection::connected);
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        Q_EMIT dock.table()->cellClicked(2, 0);
        QCOMPARE(session.line()->deviceInView(), 3);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QCOMPARE(*session.parameters()->store()->deviceValue(QStringLiteral("device.id")), 3);
        QCOMPARE(connected.size(), 0);
        QVERIFY(dock.rowTexts(2).at(2).contains(QStringLiteral("in view")));

        // The name is the user's.
        dock.table()->item(2, 1)->setText(QStringLiteral("Z axis"));
        QCOMPARE(dock.nameOf(3), QStringLiteral("Z axis"));
    }

    // Referenced or not, a motion under way and failed reads are each device's own.
    void eachRowShowsItsOwnDevicesState()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session, {1, 2});
        session.line()->setDeviceIds({1, 2});
        session.line()->setBackgroundIntervalMs(300);
        test::connectToSimulator(session);
        DeviceListDock dock(&session);
        test::simHost(session)->deviceAt(1)->setMachinePosition(1, 10.0);
        session.command(QStringLiteral("motor1.home"));
        QTRY_VERIFY(dock.rowTexts(0).at(2).startsWith(QStringLiteral("running: ")));
        QTRY_COMPARE_WITH_TIMEOUT(dock.rowTexts(0).at(3), QStringLiteral("motor 1"), 15000);
        QCOMPARE(dock.rowTexts(1).at(3), QStringLiteral("no"));
        QVERIFY(session.line()->showDevice(2));
        QCOMPARE(dock.rowTexts(0).at(3), QStringLiteral("motor 1")); // still, while 2 is in view
        QCOMPARE(dock.rowTexts(1).at(3), QStringLiteral("no"));
        QTRY_COMPARE_WITH_TIMEOUT(dock.rowTexts(0).at(2), QStringLiteral("answering"), 10000);
        QCOMPARE(dock.rowTexts(0).at(4), QStringLiteral("0"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDeviceList, Gui)
#include "tst_devicelist.moc"
