#include "commissioning/checklistfile.h"
#include "map/registermap.h"
#include "profile/backupstore.h"
#include "profile/profilefile.h"
#include "programrun.h"
#include "scripteddevice.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

int writeCount(const QList<QByteArray> &requests)
{
    int n = 0;
    for (const QByteArray &r : requests)
        n += (quint8(r.at(1)) == 0x06 || quint8(r.at(1)) == 0x10) ? 1 : 0;
    return n;
}

} // namespace

// stepcomctl and commissioning: a backup before apply (--no-backup), the report with the
// checklist kept beside the profile.
class TestCtlCommissioning : public QObject
{
    Q_OBJECT
    std::unique_ptr<ScriptedDevice> device;
    QTemporaryDir dir;

    ProgramRun ctl(const QStringList &args, const QStringList &environment = {})
    {
        ProgramOptions options;
        options.environment = environment;
        const QStringList link{QStringLiteral("--port"),    device->clientPath(),
                               QStringLiteral("--timeout"), QStringLiteral("300"),
                               QStringLiteral("--retries"), QStringLiteral("0")};
        return runProgram(QStringLiteral("stepcomctl"), link + args, options);
    }
    QString machineA() const
    {
        return sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json"));
    }
    QString data() const { return dir.filePath(QStringLiteral("data")); }
    QString backups() const { return data() + QStringLiteral("/StepCom/stepcom/backups"); }

private Q_SLOTS:
    void init()
    {
        device = std::make_unique<ScriptedDevice>();
        QString error;
        QVERIFY2(device->open(&error), qPrintable(error));
        device->useRegisterDevice();
        const auto r = ProfileFile::load(machineA(), RegisterMap::builtin());
        QVERIFY(r.ok());
        for (auto it = r.profile->values.cbegin(); it != r.profile->values.cend(); ++it) {
            const Parameter *p = RegisterMap::builtin().find(it.key());
            const auto words = p->encode(it.value());
            for (int i = 0; i < words.size(); ++i)
                device->registers[p->address + i] = words.at(i);
        }
        device->registers[211] = 1;
        device->registers[212] = 9600;
        qputenv("XDG_DATA_HOME", QFile::encodeName(data()));
        QDir(backups()).removeRecursively();
    }

    void applySavesABackupFirst()
    {
        device->registers[5] = 450; // motor1.speed differs from the profile's 300
        const ProgramRun r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        const QList<BackupEntry> list = BackupStore(backups()).list(RegisterMap::builtin());
        QCOMPARE(list.size(), 1);
        QVERIFY2(r.out.contains(QStringLiteral("backup of the controller's settings: ") +
                                list.first().path),
                 qPrintable(r.out));
        QCOMPARE(list.first().operation, QStringLiteral("apply"));
        QVERIFY2(list.first().device.contains(device->clientPath()),
                 qPrintable(list.first().device));
        // The backup holds what the controller held before: 450, not the profile's 300.
        const auto backup = BackupStore::load(list.first().path, RegisterMap::builtin());
        QVERIFY(backup.ok());
        QCOMPARE(backup.profile->values.value(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(backup.profile->values.value(QStringLiteral("device.id")), 1);
        QCOMPARE(device->registers[5], quint16(300));
    }

    // The session's risk guard, as in the window: a backup before the write and another
    // before the save to flash.
    void applyWithSaveToFlashBacksUpBeforeEach()
    {
        device->registers[5] = 450;
        const ProgramRun r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes"),
                                  QStringLiteral("--save-to-flash")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QStringList operations;
        for (const BackupEntry &e : BackupStore(backups()).list(RegisterMap::builtin()))
            operations << e.operation;
        operations.sort();
        QCOMPARE(operations, (QStringList{"apply", "save-to-flash"}));
        QVERIFY(r.out.indexOf(QStringLiteral("backup of the controller's settings")) <
                r.out.indexOf(QStringLiteral("(written, verified)")));
        QVERIFY(r.out.contains(QStringLiteral("saved to flash")));
    }

    void noBackupWritesNone()
    {
        device->registers[5] = 450;
        const ProgramRun r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes"),
                                  QStringLiteral("--no-backup")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QVERIFY(!r.out.contains(QStringLiteral("backup")));
        QVERIFY(!QDir(backups()).exists() || QDir(backups()).entryList(QDir::Files).isEmpty());
        QCOMPARE(device->registers[5], quint16(300));
    }

    void noApplyWithoutItsBackup()
    {
        device->registers[5] = 450;
        QFile blocker(dir.filePath(QStringLiteral("blocker")));
        QVERIFY(blocker.open(QIODevice::WriteOnly)); // a file where the data folder would be
        blocker.close();
        const ProgramRun r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes")},
                                 {QStringLiteral("XDG_DATA_HOME=") + blocker.fileName()});
        QCOMPARE(r.exitCode, 1); // not done (the table's 1), not a usage error
        QVERIFY2(r.err.contains(QStringLiteral("no backup of the controller's settings could be "
                                               "saved")) &&
                     r.err.contains(QStringLiteral("--no-backup")),
                 qPrintable(r.err));
        QCOMPARE(writeCount(device->requests()), 0);
        QCOMPARE(device->registers[5], quint16(450));
    }

    void reportIncludesTheChecklist()
    {
        const QString profile = dir.filePath(QStringLiteral("machine-c.json"));
        QFile::remove(profile);
        QVERIFY(QFile::copy(machineA(), profile));
        Checklist c = Checklist::forMap(RegisterMap::builtin());
        QCOMPARE(
            c.record(QStringLiteral("motor1.calibration"), StepResult::Passed,
                     {{QStringLiteral("measured"), QStringLiteral("99.20"), QStringLiteral("mm")}}),
            QString());
        QCOMPARE(ChecklistFile::save(ChecklistFile::pathFor(profile), c), QString());
        const QString html = dir.filePath(QStringLiteral("c.html"));
        ProgramRun r =
            runProgram(QStringLiteral("stepcomctl"),
                       {QStringLiteral("report"), QStringLiteral("--from"), profile, html});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("with the commissioning checklist "
                                               "machine-c.checklist.json: 1 of 20 steps passed")),
                 qPrintable(r.out));
        QFile f(html);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY(text.contains(QStringLiteral("Measured distance: 99.20 mm")));
        QVERIFY(text.contains(QStringLiteral("Settings fingerprint")));

        // A broken checklist: no certificate without its results.
        QFile bad(ChecklistFile::pathFor(profile));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"format\": \"stepcom-checklist\"");
        bad.close();
        const QString pdf = dir.filePath(QStringLiteral("c.pdf"));
        r = runProgram(QStringLiteral("stepcomctl"),
                       {QStringLiteral("report"), QStringLiteral("--from"), profile, pdf});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(
            r.err.contains(QStringLiteral("machine-c.checklist.json: not valid JSON")) &&
                r.err.contains(QStringLiteral("the checklist beside the profile cannot be read")),
            qPrintable(r.err));
        QVERIFY(!QFile::exists(pdf));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlCommissioning, Guiless)
#include "tst_ctlcommissioning.moc"
