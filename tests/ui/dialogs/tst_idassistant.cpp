#include "base/language.h"
#include "dialogs/busscandialog.h"
#include "dialogs/idassistantdialog.h"
#include "line/busscanner.h"
#include "line/idassigner.h"
#include "map/factoryvalues.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/builtinsimulator.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/docks/devicelistsettings.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

// The id assistant in the window (Device → Assign device ids…), "Add all found" from a bus scan,
// and the line's ids and names kept with the connection settings.
class TestIdAssistant : public QObject
{
    Q_OBJECT

    static void click(QWidget *parent, const char *name)
    {
        auto *b = parent->findChild<QPushButton *>(QLatin1String(name));
        QVERIFY2(b, name);
        QVERIFY2(b->isEnabled(), name);
        b->click();
    }
    static void waitWhileWorking(IdAssistantDialog *d)
    {
        QTRY_VERIFY_WITH_TIMEOUT(d->assigner()->state() != IdAssigner::State::Working, 30000);
    }
    static bool startRtu(SimHost &host, const QList<int> &ids)
    {
        SimOptions o;
        o.rtu = true;
        o.ids = ids;
        o.answerDelayMs = 5;
        QString error;
        const bool ok = host.start(o, &error);
        if (!ok)
            qWarning() << error;
        return ok;
    }
    static LinkSettings line(const SimHost &host)
    {
        LinkSettings s;
        s.portName = host.rtuPath();
        s.timeoutMs = 150;
        s.retries = 0;
        s.answerDelayMs = 5; // the simulator's (startRtu): sooner answers would be stale ones
        return s;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
    }
    void init() { QSettings().clear(); }
    void cleanup() { QSettings().clear(); }

