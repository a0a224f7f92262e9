// The support bundle: what goes in (the logs of the last days, the profile and its
// checklist, the machine's report, the settings, versions and the serial adapters, a README
// naming it all), read back, and replayed by stepcomctl; its progress, and that a bundle
// cancelled or failed leaves no file.
#include "logbuilder.h"
#include "programrun.h"
#include "support/supportbundle.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRandomGenerator>
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

// Every file under `dir` whose name has `part` in it (what a bundle is written to first).
QStringList filesNamed(const QString &dir, const QString &part)
{
    QStringList found;
    QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        if (QFileInfo(path).fileName().contains(part))
            found << path;
    }
    return found;
}

// `bytes` that do not compress: the bundle takes as long to write as their size says.
QByteArray noise(qsizetype bytes)
{
    QByteArray data(bytes, Qt::Uninitialized);
    QRandomGenerator generator(26);
    generator.fillRange(reinterpret_cast<quint32 *>(data.data()), bytes / 4);
    return data;
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
        // No report given: none inside, and the README says why.
        QVERIFY2(readme.contains(QLatin1String("No commissioning report of the machine: none was "
                                               "made.")),
                 qPrintable(readme));
    }

    // The machine report the caller made is report.html, and the README names its sheets.
    void holdsTheMachineReport()
    {
        BundleInput withReport = input;
        withReport.reportHtml = "<html><body><h1>Commissioning report</h1></body></html>";
        withReport.reportSheets = {QStringLiteral("id 1: /dev/ttyUSB0 · 9600 8N1 · id 1, values "
                                                  "as read"),
                                   QStringLiteral("id 1 \"Machine A\": made from the profile file "
                                                  "machine-a.json (no controller read)")};
        const QString zip = dir.filePath(QStringLiteral("report.zip"));
        QStringList contents;
        QString error;
        QVERIFY2(SupportBundle::create(zip, withReport, &contents, &error), qPrintable(error));
        QCOMPARE(contents.mid(0, 3), (QStringList{"README.txt", "system.txt", "report.html"}));
        QTemporaryDir out;
        QCOMPARE(readEntry(zip, QStringLiteral("report.html"), out), withReport.reportHtml);
        const QString readme = QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out));
        QVERIFY2(readme.contains(QLatin1String("report.html\n    the commissioning report of the "
                                               "machine")),
                 qPrintable(readme));
        QVERIFY2(readme.contains(QLatin1String("2 controller sheet(s)")), qPrintable(readme));
        for (const QString &sheet : std::as_const(withReport.reportSheets))
            QVERIFY2(readme.contains(sheet), qPrintable(readme));
        QVERIFY(!readme.contains(QLatin1String("No commissioning report")));
        // None, and why: the README says so, and there is no empty report.
        BundleInput without = input;
        without.noReport = QStringLiteral("no controller was read");
        QVERIFY2(SupportBundle::create(zip, without, &contents, &error), qPrintable(error));
        QVERIFY(!SupportBundle::logs(zip, &error).isEmpty());
        QVERIFY(SupportBundle::extract(zip, QStringLiteral("report.html"), out.path(), &error)
                    .isEmpty());
        QVERIFY2(QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out))
                     .contains(QLatin1String("No commissioning report of the machine: no "
                                             "controller was read.")),
                 qPrintable(error));
    }

    // No log of those days: the README says there is none, not that the logs are inside.
    void withoutLogsTheReadmeSaysSo()
    {
        BundleInput none = input;
        none.logDirectory = dir.filePath(QStringLiteral("no-logs"));
        none.days = 3;
        const QString zip = dir.filePath(QStringLiteral("nologs.zip"));
        QStringList contents;
        QString error;
        QVERIFY2(SupportBundle::create(zip, none, &contents, &error), qPrintable(error));
        QTemporaryDir out;
        const QString readme = QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out));
        QVERIFY2(!readme.contains(QLatin1String("Session logs of the last")), qPrintable(readme));
        QVERIFY2(readme.contains(QLatin1String("No session log of the last 3 day(s)")),
                 qPrintable(readme));
    }

    // The progress never goes back, counts every byte that goes in and ends at the end.
    void progressReachesTheEnd()
    {
        BundleInput big = input;
        big.logDirectory = dir.filePath(QStringLiteral("big-logs"));
        qint64 logBytes = 0;
        for (int i = 0; i < 3; ++i) {
            const QByteArray data = noise(1024 * 1024 + i * 1000);
            QVERIFY(
                writeFile(big.logDirectory + QStringLiteral("/stepcom-big-%1.log").arg(i), data));
            logBytes += data.size();
        }
        big.now = QDateTime::currentDateTime();
        QList<std::pair<qint64, qint64>> seen;
        SupportBundle::Callbacks callbacks;
        callbacks.progress = [&seen](qint64 done, qint64 total) { seen.append({done, total}); };
        const QString zip = dir.filePath(QStringLiteral("big.zip"));
        QString error;
        QVERIFY2(SupportBundle::create(zip, big, nullptr, &error, callbacks), qPrintable(error));
        QVERIFY2(seen.size() > 12, qPrintable(QString::number(seen.size()))); // chunk by chunk
        const qint64 total = seen.first().second;
        QVERIFY2(total > logBytes, qPrintable(QString::number(total))); // the rest goes in too
        for (qsizetype i = 0; i < seen.size(); ++i) {
            QCOMPARE(seen.at(i).second, total);
            QVERIFY(seen.at(i).first >= 0 && seen.at(i).first <= total);
            if (i > 0)
                QVERIFY2(seen.at(i).first >= seen.at(i - 1).first,
                         qPrintable(QStringLiteral("%1 after %2")
                                        .arg(seen.at(i).first)
                                        .arg(seen.at(i - 1).first)));
        }
        QCOMPARE(seen.last().first, total);
        QCOMPARE(SupportBundle::logs(zip, &error).size(), 3);
    }

    // Cancelled half-way: no bundle, nothing written beside it, and a bundle of that name that
    // was there stays as it was.
    void cancelledLeavesNoFile()
    {
        BundleInput big = input;
        big.logDirectory = dir.filePath(QStringLiteral("cancelled-logs"));
        for (int i = 0; i < 2; ++i)
            QVERIFY(writeFile(big.logDirectory + QStringLiteral("/stepcom-c-%1.log").arg(i),
                              noise(2 * 1024 * 1024)));
        big.now = QDateTime::currentDateTime();
        const QString folder = dir.filePath(QStringLiteral("out-cancelled"));
        QVERIFY(QDir().mkpath(folder));
        const QString zip = folder + QStringLiteral("/bundle.zip");
        int calls = 0;
        SupportBundle::Callbacks callbacks;
        callbacks.progress = [&calls](qint64, qint64) { ++calls; };
        callbacks.cancelled = [&calls] { return calls >= 5; }; // well inside the first log
        QString error;
        QVERIFY(!SupportBundle::create(zip, big, nullptr, &error, callbacks));
        QCOMPARE(error, QStringLiteral("cancelled"));
        QVERIFY(calls >= 5);
        QVERIFY(!QFileInfo::exists(zip));
        QCOMPARE(QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList());
        // An older bundle of that name is left alone.
        QVERIFY(writeFile(zip, "an older bundle"));
        calls = 0;
        QVERIFY(!SupportBundle::create(zip, big, nullptr, &error, callbacks));
        QFile older(zip);
        QVERIFY(older.open(QIODevice::ReadOnly));
        QCOMPARE(older.readAll(), QByteArray("an older bundle"));
        QCOMPARE(filesNamed(folder, QStringLiteral(".part")), QStringList());
        // Not cancelled, it replaces the older one.
        QVERIFY2(SupportBundle::create(zip, big, nullptr, &error), qPrintable(error));
        QCOMPARE(SupportBundle::logs(zip, &error).size(), 2);
        QCOMPARE(filesNamed(folder, QStringLiteral(".part")), QStringList());
    }

    // A file that cannot be put in half-way (a settings "file" that is a folder) fails the
    // bundle, named, and leaves nothing.
    void failedLeavesNoFile()
    {
        BundleInput broken = input;
        broken.settingsFiles = {dir.filePath(QStringLiteral("a-folder.conf"))};
        QVERIFY(QDir().mkpath(broken.settingsFiles.first()));
        const QString folder = dir.filePath(QStringLiteral("out-failed"));
        QVERIFY(QDir().mkpath(folder));
        const QString zip = folder + QStringLiteral("/bundle.zip");
        QString error;
        QVERIFY(!SupportBundle::create(zip, broken, nullptr, &error));
        QVERIFY2(error.contains(QLatin1String("bundle.zip")) &&
                     error.contains(QLatin1String("settings/a-folder.conf")),
                 qPrintable(error));
        QCOMPARE(QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList());
        // A folder that does not exist: said, nothing made.
        QVERIFY(!SupportBundle::create(dir.filePath(QStringLiteral("no/such/folder/b.zip")), input,
                                       nullptr, &error));
        QVERIFY2(error.contains(QLatin1String("no/such/folder/b.zip")), qPrintable(error));
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

    // stepcomctl bundle holds the machine report: of the controllers given (here the built-in
    // simulator, two on its line) and of the profile; without either, the README says why.
    void stepcomctlBundlesTheMachineReport()
    {
        const QString profile = dir.filePath(QStringLiteral("machine-b.json"));
        const ProgramRun dumped = runProgram(QStringLiteral("stepcomctl"),
                                             {"dump", profile, "--sim", "--name", "Machine B"});
        QVERIFY2(dumped.exitCode == 0, qPrintable(dumped.err));
        const QString zip = dir.filePath(QStringLiteral("ctl-report.zip"));
        const ProgramRun made =
            runProgram(QStringLiteral("stepcomctl"),
                       {"bundle", zip, "--sim", "--id", "1,2", "--profile", profile});
        QVERIFY2(made.exitCode == 0, qPrintable(made.err));
        QVERIFY2(made.out.contains(QLatin1String("  report.html")), qPrintable(made.out));
        QTemporaryDir out;
        const QString html = QString::fromUtf8(readEntry(zip, QStringLiteral("report.html"), out));
        for (const char *expected :
             {"Controller id 1", "Controller id 2", "Machine B", "data:image/png;base64,"})
            QVERIFY2(html.contains(QLatin1String(expected)), expected);
        const QString readme = QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out));
        QVERIFY2(readme.contains(QLatin1String("3 controller sheet(s)")), qPrintable(readme));
        QVERIFY2(readme.contains(QStringLiteral(" · id 2, values as read at ")),
                 qPrintable(readme));
        QVERIFY2(readme.contains(QLatin1String("id 1 \"Machine B\": made from the profile file "
                                               "machine-b.json")),
                 qPrintable(readme));

        // Neither: no report.html; the README and the output say why.
        const ProgramRun bare = runProgram(QStringLiteral("stepcomctl"), {"bundle", zip});
        QVERIFY2(bare.exitCode == 0, qPrintable(bare.err));
        QVERIFY2(!bare.out.contains(QLatin1String("report.html")), qPrintable(bare.out));
        QVERIFY2(bare.out.contains(QLatin1String("no machine report: no controller was read")),
                 qPrintable(bare.out));
        QVERIFY2(QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out))
                     .contains(QLatin1String("No commissioning report of the machine: no "
                                             "controller was read (--port, --tcp or --sim) and "
                                             "no profile was given (--profile).")),
                 "README");
        // A profile StepCom cannot read goes in as it is, and the README says why no report.
        const ProgramRun broken = runProgram(QStringLiteral("stepcomctl"),
                                             {"bundle", zip, "--profile", input.profilePath});
        QVERIFY2(broken.exitCode == 0, qPrintable(broken.err));
        QVERIFY2(broken.err.contains(QLatin1String("goes into the bundle as it is, but not into "
                                                   "the report")),
                 qPrintable(broken.err));
        QVERIFY(broken.out.contains(QLatin1String("profile/machine-a.json")));
        QVERIFY2(QString::fromUtf8(readEntry(zip, QStringLiteral("README.txt"), out))
                     .contains(QLatin1String("No commissioning report of the machine: the profile "
                                             "machine-a.json could not be read")),
                 "README");
        // A profile that is not there: nothing made, said.
        const ProgramRun missing = runProgram(
            QStringLiteral("stepcomctl"),
            {"bundle", dir.filePath(QStringLiteral("none.zip")), "--profile", "gone.json"});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY2(missing.err.contains(QLatin1String("--profile: gone.json does not exist")),
                 qPrintable(missing.err));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("none.zip"))));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBundle, Guiless)
#include "tst_bundle.moc"
