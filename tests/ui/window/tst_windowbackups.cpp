#include "base/backupguard.h"
#include "bus/modbuslink.h"
#include "dialogs/backupsdialog.h"
#include "dialogs/profilecomparedialog.h"
#include "profile/backupstore.h"
#include "profile/profilefile.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "window/profileactions.h"

#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <memory>

using namespace stepcom;

// The window's automatic backups: one before each apply, factory reset, save to flash and id
// change, holding what the controller held; none, and nothing done, when it cannot be saved;
// File → Backups lists them and restores one through the compare and apply dialog.
class TestWindowBackups : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    std::unique_ptr<QWidget> window;
    std::unique_ptr<DeviceSession> session;
    BackupGuard *guard = nullptr;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    QString backups() const { return dir.filePath(QStringLiteral("backups")); }
    QStringList operations() const
    {
        QStringList ops;
        for (const BackupEntry &e : BackupStore(backups()).list(session->map()))
            ops.prepend(e.operation);
        return ops;
    }
    void runCommand(std::function<void()> start, const QString &key, bool expect = true)
    {
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        start();
        QTRY_VERIFY_WITH_TIMEOUT(!done.isEmpty() && done.last().at(0).toString() == key, 10000);
        QCOMPARE(done.last().at(1).toBool(), expect);
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init()
    {
        QDir(backups()).removeRecursively();
        window = std::make_unique<QWidget>();
        session = std::make_unique<DeviceSession>();
        test::connectToSimulator(*session);
        guard = new BackupGuard(session.get(), window.get());
        guard->setDirectory(backups());
    }
    void cleanup()
    {
        window.reset();
        session.reset();
    }

    void backupBeforeEachRiskyOperation()
    {
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 450));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        runCommand([this] { session->saveToFlash(); }, QStringLiteral("save_to_flash"));
        runCommand([this] { session->factoryReset(); }, QStringLiteral("factory_reset"));
        QTRY_COMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 300);
        // The window reads everything after a reset: the store shows the factory values.
        QTRY_COMPARE(session->parameters()->store()->deviceValue(QStringLiteral("motor1.speed")),
                     std::optional<qint64>(300));
        QSignalSpy linked(session->line(), &SessionLine::linkChanged);
        session->line()->changeLink(7, session->connection()->settings().baud);
        QTRY_VERIFY_WITH_TIMEOUT(!linked.isEmpty(), 10000);
        QCOMPARE(sim()->deviceId(), 7);
        QCOMPARE(operations(),
                 (QStringList{QStringLiteral("save-to-flash"), QStringLiteral("factory-reset"),
                              QStringLiteral("device-id")}));
        // The factory reset's backup holds the speed from before the reset.
        const QList<BackupEntry> list = BackupStore(backups()).list(session->map());
        const auto reset = BackupStore::load(list.at(1).path, session->map());
        QVERIFY(reset.ok());
        QCOMPARE(reset.profile->values.value(QStringLiteral("motor1.speed")), 450);

        // File → Backups lists them; restoring one goes through compare and apply, which backs
        // up the settings it replaces first.
        ProfileActions actions(session.get(), window.get());
        actions.setBackupDirectory(backups());
        actions.showBackups();
        BackupsDialog *dialog = actions.backupsDialog();
        QVERIFY(dialog);
        QCOMPARE(dialog->list()->topLevelItemCount(), 3);
        dialog->list()->setCurrentItem(dialog->list()->topLevelItem(1)); // the factory reset's
        dialog->restoreButton()->click();
        ProfileCompareDialog *compare = actions.compareDialog();
        QVERIFY(compare);
        QVERIFY(compare->checkedKeys().contains(QStringLiteral("motor1.speed")));
        QSignalSpy applied(compare, &ProfileCompareDialog::applied);
        compare->applyButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!applied.isEmpty(), 10000);
        QVERIFY(applied.first().at(0).toBool());
        QCOMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 450);
        QCOMPARE(operations().last(), QStringLiteral("apply"));
    }

    void nothingIsDoneWithoutABackup()
    {
        // A file where the folder should be: no backup can be saved.
        QFile blocker(dir.filePath(QStringLiteral("blocked")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        guard->setDirectory(dir.filePath(QStringLiteral("blocked/backups")));
        QSignalSpy dispatched(SessionInternals::link(*session), &ModbusLink::dispatched);
        QSignalSpy messages(session.get(), &DeviceSession::message);
        runCommand([this] { session->factoryReset(); }, QStringLiteral("factory_reset"), false);
        for (const QList<QVariant> &args : dispatched)
            QVERIFY(args.at(1).value<Request>().what != QLatin1String("factory_reset"));
        bool said = false;
        for (const QList<QVariant> &args : messages)
            said = said || args.at(1).toString().contains(QStringLiteral("No backup"));
        QVERIFY(said);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestWindowBackups, Gui)
#include "tst_windowbackups.moc"
