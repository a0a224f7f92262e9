// Help → Create support bundle…: the machine's commissioning report goes in (the
// devices as the window last read them, the profile's sheet), or the README says why not; the
// bundle is written on a thread of its own, the window answering meanwhile; Cancel leaves
// nothing.
#include "base/language.h"
#include "dialogs/supportbundledialog.h"
#include "map/factoryvalues.h"
#include "profile/profilefile.h"
#include "session/devicesession.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "simsession.h"
#include "support/supportbundle.h"
#include "widgets/docks/devicelistdock.h"
#include "window/machineactions.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace stepcom;

class TestBundleDialog : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> window;
    MachineActions *actions = nullptr;
    DeviceListDock *list = nullptr;
    QTemporaryDir dir;
    QString profile;
    QString bigLogs;

    SupportBundleDialog *openDialog(const QString &profilePath)
    {
        auto *dialog = new SupportBundleDialog(
            profilePath, actions ? actions->reportSheets() : ReportSheets{}, window.get());
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setLogDirectory(dir.filePath(QStringLiteral("no-logs")));
        dialog->show();
        return dialog;
    }
    QPushButton *button(SupportBundleDialog *dialog, QDialogButtonBox::StandardButton which)
    {
        return dialog->findChild<QDialogButtonBox *>()->button(which);
    }
    QByteArray entry(const QString &zip, const QString &name)
    {
        QTemporaryDir out;
        QString error;
        QFile f(SupportBundle::extract(zip, name, out.path(), &error));
        if (!f.open(QIODevice::ReadOnly))
            qWarning("%s", qPrintable(error));
        return f.readAll();
    }
    QStringList leftIn(const QString &folder)
    {
        return QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
        const RegisterMap &map = RegisterMap::builtin();
        Profile p = Profile::fromValues(map, FactoryValues::writable(map), false);
        p.name = QStringLiteral("Machine C");
        profile = dir.filePath(QStringLiteral("machine-c.json"));
        QCOMPARE(ProfileFile::save(profile, p, map), QString());
        // Logs that take a while to pack: 2 × 16 MB that do not compress.
        bigLogs = dir.filePath(QStringLiteral("big-logs"));
        QVERIFY(QDir().mkpath(bigLogs));
        QByteArray noise(16 * 1024 * 1024, Qt::Uninitialized);
        QRandomGenerator generator(26);
        generator.fillRange(reinterpret_cast<quint32 *>(noise.data()), noise.size() / 4);
        for (const char *name : {"/stepcom-big-1.log", "/stepcom-big-2.log"}) {
            QFile f(bigLogs + QLatin1String(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            QCOMPARE(f.write(noise), noise.size());
        }
    }
    void init()
    {
        session = std::make_unique<DeviceSession>();
        window = std::make_unique<QWidget>();
        actions = new MachineActions(session.get(), window.get());
        list = new DeviceListDock(session.get(), window.get());
        actions->addTo(new QMenu(window.get()), [this] { return list; });
        test::useBuiltinSimulator(*session, {1, 2, 3});
    }
    void cleanup()
    {
        window.reset();
        session.reset();
    }

    // Three devices on the line, two of them read (shown in turn): the report has those two as
    // last read, with the names the list gives them, and the profile's sheet.
    void theReportIsTheMachineAsTheWindowKnowsIt()
    {
        session->line()->setDeviceIds({1, 2, 3});
        test::connectToSimulator(*session);
        QTRY_COMPARE(list->table()->rowCount(), 3);
        list->table()->item(1, 1)->setText(QStringLiteral("Y axis"));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        QVERIFY(session->line()->showDevice(2));
        QTRY_VERIFY_WITH_TIMEOUT(!read.isEmpty(), 10000);
        QVERIFY(session->line()->showDevice(1));
        QTRY_VERIFY_WITH_TIMEOUT(read.size() >= 2, 10000);

        SupportBundleDialog *dialog = openDialog(profile);
        const QString text = dialog->reportText();
        QVERIFY2(text.contains(QLatin1String("ids 1, 2 as last read")) &&
                     text.contains(QLatin1String("the profile machine-c.json")),
                 qPrintable(text));
        QSignalSpy written(dialog, &SupportBundleDialog::written);
        const QString zip = dir.filePath(QStringLiteral("machine.zip"));
        QVERIFY(dialog->createFile(zip));
        QVERIFY(written.wait(30000) || !written.isEmpty());
        QVERIFY2(written.at(0).at(0).toBool(), qPrintable(written.at(0).at(1).toString()));
        QVERIFY(written.at(0).at(1).toString().contains(QStringLiteral("• report.html")));
        const QString html = QString::fromUtf8(entry(zip, QStringLiteral("report.html")));
        for (const char *expected :
             {"Controller id 1", "Controller id 2: Y axis", "Machine C", "machine-c.json"})
            QVERIFY2(html.contains(QLatin1String(expected)), expected);
        QVERIFY(!html.contains(QLatin1String("Controller id 3")));
        const QString readme = QString::fromUtf8(entry(zip, QStringLiteral("README.txt")));
        QVERIFY2(readme.contains(QLatin1String("3 controller sheet(s)")), qPrintable(readme));
        QVERIFY2(readme.contains(QLatin1String("id 2 \"Y axis\": ")), qPrintable(readme));
        QVERIFY2(readme.contains(QLatin1String("made from the profile file machine-c.json")),
                 qPrintable(readme));
        // Left out by choice: none, and the README says so.
        dialog = openDialog(profile);
        dialog->setReportIncluded(false);
        QSignalSpy again(dialog, &SupportBundleDialog::written);
        QVERIFY(dialog->createFile(zip));
        QVERIFY(again.wait(30000) || !again.isEmpty());
        QVERIFY(!again.at(0).at(1).toString().contains(QLatin1String("report.html")));
        QVERIFY2(QString::fromUtf8(entry(zip, QStringLiteral("README.txt")))
                     .contains(QLatin1String("No commissioning report of the machine: left out "
                                             "when the bundle was made.")),
                 "README");
    }

    // Nothing read and no profile: no report to offer, and the README says why.
    void nothingToReportIsSaid()
    {
        SupportBundleDialog *dialog = openDialog(QString());
        QVERIFY2(dialog->reportText().startsWith(QLatin1String("None: ")),
                 qPrintable(dialog->reportText()));
        QVERIFY(!dialog->findChild<QWidget *>(QStringLiteral("bundleReport"))->isEnabled());
        QSignalSpy written(dialog, &SupportBundleDialog::written);
        const QString zip = dir.filePath(QStringLiteral("nothing.zip"));
        QVERIFY(dialog->createFile(zip));
        QVERIFY(written.wait(30000) || !written.isEmpty());
        QVERIFY(written.at(0).at(0).toBool());
        QVERIFY(!written.at(0).at(1).toString().contains(QLatin1String("report.html")));
        QVERIFY2(QString::fromUtf8(entry(zip, QStringLiteral("README.txt")))
                     .contains(QLatin1String("No commissioning report of the machine: no "
                                             "device's settings were read in the session and no "
                                             "profile went in.")),
                 "README");
    }

    // 32 MB of logs: createFile() returns at once, the window's events go on (a timer fires)
    // while the bundle is packed, the progress bar shows, and the result is said.
    void staysResponsiveWhileWriting()
    {
        SupportBundleDialog *dialog = openDialog(QString());
        dialog->setLogDirectory(bigLogs);
        QVERIFY2(dialog->logsText().startsWith(QLatin1String("2 session logs, ")),
                 qPrintable(dialog->logsText()));
        int ticks = 0;
        QTimer timer;
        connect(&timer, &QTimer::timeout, this, [&ticks] { ++ticks; });
        timer.start(0);
        int ticksWhenWritten = -1;
        connect(dialog, &SupportBundleDialog::written, this, [&] { ticksWhenWritten = ticks; });
        QSignalSpy written(dialog, &SupportBundleDialog::written);
        const QString zip = dir.filePath(QStringLiteral("big.zip"));
        QVERIFY(dialog->createFile(zip));
        QVERIFY(written.isEmpty()); // not written inside the call: on its own thread
        QVERIFY(dialog->isBusy());
        QVERIFY(dialog->progressBar()->isVisible());
        QVERIFY(!button(dialog, QDialogButtonBox::Save)->isEnabled());
        QVERIFY(!dialog->createFile(zip)); // one at a time
        QVERIFY(written.wait(120000) || !written.isEmpty());
        QVERIFY2(ticksWhenWritten > 0, qPrintable(QString::number(ticksWhenWritten)));
        QVERIFY2(written.at(0).at(0).toBool(), qPrintable(written.at(0).at(1).toString()));
        QVERIFY(written.at(0).at(1).toString().startsWith(QLatin1String("Support bundle written")));
        QVERIFY(dialog->resultBox());
        QCOMPARE(dialog->resultBox()->text(), written.at(0).at(1).toString());
        QVERIFY(!dialog->isBusy());
        QVERIFY(!dialog->isVisible()); // done: the dialog closed, the message says it
        QString error;
        QCOMPARE(SupportBundle::logs(zip, &error).size(), 2);
    }

    // Cancel while it is written: nothing is left, it says so, and the dialog stays for another
    // try; Cancel then closes it.
    void cancelLeavesNothing()
    {
        SupportBundleDialog *dialog = openDialog(QString());
        dialog->setLogDirectory(bigLogs);
        const QString folder = dir.filePath(QStringLiteral("cancelled"));
        QVERIFY(QDir().mkpath(folder));
        QSignalSpy written(dialog, &SupportBundleDialog::written);
        QVERIFY(dialog->createFile(folder + QStringLiteral("/bundle.zip")));
        QTest::mouseClick(button(dialog, QDialogButtonBox::Cancel), Qt::LeftButton);
        QVERIFY(written.wait(60000) || !written.isEmpty());
        QVERIFY(!written.at(0).at(0).toBool());
        QCOMPARE(written.at(0).at(1).toString(),
                 QStringLiteral("The support bundle was cancelled: nothing was written."));
        QCOMPARE(leftIn(folder), QStringList());
        QVERIFY(dialog->isVisible());
        QVERIFY(!dialog->isBusy());
        QVERIFY(!dialog->progressBar()->isVisible());
        QVERIFY(button(dialog, QDialogButtonBox::Save)->isEnabled());
        QPointer<SupportBundleDialog> gone(dialog);
        QTest::mouseClick(button(dialog, QDialogButtonBox::Cancel), Qt::LeftButton);
        QTRY_VERIFY(!gone);
    }

    // Closed with the window while it writes: it stops and leaves nothing.
    void closedWithTheWindowLeavesNothing()
    {
        SupportBundleDialog *dialog = openDialog(QString());
        dialog->setLogDirectory(bigLogs);
        const QString folder = dir.filePath(QStringLiteral("closed"));
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(dialog->createFile(folder + QStringLiteral("/bundle.zip")));
        window.reset(); // the dialog with it
        QCOMPARE(leftIn(folder), QStringList());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBundleDialog, Gui)
#include "tst_bundledialog.moc"
