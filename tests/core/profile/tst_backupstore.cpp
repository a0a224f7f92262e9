#include "map/registermap.h"
#include "profile/backupstore.h"
#include "profile/profilefile.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

const QDateTime kBackupT0(QDate(2024, 6, 1), QTime(9, 30, 15, 250), Qt::UTC);

// The settings of machine A as a controller returns them, link included.
QHash<QString, qint64> controller()
{
    const auto r =
        ProfileFile::load(sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json")),
                          RegisterMap::builtin());
    if (!r.ok())
        qFatal("machine-a.json");
    QHash<QString, qint64> values;
    for (auto it = r.profile->values.cbegin(); it != r.profile->values.cend(); ++it)
        values.insert(it.key(), it.value());
    values.insert("device.id", 3);
    values.insert("device.baud", 19200);
    values.insert("motor1.position", 1234); // status: never in a backup
    return values;
}

} // namespace

// Automatic backups: written before a risky operation, bounded, listed, loaded for a restore.
class TestBackupStore : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void defaultDirectoryIsTheWindowsDataLocation()
    {
        QVERIFY2(BackupStore::defaultDirectory().endsWith("/StepCom/stepcom/backups"),
                 qPrintable(BackupStore::defaultDirectory()));
    }

    void writtenWithWhatFollowed()
    {
        QTemporaryDir dir;
        const QString folder = dir.filePath("data/backups"); // created on first use
        const BackupStore store(folder);
        const auto saved =
            store.save(RegisterMap::builtin(), controller(), BackupStore::Operation::FactoryReset,
                       "/dev/ttyUSB0 · 19200 8N1 · id 3", kBackupT0);
        QVERIFY2(saved.ok(), qPrintable(saved.error));
        QCOMPARE(QFileInfo(saved.path).fileName(),
                 QStringLiteral("backup-20240601-093015-250-factory-reset.json"));
        const auto r = BackupStore::load(saved.path, RegisterMap::builtin());
        QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
        QCOMPARE(r.profile->backupOperation, QStringLiteral("factory-reset"));
        QCOMPARE(r.profile->backupDevice, QStringLiteral("/dev/ttyUSB0 · 19200 8N1 · id 3"));
        QCOMPARE(r.profile->created, QDateTime(QDate(2024, 6, 1), QTime(9, 30, 15), Qt::UTC));
        QCOMPARE(r.profile->deviceId, 3);
        QCOMPARE(r.profile->name, QStringLiteral("Backup before factory reset"));
        // Everything a restore needs, the link included; no status values.
        QHash<QString, qint64> expected = controller();
        expected.remove("motor1.position");
        QCOMPARE(r.profile->values.size(), expected.size());
        for (auto it = expected.cbegin(); it != expected.cend(); ++it)
            QCOMPARE(r.profile->values.value(it.key()), it.value());
        // Two in the same millisecond do not overwrite each other.
        const auto again = store.save(RegisterMap::builtin(), controller(),
                                      BackupStore::Operation::FactoryReset, {}, kBackupT0);
        QVERIFY(again.ok());
        QVERIFY(again.path.endsWith("-factory-reset-2.json"));
    }

    void boundedListedNewestFirst()
    {
        QTemporaryDir dir;
        const BackupStore store(dir.path(), 3);
        const QList<BackupStore::Operation> ops{
            BackupStore::Operation::Apply, BackupStore::Operation::SaveToFlash,
            BackupStore::Operation::DeviceId, BackupStore::Operation::Baud,
            BackupStore::Operation::Apply};
        QStringList paths;
        QStringList removed;
        for (int i = 0; i < ops.size(); ++i) {
            const auto s = store.save(RegisterMap::builtin(), controller(), ops.at(i),
                                      QStringLiteral("link %1").arg(i), kBackupT0.addSecs(60 * i));
            QVERIFY2(s.ok(), qPrintable(s.error));
            paths << s.path;
            removed << s.removed;
        }
        QCOMPARE(removed, paths.mid(0, 2)); // the two oldest went
        QFile junk(dir.filePath("backup-20240601-100000-000-apply.json"));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("{");
        junk.close();
        QFile other(dir.filePath("notes.txt")); // not a backup: neither listed nor removed
        QVERIFY(other.open(QIODevice::WriteOnly));
        other.close();

        const QList<BackupEntry> list = store.list(RegisterMap::builtin());
        QCOMPARE(list.size(), 4);
        QVERIFY(!list.at(0).error.isEmpty()); // the broken one, newest by its name
        QVERIFY2(list.at(0).error.contains("not valid JSON"), qPrintable(list.at(0).error));
        QCOMPARE(list.at(0).time, QDateTime(QDate(2024, 6, 1), QTime(10, 0), Qt::UTC));
        QCOMPARE(list.at(1).path, paths.at(4));
        QCOMPARE(list.at(1).operation, QStringLiteral("apply"));
        QCOMPARE(list.at(1).device, QStringLiteral("link 4"));
        QCOMPARE(list.at(1).deviceId, 3);
        QCOMPARE(list.at(1).time, QDateTime(QDate(2024, 6, 1), QTime(9, 34, 15), Qt::UTC));
        QCOMPARE(list.at(2).operation, QStringLiteral("baud"));
        QCOMPARE(list.at(3).operation, QStringLiteral("device-id"));
        QCOMPARE(BackupStore::operationLabel(list.at(3).operation),
                 QStringLiteral("device id change"));
        QVERIFY(QFile::exists(dir.filePath("notes.txt")));

        // The next save keeps three: the broken file counts too, and is the newest by name, so
        // the oldest good ones go first.
        const auto s = store.save(RegisterMap::builtin(), controller(),
                                  BackupStore::Operation::Apply, {}, kBackupT0.addSecs(3600));
        QVERIFY(s.ok());
        QCOMPARE(s.removed, (QStringList{paths.at(2), paths.at(3)}));
    }

    void cannotWriteSaysWhy()
    {
        QTemporaryDir dir;
        QFile blocker(dir.filePath("backups"));
        QVERIFY(blocker.open(QIODevice::WriteOnly)); // a file where the folder should be
        blocker.close();
        const BackupStore store(dir.filePath("backups"));
        const auto s = store.save(RegisterMap::builtin(), controller(),
                                  BackupStore::Operation::Apply, {}, kBackupT0);
        QVERIFY(!s.ok());
        QVERIFY2(s.error.contains("cannot create the backup folder"), qPrintable(s.error));
        const auto empty =
            BackupStore(dir.filePath("b2"))
                .save(RegisterMap::builtin(), {}, BackupStore::Operation::Apply, {}, kBackupT0);
        QVERIFY(empty.error.contains("no settings to back up"));
        QVERIFY(QDir(dir.filePath("b2")).entryList(QDir::Files).isEmpty());
    }

    void backupMetadataIsChecked()
    {
        QTemporaryDir dir;
        const auto s = BackupStore(dir.path())
                           .save(RegisterMap::builtin(), controller(),
                                 BackupStore::Operation::Apply, "x", kBackupT0);
        QFile f(s.path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray bytes = f.readAll();
        QVERIFY(bytes.contains("\"schema\": 2"));
        bytes.replace("\"operation\": \"apply\"", "\"operation\": \"format-disk\"");
        const auto r = ProfileFile::parse(bytes, RegisterMap::builtin());
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.join('\n').contains(
                     "\"backup\" must be {\"operation\": one of apply, factory-reset"),
                 qPrintable(r.errors.join('\n')));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBackupStore, Guiless)
#include "tst_backupstore.moc"
