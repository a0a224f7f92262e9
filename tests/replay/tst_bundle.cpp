// The support bundle (issue 26): what goes in (the logs of the last days, the profile and its
// checklist, the settings, versions and the serial adapters, a README naming it all), read
// back, and replayed by stepcomctl.
#include "logbuilder.h"
#include "programrun.h"
#include "support/supportbundle.h"

#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

bool writeFile(const QString &path, const QByteArray &content)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(content) == content.size();
}

QByteArray readEntry(const QString &zip, const QString &entry, const QTemporaryDir &dir)
{
    QString error;
    QFile f(SupportBundle::extract(zip, entry, dir.path(), &error));
    if (!f.open(QIODevice::ReadOnly))
        qWarning("%s", qPrintable(error));
    return f.readAll();
}

} // namespace

class TestBundle : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    BundleInput input;

private Q_SLOTS:
    void initTestCase()
    {
        // Logs of today and of a month ago, a profile with its checklist, a settings file and
        // an adapter's by-id link, in the test's own folder.
        input.now = QDateTime(QDate(2026, 11, 24), QTime(12, 0));
        input.logDirectory = dir.filePath(QStringLiteral("logs"));
        input.days = 7;
        LogBuilder b;
        b.header();
        b.read(1, 0, {180, 8});
        b.write(1, 0, {90});
        const QString recent = input.logDirectory + QStringLiteral("/stepcom-20261124-1.log");
        const QString old = input.logDirectory + QStringLiteral("/stepcom-20261020-1.log");
        QVERIFY(writeFile(recent, b.text.toUtf8()));
        QVERIFY(writeFile(old, b.text.toUtf8()));
        for (const auto &[path, when] : {std::pair{recent, input.now.addSecs(-3600)},
                                         std::pair{old, input.now.addDays(-35)}}) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadWrite));
            QVERIFY(f.setFileTime(when, QFileDevice::FileModificationTime));
        }
        input.profilePath = dir.filePath(QStringLiteral("machine-a.json"));
        QVERIFY(writeFile(input.profilePath, "{}"));
        QVERIFY(writeFile(dir.filePath(QStringLiteral("machine-a.checklist.json")), "{}"));
        input.settingsFiles = {dir.filePath(QStringLiteral("stepcom.conf"))};
        QVERIFY(writeFile(input.settingsFiles.first(), "[General]\nlanguage=en\n"));
        input.serialByIdDirectory = dir.filePath(QStringLiteral("by-id"));
        QVERIFY(QDir().mkpath(input.serialByIdDirectory));
        QVERIFY(QFile::link(QStringLiteral("/dev/ttyUSB0"),
                            input.serialByIdDirectory +
                                QStringLiteral("/usb-FTDI_FT232R_USB_UART_A10K1234-if00-port0")));
    }

    void holdsWhatItsReadmeSays()
    {
        const QString zip = dir.filePath(QStringLiteral("bundle.zip"));
        QStringList contents;
        QString error;
        QVERIFY2(SupportBundle::create(zip, input, &contents, &error), qPrintable(error));
        QCOMPARE(contents,
                 (QStringList{"README.txt", "system.txt", "logs/stepcom-20261124-1.log",
                              "profile/machine-a.json", "profile/machine-a.checklist.json",
                              "settings/stepcom.conf"}));
        QCOMPARE(SupportBundle::logs(zip, &error), QStringList{"logs/stepcom-20261124-1.log"});
        QTemporaryDir out;
        const QString readme = QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out));
        for (const QString &name : contents.mid(1))
            QVERIFY2(readme.contains(name), qPrintable(readme));
        const QString system = QString::fromUtf8(readEntry(zip, QStringLiteral("system.txt"), out));
        QVERIFY(system.contains(QStringLiteral("Qt: %1").arg(QLatin1String(qVersion()))));
        QVERIFY(system.contains(QStringLiteral("StepCom: %1").arg(QLatin1String(STEPCOM_VERSION))));
        QVERIFY2(system.contains(
                     QLatin1String("usb-FTDI_FT232R_USB_UART_A10K1234-if00-port0 -> /dev/ttyUSB0")),
                 qPrintable(system));
        QCOMPARE(readEntry(zip, QStringLiteral("settings/stepcom.conf"), out),
                 QByteArray("[General]\nlanguage=en\n"));
    }

    void notABundleIsSaid()
    {
        QString error;
        QVERIFY(SupportBundle::logs(input.profilePath, &error).isEmpty());
        QVERIFY2(error.contains(QLatin1String("is not a zip file")), qPrintable(error));
        BundleInput missing = input;
        missing.profilePath = dir.filePath(QStringLiteral("gone.json"));
        QVERIFY(!SupportBundle::create(dir.filePath(QStringLiteral("x.zip")), missing, nullptr,
                                       &error));
        QVERIFY2(error.contains(QLatin1String("gone.json does not exist")), qPrintable(error));
    }

    // stepcomctl bundle takes the window's logs and settings; replay opens the bundle.
    void stepcomctlMakesAndReplaysABundle()
    {
        const QString logs = SupportBundle::defaultLogDirectory();
        QVERIFY2(
            logs.startsWith(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)),
            qPrintable(logs));
        QVERIFY(QDir().mkpath(logs));
        QFile::remove(logs + QStringLiteral("/stepcom-20261124-1.log"));
        QVERIFY(QFile::copy(input.logDirectory + QStringLiteral("/stepcom-20261124-1.log"),
                            logs + QStringLiteral("/stepcom-20261124-1.log")));
        const QString zip = dir.filePath(QStringLiteral("ctl.zip"));
        const ProgramRun made =
            runProgram(QStringLiteral("stepcomctl"),
                       {"bundle", zip, "--days", "3650", "--profile", input.profilePath});
        QVERIFY2(made.exitCode == 0, qPrintable(made.err));
        QVERIFY2(made.out.contains(QLatin1String("logs/stepcom-20261124-1.log")),
                 qPrintable(made.out));
        QVERIFY(made.out.contains(QLatin1String("profile/machine-a.json")));
        const ProgramRun replayed =
            runProgram(QStringLiteral("stepcomctl"), {"replay", zip, "--events"});
        QVERIFY2(replayed.exitCode == 0, qPrintable(replayed.err));
        QVERIFY2(replayed.err.contains(QLatin1String("replaying logs/stepcom-20261124-1.log")),
                 qPrintable(replayed.err));
        QVERIFY2(replayed.out.contains(QLatin1String("write")) &&
                     replayed.out.contains(QStringLiteral("motor1.step_angle 1.80 ° → 0.90 °")),
                 qPrintable(replayed.out));
        const ProgramRun wrongEntry = runProgram(
            QStringLiteral("stepcomctl"), {"replay", zip, "--entry", "nope.log", "--events"});
        QCOMPARE(wrongEntry.exitCode, 2);
        QVERIFY2(wrongEntry.err.contains(QLatin1String("the bundle holds no log nope.log")),
                 qPrintable(wrongEntry.err));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBundle, Guiless)
#include "tst_bundle.moc"
