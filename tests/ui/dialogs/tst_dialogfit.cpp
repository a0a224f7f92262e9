// The dialogs fit the screens technicians have (split from tst_layoutfit): write
// changes, bus scan, profile save and compare, files compare, backups, the support bundle, the
// pendant and
// the user guide window at the screen the test runs on (the same five as tst_layoutfit), in
// English and Chinese.
// Fails when a dialog is larger than the screen or cannot shrink to it, a text in it is cut, a
// widget lies outside its parent, a view scrolls sideways, or a guide picture is wider than the
// guide.
#include "layoutchecks.h"

#include "base/language.h"
#include "base/writechangesdialog.h"
#include "device/parameterstore.h"
#include "dialogs/backupsdialog.h"
#include "dialogs/busscandialog.h"
#include "dialogs/pendantdialog.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilefilesdialog.h"
#include "dialogs/profilesavedialog.h"
#include "dialogs/supportbundledialog.h"
#include "help/guidewindow.h"
#include "map/factoryvalues.h"
#include "pages/connectionpage.h"
#include "pendant/pendantserver.h"
#include "profile/backupstore.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "window/mainwindow.h"
#include "window/pendantactions.h"
#include "window/windowprobe.h"

#include <QAction>
#include <QApplication>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTreeWidget>

using namespace stepcom;
using namespace stepcom::test;

class TestDialogFit : public QObject, public LayoutChecks
{
    Q_OBJECT