    void theAssistantNamesEachControllerAndRefusesACollision()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session, {1, 201, 202, 203});
        MainWindow window(&session);
        window.show();
        test::connectToSimulator(session);
        SimHost *host = test::simHost(session);

        QAction *action = WindowProbe(window).action(QStringLiteral("assignIds"));
        QVERIFY(action);
        QVERIFY(!action->text().isEmpty());
        action->trigger();
        auto *dialog = window.findChild<IdAssistantDialog *>();
        QVERIFY(dialog && dialog->isVisible());
        QVERIFY(!dialog->isModal());

        click(dialog, "start");
        QCOMPARE(dialog->assigner()->state(), IdAssigner::State::Waiting);
        QVERIFY(dialog->statusText().contains(QStringLiteral("It gets id 2")));
        dialog->findChild<QLineEdit *>(QStringLiteral("name"))->setText(QStringLiteral("X table"));
        click(dialog, "next");
        waitWhileWorking(dialog);
        QVERIFY2(dialog->assigner()->state() == IdAssigner::State::Waiting,
                 qPrintable(dialog->statusText()));
        QCOMPARE(dialog->rowCount(), 1);
        QCOMPARE(dialog->rowTexts(0), (QStringList{"2", "X table"}));
        QCOMPARE(host->devices().at(0)->deviceId(), 2);
        // On the window's device list, with its name, and the list is shown.
        DeviceListDock *dock = WindowProbe(window).deviceListDock();
        QVERIFY(dock->isVisible());
        QCOMPARE(dock->nameOf(2), QStringLiteral("X table"));
        QCOMPARE(session.line()->deviceIds(), QList<int>{2});

        // Two new controllers connected at once: refused in words, nothing written.
        QVERIFY(host->devices().at(1)->setValue(QStringLiteral("device.id"), 1));
        QVERIFY(host->devices().at(2)->setValue(QStringLiteral("device.id"), 1));
        click(dialog, "next");
        waitWhileWorking(dialog);
        QCOMPARE(dialog->assigner()->state(), IdAssigner::State::Collision);
        QVERIFY2(dialog->statusText().contains(QStringLiteral("Refused")) &&
                     dialog->statusText().contains(QStringLiteral("two or more controllers")),
                 qPrintable(dialog->statusText()));
        QCOMPARE(dialog->rowCount(), 1);
        QCOMPARE(host->devices().at(1)->deviceId(), 1);
        QCOMPARE(host->devices().at(2)->deviceId(), 1);

        // One taken away: Next goes on.
        QVERIFY(host->devices().at(2)->setValue(QStringLiteral("device.id"), 202));
        click(dialog, "next");
        waitWhileWorking(dialog);
        QVERIFY2(dialog->assigner()->state() == IdAssigner::State::Waiting,
                 qPrintable(dialog->statusText()));
        QCOMPARE(dialog->rowTexts(1), (QStringList{"3", ""}));

        // Closing finishes the run: the list holds both, the live status runs again.
        dialog->reject();
        QTRY_VERIFY_WITH_TIMEOUT(!dialog->isVisible(), 20000);
        QCOMPARE(dialog->assigner()->state(), IdAssigner::State::Finished);
        QCOMPARE(session.line()->deviceIds(), (QList<int>{2, 3}));
        QVERIFY(session.isLive());
        QCOMPARE(dock->table()->rowCount(), 2);
        QCOMPARE(dock->rowTexts(0).at(1), QStringLiteral("X table"));
        QTRY_COMPARE_WITH_TIMEOUT(dock->rowTexts(1).at(2), QStringLiteral("answering"), 15000);
    }

    void startNeedsAConnectionAndSaysSo()
    {
        DeviceSession session;
        IdAssistantDialog dialog(&session);
        dialog.show();
        QVERIFY(!dialog.findChild<QPushButton *>(QStringLiteral("start"))->isEnabled());
        QVERIFY(dialog.statusText().contains(QStringLiteral("Connect to the line first")));
        dialog.start();
        QCOMPARE(dialog.assigner()->state(), IdAssigner::State::Idle);
    }

    void addAllFoundAndTheListComesBackOnTheNextConnect()
    {
        SimHost host;
        QVERIFY(startRtu(host, {2, 3}));
        DeviceSession session;
        DeviceListDock dock(&session);
        BusScanDialog scan(&session, line(host));
        scan.setCheckedBauds({9600});
        scan.setIdRange(1, 4);
        scan.setProbeTimeoutMs(80);
        QVERIFY(!scan.findChild<QPushButton *>(QStringLiteral("addAll"))->isEnabled());
        QSignalSpy finished(scan.scanner(), &BusScanner::finished);
        scan.startScan();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(scan.foundCount(), 2);
        QSignalSpy added(&scan, &BusScanDialog::devicesAdded);
        click(&scan, "addAll");
        QCOMPARE(added.size(), 1);
        QCOMPARE(session.line()->deviceIds(), (QList<int>{2, 3}));
        QVERIFY2(scan.statusText().contains(QStringLiteral("Added to the device list: id 2,3")),
                 qPrintable(scan.statusText()));
        QCOMPARE(dock.table()->rowCount(), 2);
        // A second time adds nothing and says so.
        QVERIFY(scan.addAllFound().isEmpty());
        QVERIFY(scan.statusText().contains(QStringLiteral("on the device list already")));

        // Connected: the list and the names are kept with the connection settings.
        session.connection()->connectTo(scan.settingsFor(0));
        QTRY_VERIFY_WITH_TIMEOUT(session.connection()->isConnected(), 5000);
        dock.setName(3, QStringLiteral("Z axis"));
        const DeviceListSettings saved = DeviceListSettings::load();
        QCOMPARE(saved.line, QStringLiteral("serial:%1").arg(host.rtuPath()));
        QCOMPARE(saved.ids, (QList<int>{2, 3}));
        QCOMPARE(saved.names.value(3), QStringLiteral("Z axis"));
        session.connection()->disconnectFrom();

        // The next connect to this line restores them; another line does not get them.
        DeviceSession again;
        DeviceListDock dockAgain(&again);
        LinkSettings s = line(host);
        s.deviceId = 3;
        again.connection()->connectTo(s);
        QTRY_VERIFY_WITH_TIMEOUT(again.connection()->isConnected(), 5000);
        QCOMPARE(again.line()->deviceIds(), (QList<int>{2, 3}));
        QCOMPARE(dockAgain.nameOf(3), QStringLiteral("Z axis"));
        QCOMPARE(dockAgain.table()->rowCount(), 2);
        QTRY_COMPARE_WITH_TIMEOUT(dockAgain.rowTexts(0).at(2), QStringLiteral("answering"), 15000);
        again.connection()->disconnectFrom();

        SimHost other;
        QVERIFY(startRtu(other, {1}));
        DeviceSession elsewhere;
        DeviceListDock dockElsewhere(&elsewhere);
        elsewhere.connection()->connectTo(line(other));
        QTRY_VERIFY_WITH_TIMEOUT(elsewhere.connection()->isConnected(), 5000);
        QCOMPARE(elsewhere.line()->deviceIds(), QList<int>{1});
        elsewhere.connection()->disconnectFrom();
    }

    void addDeviceByIdRefusesBadIds()
    {
        DeviceSession session;
        DeviceListDock dock(&session);
        QVERIFY(dock.addDevice(4, QStringLiteral("feeder")));
        QCOMPARE(dock.nameOf(4), QStringLiteral("feeder"));
        QVERIFY(!dock.addDevice(4));
        QVERIFY(!dock.addDevice(0));
        QVERIFY(!dock.addDevice(256));
        QVERIFY(!session.line()->deviceIds().contains(0));
    }

    void savedSettingsRoundTrip()
    {
        DeviceListSettings s;
        s.line = QStringLiteral("tcp:10.0.0.5:502");
        s.ids = {5, 2, 9};
        s.names = {{2, QStringLiteral("Y")}, {9, QStringLiteral("Spindle 机")}, {7, "not listed"}};
        s.save();
        const DeviceListSettings back = DeviceListSettings::load();
        QCOMPARE(back.line, s.line);
        QCOMPARE(back.ids, s.ids); // in the order given
        QCOMPARE(back.names.size(), 2);
        QCOMPARE(back.names.value(9), QStringLiteral("Spindle 机"));
        QVERIFY(!back.names.contains(7));
        // Hand-edited nonsense is dropped whole, never half-used.
        QSettings().setValue(QStringLiteral("connection/deviceIds"), QStringLiteral("2,x,300"));
        QVERIFY(DeviceListSettings::load().ids.isEmpty());
        DeviceListSettings::clear();
        QVERIFY(DeviceListSettings::load().line.isEmpty());
    }

    // The assistant asks whether to save each id (yes by default): saved, it survives the next
    // power-off; not saved, the controller is back at id 1.
    void theAssistantAsksToSaveEachId_data()
    {
        QTest::addColumn<bool>("save");
        QTest::addColumn<int>("idAfter");
        QTest::newRow("saved") << true << 2;
        QTest::newRow("not saved") << false << 1;
    }
    void theAssistantAsksToSaveEachId()
    {
        QFETCH(bool, save);
        QFETCH(int, idAfter);
        DeviceSession session;
        test::useBuiltinSimulator(session, {1});
        MainWindow window(&session);
        window.show();
        test::connectToSimulator(session);
        SimDevice *sim = test::simHost(session)->device();
        WindowProbe(window).action(QStringLiteral("assignIds"))->trigger();
        auto *dialog = window.findChild<IdAssistantDialog *>();
        QVERIFY(dialog);
        auto *box = dialog->findChild<QCheckBox *>(QStringLiteral("saveToFlash"));
        QVERIFY(box && box->isEnabled() && !box->text().isEmpty());
        QVERIFY(box->isChecked());
        box->setChecked(save);
        click(dialog, "start");
        click(dialog, "next");
        waitWhileWorking(dialog);
        QVERIFY2(dialog->assigner()->state() == IdAssigner::State::Waiting,
                 qPrintable(dialog->statusText()));
        QVERIFY(!box->isEnabled()); // fixed for the run
        QCOMPARE(sim->deviceId(), 2);
        sim->powerCycle(1);
        QTRY_VERIFY_WITH_TIMEOUT(!sim->isPoweredOff(), 10000);
        QCOMPARE(sim->deviceId(), idAfter);
    }

    // Device → Reset the built-in simulator to factory: away from it, its flash forgotten.
    void theBuiltinSimulatorIsResetToFactory()
    {
        QTemporaryDir dir;
        DeviceSession session;
        auto sim = std::make_unique<BuiltinSimulator>();
        const QString flash = dir.filePath(QStringLiteral("sim/flash.json"));
        sim->setFlashPath(flash);
        session.setSimulator(std::move(sim));
        MainWindow window(&session);
        window.show();
        test::connectToSimulator(session);
        QVERIFY(test::simHost(session)->device()->setValue(QStringLiteral("motor1.speed"), 450));
        QVERIFY(test::simHost(session)->device()->command(QStringLiteral("save_to_flash")));
        QVERIFY(QFileInfo::exists(flash));

        QAction *reset = WindowProbe(window).action(QStringLiteral("resetSimulator"));
        QVERIFY(reset && reset->isEnabled() && !reset->text().isEmpty());
        reset->trigger();
        QCOMPARE(session.connection()->linkState(), SessionConnection::LinkState::Disconnected);
        QVERIFY(!QFileInfo::exists(flash));
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        session.connection()->connectSimulator();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 30000);
        const qint64 factory =
            FactoryValues::writable(session.map()).value(QStringLiteral("motor1.speed"));
        QVERIFY(factory != 450);
        QCOMPARE(test::simHost(session)->device()->value(QStringLiteral("motor1.speed")),
                 std::optional<qint64>(factory));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestIdAssistant, Gui)
#include "tst_idassistant.moc"
