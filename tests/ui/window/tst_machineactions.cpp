#include "base/backupguard.h"
#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "dialogs/applytodevicesdialog.h"
#include "profile/profilefile.h"
#include "profile/profilerollout.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/devicelistdock.h"
#include "window/machineactions.h"

#include <QAction>
#include <QDate>
#include <QDir>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

using namespace stepcom;

// The File menu's actions for every device of the line, against three simulated controllers:
// one profile applied to two of them, every device saved into a folder, the machine's report.
class TestMachineActions : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> window;
    MachineActions *actions = nullptr;
    DeviceListDock *list = nullptr;
    BackupGuard *guard = nullptr;
    QTemporaryDir dir;
    QStringList messages;

    SimHost *host() const { return test::simHost(*session); }
    qint64 simValue(int id, const QString &key) const
    {
        return host()->deviceAt(id)->value(key).value_or(-1);
    }
    QList<int> writeFrameIds() const
    {
        QList<int> ids;
        for (const TrafficEntry &e : session->connection()->traffic()->entries()) {
            if (e.direction == TrafficEntry::Direction::Sent && e.bytes.size() > 1 &&
                (quint8(e.bytes.at(1)) == 0x06 || quint8(e.bytes.at(1)) == 0x10))
                ids << quint8(e.bytes.at(0));
        }
        return ids;
    }

    // Three devices on the list, the second called "Y axis" by the user.
    void connectLine()
    {
        session->line()->setDeviceIds({1, 2, 3});
        test::connectToSimulator(*session);
        QTRY_COMPARE(list->table()->rowCount(), 3);
        list->table()->item(1, 1)->setText(QStringLiteral("Y axis"));
        QCOMPARE(list->nameOf(2), QStringLiteral("Y axis"));
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        window = std::make_unique<QWidget>();
        actions = new MachineActions(session.get(), window.get());
        auto *menu = new QMenu(window.get());
        list = new DeviceListDock(session.get(), window.get());
        actions->addTo(menu, [this] { return list; });
        // The window's backups: the session's risk guard, which the rollout goes through.
        guard = new BackupGuard(session.get(), window.get());
        guard->setDirectory(dir.filePath(QStringLiteral("backups")));
        messages.clear();
        connect(actions, &MachineActions::finished, this,
                [this](bool, const QString &text) { messages << text; });
        test::useBuiltinSimulator(*session, {1, 2, 3});
    }
    void cleanup()
    {
        window.reset();
        session.reset();
    }

    void theActionsNeedSeveralDevices()
    {
        test::connectToSimulator(*session);
        QVERIFY(!actions->applyAction()->isEnabled());
        QVERIFY(!actions->reportAction()->isEnabled());
        session->line()->setDeviceIds({1, 2, 3});
        QTRY_VERIFY(actions->applyAction()->isEnabled());
        QVERIFY(actions->dumpAction()->isEnabled());
        QVERIFY(actions->reportAction()->isEnabled());
    }

    void aProfileGoesToTheTickedDevicesOnly()
    {
        connectLine();
        const QString speed = QStringLiteral("motor1.speed");
        const QString distance = QStringLiteral("motor1.move_distance");
        QHash<QString, qint64> values;
        for (const Parameter *p : Profile::profileParameters(session->map(), false))
            values.insert(p->key, simValue(1, p->key));
        const qint64 speed1 = values.value(speed);
        const qint64 distance1 = values.value(distance);
        values[speed] += 5;
        values[distance] += 9;
        const QString path = dir.filePath(QStringLiteral("axis.json"));
        QVERIFY(ProfileFile::save(path, Profile::fromValues(session->map(), values, false),
                                  session->map())
                    .isEmpty());
        QVERIFY(actions->applyProfileFile(path));
        ApplyToDevicesDialog *dialog = actions->applyDialog();
        QVERIFY(dialog && dialog->isVisible() && !dialog->isModal());
        QCOMPARE(dialog->checkedDevices(), (QList<int>{1, 2, 3}));
        dialog->setDeviceChecked(1, false);
        QVERIFY(!dialog->writeButton()->isEnabled()); // nothing compared: nothing to confirm
        session->connection()->traffic()->clear();
        dialog->compareButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(dialog->rows()->topLevelItemCount(), 2, 15000);
        QVERIFY(writeFrameIds().isEmpty());
        QCOMPARE(dialog->writeButton()->text(), QStringLiteral("&Write 4 value(s) to 2 device(s)"));
        // Device 3 keeps its distance: that row is unchecked.
        QTreeWidgetItem *three = dialog->rows()->topLevelItem(1);
        QCOMPARE(three->childCount(), 2);
        for (int c = 0; c < three->childCount(); ++c) {
            if (three->child(c)->text(0).contains(distance))
                three->child(c)->setCheckState(0, Qt::Unchecked);
        }
        QCOMPARE(dialog->writeButton()->text(), QStringLiteral("&Write 3 value(s) to 2 device(s)"));
        QSignalSpy finished(dialog->rollout(), &ProfileRollout::finished);
        dialog->writeButton()->click();
        QVERIFY2(!dialog->close(), "open until every device has its result");
        QVERIFY(dialog->isVisible());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(dialog->resultLines(),
                 (QStringList{QStringLiteral("id 2 (Y axis): written and verified, 2 value(s)"),
                              QStringLiteral("id 3: written and verified, 1 value(s)")}));
        QVERIFY(dialog->summary()->text().contains(QStringLiteral("id 3: written and verified")));
        QVERIFY(!dialog->writeButton()->isEnabled()); // once
        const QList<int> ids = writeFrameIds();
        QVERIFY(!ids.contains(1));
        QVERIFY(ids.contains(2) && ids.contains(3));
        QCOMPARE(simValue(1, speed), speed1);
        QCOMPARE(simValue(2, speed), speed1 + 5);
        QCOMPARE(simValue(2, distance), distance1 + 9);
        QCOMPARE(simValue(3, speed), speed1 + 5);
        QCOMPARE(simValue(3, distance), distance1);
        QVERIFY(messages.contains(QStringLiteral("id 3: written and verified, 1 value(s)")));
        // A backup of each device written, before it was written.
        QCOMPARE(QDir(dir.filePath(QStringLiteral("backups"))).entryList(QDir::Files).size(), 2);
    }

    void everyDeviceIsSavedIntoOneFolder()
    {
        connectLine();
        const QString folder = dir.filePath(QStringLiteral("line"));
        QVERIFY(QDir().mkpath(folder));
        actions->dumpIntoFolder(folder);
        QVERIFY(!actions->dumpAction()->isEnabled()); // one at a time
        QTRY_COMPARE_WITH_TIMEOUT(QDir(folder).entryList(QDir::Files).size(), 3, 15000);
        const QString day = QDate::currentDate().toString(Qt::ISODate);
        QVERIFY(QFileInfo::exists(
            QDir(folder).filePath(QStringLiteral("id2 Y axis %1.json").arg(day))));
        QTRY_VERIFY(actions->dumpAction()->isEnabled());
        const ProfileParseResult p = ProfileFile::load(
            QDir(folder).filePath(QStringLiteral("id3 %1.json").arg(day)), session->map());
        QVERIFY(p.ok());
        QCOMPARE(p.profile->values.value(QStringLiteral("device.id")), 3);
        // A folder that is not there: said, nothing read.
        messages.clear();
        actions->dumpIntoFolder(dir.filePath(QStringLiteral("missing")));
        QVERIFY(messages.last().contains(QStringLiteral("no such folder")));
    }

    void theMachineReportHasEveryDevice()
    {
        connectLine();
        const QString path = dir.filePath(QStringLiteral("machine.html"));
        actions->reportFile(path, QStringLiteral("Mill 7"), QStringLiteral("hall 2"));
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(path), 20000);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString html = QString::fromUtf8(f.readAll());
        QVERIFY(html.contains(QStringLiteral(">Controller id 1</h1>")));
        QVERIFY(html.contains(QStringLiteral(">Controller id 2: Y axis</h1>")));
        QVERIFY(html.contains(QStringLiteral(">Controller id 3</h1>")));
        QVERIFY(html.contains(QStringLiteral("hall 2")));
        QVERIFY(messages.last().startsWith(QStringLiteral("Commissioning report of 3 device(s)")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestMachineActions, Gui)
#include "tst_machineactions.moc"