    static void languages()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QSettings().clear(); // no window layout saved by another run
    }
    void cleanup() { m_problems.clear(); }

    // The dialogs a technician meets most: comparing a profile with the controller or with
    // another file, and saving one.
    void profileDialogsFit_data() { languages(); }
    void profileDialogsFit()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        Profile profile;
        profile.values.insert(QStringLiteral("motor1.speed"), 300);
        ProfileCompareDialog compare(&session, profile, QStringLiteral("machine-a.json"), &window);
        ProfileSaveDialog save(true, QStringLiteral("Press 4 2026-11-24"), &window);
        Profile other = profile;
        other.values.insert(QStringLiteral("motor1.speed"), 450);
        other.values.insert(QStringLiteral("motor2.microsteps"), 16);
        ProfileFilesDialog files(
            session.map(), profile,
            QStringLiteral("/home/technician/profiles/press-4-machine-a.json"), other,
            QStringLiteral("/home/technician/profiles/press-4-machine-b.json"), &window);
        for (QDialog *dialog : {static_cast<QDialog *>(&compare), static_cast<QDialog *>(&save),
                                static_cast<QDialog *>(&files)}) {
            checkDialog(dialog, QString::fromLatin1(dialog->metaObject()->className()));
            dialog->close();
        }
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }

    // Help → Create support bundle…, nothing read yet: the longest words it shows.
    void pendantDialogFits_data() { languages(); }
    void pendantDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        PendantServer *server = window.pendantActions()->server();
        QVERIFY2(server->start(QHostAddress::LocalHost, 0), qPrintable(server->error()));
        PendantDialog *dialog = window.pendantActions()->openDialog(); // running: code, address
        QVERIFY(dialog);
        checkDialog(dialog, QStringLiteral("pendant"));
        dialog->close();
        server->stop();
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }

    void supportBundleDialogFits_data() { languages(); }
    void supportBundleDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        WindowProbe(window).action(QStringLiteral("createSupportBundle"))->trigger();
        auto *dialog = window.findChild<SupportBundleDialog *>();
        QVERIFY(dialog);
        checkDialog(dialog, QStringLiteral("support bundle"));
        dialog->close();
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }

    void busScanDialogFits_data() { languages(); }
    void busScanDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        auto *page = qobject_cast<ConnectionPage *>(WindowProbe(window).pages().first());
        BusScanDialog *dialog = page->openBusScan();
        QVERIFY(dialog);
        checkDialog(dialog, QStringLiteral("bus scan"));
        dialog->close();
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }

    // Write changes: a dozen edits with long names, and the problems the pages flag above them.
    void writeChangesDialogFits_data() { languages(); }
    void writeChangesDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        ParameterStore *store = session.parameters()->store();
        int edits = 0;
        for (const Parameter &p : session.map().parameters()) {
            if (p.writable() && store->edit(p.key, p.rawMax).isEmpty() && ++edits == 12)
                break;
        }
        QVERIFY(edits >= 6);
        WriteChangesDialog dialog(*store, &window);
        QCOMPARE(dialog.writes().size(), edits);
        dialog.setProblems(
            {QStringLiteral(
                 "Motor 1: the travel limit (12000 steps) is beyond the soft limit the "
                 "machine's drawing gives for this axis, check the mechanics before writing"),
             QStringLiteral("Motor 2: home input and limit input are wired to the same terminal")});
        checkDialog(&dialog, QStringLiteral("write changes"));
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }

    // File → Backups with a few backups, one of them unreadable.
    void backupsDialogFits_data() { languages(); }
    void backupsDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const BackupStore store(dir.path());
        const QHash<QString, qint64> values = FactoryValues::writable(session.map());
        const QDateTime at(QDate(2026, 11, 24), QTime(9, 30), Qt::UTC);
        for (auto op : {BackupStore::Operation::Apply, BackupStore::Operation::FactoryReset,
                        BackupStore::Operation::DeviceId}) {
            QVERIFY(store
                        .save(session.map(), values, op,
                              QStringLiteral("/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_"
                                             "A50285BI-if00-port0 · 115200 8N1 · id 1"),
                              at.addSecs(60 * int(op)))
                        .ok());
        }
        QFile broken(dir.filePath(QStringLiteral("backup-20261124-100000-apply.json")));
        QVERIFY(broken.open(QIODevice::WriteOnly) && broken.write("{ not json") > 0);
        broken.close();
        BackupsDialog dialog(session.map(), dir.path(), &window);
        QVERIFY(dialog.list()->topLevelItemCount() >= 3);
        checkDialog(&dialog, QStringLiteral("backups"));
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }

    // Help → User guide at a section with pictures: nothing cut, no picture wider than the view.
    void guideWindowFits_data() { languages(); }
    void guideWindowFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        GuideWindow *guide =
            WindowProbe(window).openGuide(QStringLiteral("stepcom::ConnectionPage"));
        QVERIFY(guide);
        QVERIFY2(!guide->file().isEmpty(), "the guide was not found");
        checkDialog(guide, QStringLiteral("guide"));
        QTextBrowser *browser = guide->browser();
        const QTextDocument *doc = browser->document();
        const qreal room = browser->viewport()->width() - 2 * doc->documentMargin();
        int images = 0;
        for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
            for (auto it = b.begin(); !it.atEnd(); ++it) {
                const QTextCharFormat f = it.fragment().charFormat();
                if (!f.isImageFormat())
                    continue;
                ++images;
                const QTextImageFormat image = f.toImageFormat();
                // Shown at the width the format asks for, else at the picture's own.
                qreal shown = image.width();
                if (!image.hasProperty(QTextFormat::ImageWidth)) {
                    const QVariant data =
                        doc->resource(QTextDocument::ImageResource, QUrl(image.name()));
                    QImage picture = data.value<QImage>();
                    if (picture.isNull())
                        picture.loadFromData(data.toByteArray());
                    shown = picture.width();
                }
                if (shown > room + 1)
                    problem(QStringLiteral("guide"),
                            QStringLiteral("picture %1 is %2 px wide in a view of %3 px")
                                .arg(image.name())
                                .arg(shown)
                                .arg(room));
            }
        }
        QVERIFY2(images > 0, "the guide shows no picture");
        QVERIFY2(m_problems.isEmpty(), qPrintable(report()));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDialogFit, Gui)
#include "tst_dialogfit.moc"
