#include "base/language.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilefilesdialog.h"
#include "enabledcontrols.h"
#include "map/factoryvalues.h"
#include "pages/interpolationpage.h"
#include "pages/modespage.h"
#include "pages/motorpage.h"
#include "profile/profiledocument.h"
#include "profile/profilefile.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "testmaps.h"
#include "widgets/docks/offlinebanner.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/patheditor.h"
#include "window/mainwindow.h"
#include "window/offlineactions.h"
#include "window/profileactions.h"
#include "window/windowprobe.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <memory>

using namespace stepcom;

// Working without the machine, in the window, offscreen: a profile file edited on
// the usual pages, saved and read back exactly; nothing that reaches a controller enabled;
// connecting compares the edited values; two files compared; the report made from a file.
class TestOffline : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<MainWindow> window;
    QTemporaryDir dir;

    OfflineActions *offline() const { return WindowProbe(*window).offlineActions(); }
    ParameterStore *store() const { return session->parameters()->store(); }
    ParameterField *field(const QString &key) const
    {
        for (ParameterField *f : window->findChildren<ParameterField *>()) {
            if (f->parameter().key == key)
                return f;
        }
        return nullptr;
    }
    template<typename T>
    T *page() const
    {
        for (Page *p : WindowProbe(*window).pages()) {
            if (auto *t = qobject_cast<T *>(p))
                return t;
        }
        return nullptr;
    }
    // Machine A: the factory values with a few of its own.
    Profile machineA() const
    {
        Profile p =
            Profile::fromValues(session->map(), FactoryValues::writable(session->map()), false);
        p.name = QStringLiteral("Machine A");
        p.values[QStringLiteral("motor1.speed")] = 420;
        p.values[QStringLiteral("motor2.pitch")] = 1250; // 12.50 mm, a 32-bit register
        p.values[QStringLiteral("arc.enabled")] = 1;
        return p;
    }
    QString write(const QString &name, const Profile &p) const
    {
        const QString path = dir.filePath(name);
        const QString e = ProfileFile::save(path, p, session->map());
        return e.isEmpty() ? path : QString();
    }
    QString writeBytes(const QString &name, const QByteArray &bytes) const
    {
        const QString path = dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            return {};
        return path;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
    }
    void init()
    {
        Language::instance().setLanguage(QStringLiteral("en"));
        session = std::make_unique<DeviceSession>();
        test::useBuiltinSimulator(*session);
        window = std::make_unique<MainWindow>(session.get());
        window->show();
    }
    void cleanup()
    {
        store()->revertAll(); // no close question
        window.reset();
        session.reset();
    }

    // Open without a controller: the pages show the file's values and edit them with their
    // validation; saving writes exactly what the pages show; the file opens again the same.
    void openEditValidateSaveReopen()
    {
        const QString path = write(QStringLiteral("machine-a.json"), machineA());
        QVERIFY(!path.isEmpty());
        QVERIFY(
            WindowProbe(*window).profileActions()->openFile(path)); // File → Open, not connected
        QVERIFY(!WindowProbe(*window).profileActions()->compareDialog());
        QVERIFY(offline()->document()->isOpen());
        QVERIFY(store()->isFile());
        QVERIFY(WindowProbe(*window).offlineBanner()->isVisible());
        QVERIFY(WindowProbe(*window).offlineBanner()->text().contains(
            QStringLiteral("machine-a.json")));
        QVERIFY(window->windowTitle().contains(QStringLiteral("profile file, no controller")));
        QVERIFY(!window->statusBar()->styleSheet().isEmpty());
        QCOMPARE(store()->shownValue(QStringLiteral("motor1.speed")), 420);
        QCOMPARE(store()->state(QStringLiteral("motor1.speed")), ParameterStore::State::InSync);

        // Edits on the pages, as a user types them.
        ParameterField *speed = field(QStringLiteral("motor1.speed"));
        ParameterField *pitch = field(QStringLiteral("motor2.pitch"));
        ParameterField *micro = field(QStringLiteral("motor1.microsteps"));
        QVERIFY(speed && pitch && micro);
        speed->enterText(QStringLiteral("450"));
        pitch->enterText(QStringLiteral("7.25"));
        micro->enterText(QStringLiteral("16"));
        QCOMPARE(store()->shownValue(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(store()->shownValue(QStringLiteral("motor2.pitch")), 725);
        QVERIFY(offline()->document()->isModified());
        QVERIFY(window->windowTitle().contains(QStringLiteral("machine-a.json*")));
        // The derived values follow the file's values and the edits: 1.8°, 16 → 3200 pulses.
        MotorPage *motor1 = page<MotorPage>();
        QVERIFY(motor1);
        QCOMPARE(motor1->derived().pulsesPerRev.value_or(0), 3200.0);

        // A refused value never reaches the store, and the field says why.
        QSignalSpy rejected(speed, &ParameterField::rejected);
        speed->enterText(QStringLiteral("99999"));
        QCOMPARE(rejected.size(), 1);
        QVERIFY(rejected.at(0).at(0).toString().contains(QStringLiteral("3000")));
        QCOMPARE(store()->shownValue(QStringLiteral("motor1.speed")), 450);

        // The interpolation page checks the file's geometry like a controller's.
        InterpolationPage *interp = page<InterpolationPage>();
        QVERIFY(interp);
        QVERIFY(interp->arcEditor()->geometry().valid);
        field(QStringLiteral("arc.end_x"))->enterText(QStringLiteral("20"));
        field(QStringLiteral("arc.end_y"))->enterText(QStringLiteral("20"));
        field(QStringLiteral("arc.center_x"))->enterText(QStringLiteral("20"));
        field(QStringLiteral("arc.center_y"))->enterText(QStringLiteral("20"));
        QVERIFY(!interp->arcEditor()->geometry().valid); // centre on the start point
        QVERIFY(!interp->arcEditor()->startButton()->isEnabled());
        field(QStringLiteral("arc.center_x"))->enterText(QStringLiteral("40"));

        // The mode is an edit of the file, asked nothing and sent nowhere.
        ModesPage *modes = page<ModesPage>();
        QVERIFY(modes && modes->modeBox()->isEnabled());
        modes->chooseMode(1);
        QVERIFY(!modes->confirmation());
        QCOMPARE(store()->shownValue(QStringLiteral("mode.system")), 1);

        const Profile expected = offline()->document()->current();
        const QString saved = dir.filePath(QStringLiteral("machine-a-edited.json"));
        QVERIFY(offline()->saveFile(saved));
        QVERIFY(!offline()->document()->isModified());
        QCOMPARE(offline()->document()->path(), saved);
        const ProfileParseResult back = ProfileFile::load(saved, session->map());
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QCOMPARE(back.profile->values, expected.values);
        QCOMPARE(back.profile->values.value(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(back.profile->values.value(QStringLiteral("motor2.pitch")), 725);
        QCOMPARE(back.profile->values.value(QStringLiteral("motor1.microsteps")), 16);
        QCOMPARE(back.profile->values.value(QStringLiteral("arc.center_x")), 4000);
        QCOMPARE(back.profile->values.value(QStringLiteral("mode.system")), 1);
        QCOMPARE(back.profile->name, QStringLiteral("Machine A"));

        QVERIFY(offline()->closeFile());
        QVERIFY(!store()->isFile());
        QVERIFY(!store()->shownValue(QStringLiteral("motor1.speed")));
        QVERIFY(!WindowProbe(*window).offlineBanner()->isVisible());
        QVERIFY(offline()->openFile(saved));
        for (auto it = expected.values.cbegin(); it != expected.values.cend(); ++it)
            QCOMPARE(store()->shownValue(it.key()), it.value());
        QVERIFY(!store()->hasEdits());
    }

    // Everything that moves or writes a controller is off while a file is edited; what stays
    // on works on files, views or the language. The E-STOP has nothing to stop and says so.
    void nothingWritesOffline()
    {
        const QString path = write(QStringLiteral("machine-a.json"), machineA());
        QVERIFY(offline()->openFile(path));
        field(QStringLiteral("motor1.speed"))->enterText(QStringLiteral("450")); // an edit
        field(QStringLiteral("motor1.move_distance"))->enterText(QStringLiteral("12"));
        const QStringList enabled = test::enabledControls(window.get());
        QVERIFY2(enabled.isEmpty(), qPrintable(enabled.join(QLatin1Char('\n'))));
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("writeChanges"))->isEnabled());
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("saveToFlash"))->isEnabled());
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("commissioningReport"))->isEnabled());

        // Nothing to stop: the E-STOP is greyed and says why; F12 still reaches the session,
        // which says that nothing was sent.
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("emergencyStop"))->isEnabled());
        QVERIFY(!WindowProbe(*window).emergencyStopButton()->isEnabled());
        QVERIFY(WindowProbe(*window).emergencyStopButton()->toolTip().contains(
            QStringLiteral("Nothing to stop")));
        QSignalSpy said(session.get(), &DeviceSession::message);
        QTest::keyClick(window.get(), Qt::Key_F12);
        QVERIFY(said.size() >= 1);
        QVERIFY(said.at(0).at(1).toString().contains(QStringLiteral("nothing was sent")));
        QCOMPARE(session->connection()->traffic()->entries().size(), 0);

        // No link to lose: the file's values stay.
        session->connection()->disconnectFrom();
        QCOMPARE(store()->deviceValue(QStringLiteral("motor1.speed")), 420);
        QCOMPARE(store()->shownValue(QStringLiteral("motor1.speed")), 450);
    }

    // Connecting after offline edits ends the editing and compares the file's values, edits
    // included, with the controller's; nothing is written by that.
    void connectAfterOfflineEdits()
    {
        const QString path = write(QStringLiteral("machine-a.json"), machineA());
        QVERIFY(offline()->openFile(path));
        field(QStringLiteral("motor1.speed"))->enterText(QStringLiteral("555"));
        test::connectToSimulator(*session);
        QVERIFY(!offline()->document()->isOpen());
        QVERIFY(!store()->isFile());
        QVERIFY(!WindowProbe(*window).offlineBanner()->isVisible());
        ProfileCompareDialog *dialog = offline()->compareDialog();
        QVERIFY(dialog);
        QCOMPARE(dialog->profile().values.value(QStringLiteral("motor1.speed")), 555);
        QCOMPARE(dialog->profile().values.value(QStringLiteral("motor2.pitch")), 1250);
        const int row = dialog->rowOf(QStringLiteral("motor1.speed"));
        QVERIFY(row >= 0);
        QTRY_VERIFY(dialog->isChecked(QStringLiteral("motor1.speed"))); // differs: checked
        QCOMPARE(dialog->table()->item(row, ProfileCompareDialog::ProfileColumn)->text(),
                 QStringLiteral("555"));
        // The controller's own value, not the file's, is in the controller column.
        const qint64 simSpeed =
            test::simHost(*session)->device()->value(QStringLiteral("motor1.speed")).value_or(-1);
        QCOMPARE(store()->deviceValue(QStringLiteral("motor1.speed")), simSpeed);
        QVERIFY(simSpeed != 555); // nothing written
        QVERIFY(!store()->hasEdits());
        dialog->close();
    }

    // Closing or opening another file with unsaved edits asks first; Cancel keeps them.
    void unsavedEditsAsk()
    {
        const QString a = write(QStringLiteral("a.json"), machineA());
        const QString b = write(QStringLiteral("b.json"), machineA());
        QVERIFY(offline()->openFile(a));
        field(QStringLiteral("motor1.speed"))->enterText(QStringLiteral("500"));
        QVERIFY(!offline()->openFile(b));
        QVERIFY(offline()->question() && offline()->question()->isVisible());
        offline()->question()->button(QMessageBox::Cancel)->click();
        QCOMPARE(offline()->document()->path(), a);
        QCOMPARE(store()->shownValue(QStringLiteral("motor1.speed")), 500);
        QVERIFY(!offline()->closeFile());
        QVERIFY(offline()->question());
        offline()->question()->button(QMessageBox::Discard)->click();
        QVERIFY(!offline()->document()->isOpen());
        QVERIFY(!store()->hasEdits());
    }

    // A new profile starts from the factory values and saves like any other.
    void newFromFactoryValues()
    {
        QVERIFY(offline()->newFromFactory());
        QVERIFY(
            WindowProbe(*window).offlineBanner()->text().contains(QStringLiteral("new profile")));
        const QHash<QString, qint64> factory = FactoryValues::writable(session->map());
        for (const Parameter *p : Profile::profileParameters(session->map(), false))
            QCOMPARE(store()->shownValue(p->key), factory.value(p->key));
        field(QStringLiteral("motor2.speed"))->enterText(QStringLiteral("200"));
        const QString path = dir.filePath(QStringLiteral("new.json"));
        QVERIFY(offline()->saveFile(path));
        const ProfileParseResult back = ProfileFile::load(path, session->map());
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QCOMPARE(back.profile->values.value(QStringLiteral("motor2.speed")), 200);
        QCOMPARE(back.profile->values.value(QStringLiteral("motor1.speed")),
                 factory.value(QStringLiteral("motor1.speed")));
    }

    // A variant profile opens with what this map cannot take and what the file lacks listed;
    // saving fills what it lacks with factory values and says so; the unknown keys stay.
    void variantProfileOffline()
    {
        QStringList errors;
        const auto threeAxis = test::threeAxisMap(&errors);
        const auto lite = test::liteVariantMap(&errors);
        QVERIFY2(threeAxis && lite, qPrintable(errors.join(QLatin1Char('\n'))));
        QHash<QString, qint64> raw = FactoryValues::writable(*threeAxis);
        raw.insert(QStringLiteral("motor3.speed"), 900);
        raw.insert(QStringLiteral("motor1.speed"), 4500); // fine there, too fast here
        const QString three =
            writeBytes(QStringLiteral("three.json"),
                       test::profileSavedWith(*threeAxis, raw, QStringLiteral("Machine C")));
        QVERIFY(offline()->openFile(three));
        const QString listed = WindowProbe(*window).offlineBanner()->varianceText();
        QVERIFY2(listed.contains(QStringLiteral("stepper3/1")), qPrintable(listed));
        QVERIFY2(listed.contains(QStringLiteral("unknown to this map: motor3.speed = 900")),
                 qPrintable(listed));
        QVERIFY2(listed.contains(QStringLiteral("cannot be applied: motor1.speed: 4500")),
                 qPrintable(listed));
        QVERIFY(!store()->shownValue(QStringLiteral("motor1.speed"))); // not this map's value

        const QString litePath = writeBytes(
            QStringLiteral("lite.json"),
            test::profileSavedWith(*lite, FactoryValues::writable(*lite), QStringLiteral("L")));
        QVERIFY(offline()->openFile(litePath));
        const QString missing = WindowProbe(*window).offlineBanner()->varianceText();
        QVERIFY2(missing.contains(QStringLiteral("not in the profile: line.start_x")),
                 qPrintable(missing));
        QVERIFY2(missing.contains(QStringLiteral("motor1.home_input")), qPrintable(missing));
        field(QStringLiteral("motor1.speed"))->enterText(QStringLiteral("333"));
        QSignalSpy finished(offline(), &OfflineActions::finished);
        const QString saved = dir.filePath(QStringLiteral("lite-edited.json"));
        QVERIFY(offline()->saveFile(saved));
        bool said = false;
        for (const QList<QVariant> &f : finished)
            said = said || (f.at(1).toString().contains(QStringLiteral("factory values")) &&
                            f.at(1).toString().contains(QStringLiteral("line.start_x")));
        QVERIFY(said);
        const ProfileParseResult back =
            ProfileFile::load(saved, session->map(), ProfileFile::OtherMaps::Accept);
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QCOMPARE(back.profile->values.value(QStringLiteral("motor1.speed")), 333);
        QCOMPARE(back.profile->values.value(QStringLiteral("line.start_x")),
                 FactoryValues::value(*session->map().find(QStringLiteral("line.start_x"))));
        QVERIFY(back.profile->variance.missing.isEmpty());
        QVERIFY(WindowProbe(*window).offlineBanner()->varianceText().contains(
            QStringLiteral("stepper2-lite")));
    }

    // File → Compare profiles: two files row by row, no controller; the groups apart.
    void compareTwoFiles()
    {
        Profile a = machineA();
        Profile b = machineA();
        b.values[QStringLiteral("motor1.speed")] = 600;
        const QString pathA = write(QStringLiteral("a.json"), a);
        QStringList errors;
        const auto threeAxis = test::threeAxisMap(&errors);
        QVERIFY(threeAxis);
        QHash<QString, qint64> raw;
        for (auto it = b.values.cbegin(); it != b.values.cend(); ++it)
            raw.insert(it.key(), it.value());
        raw.insert(QStringLiteral("motor3.speed"), 900);
        const QString pathB = writeBytes(
            QStringLiteral("b.json"), test::profileSavedWith(*threeAxis, raw, QStringLiteral("B")));
        QVERIFY(offline()->compareFiles(pathA, pathB));
        ProfileFilesDialog *d = offline()->filesDialog();
        QVERIFY(d && d->isVisible());
        const int speed = d->rowOf(QStringLiteral("motor1.speed"));
        const int pitch = d->rowOf(QStringLiteral("motor2.pitch"));
        const int motor3 = d->rowOf(QStringLiteral("motor3.speed"));
        QVERIFY(speed >= 0 && pitch >= 0 && motor3 >= 0);
        QCOMPARE(d->groupOf(speed), ProfileFilesDialog::Group::Differ);
        QVERIFY(d->isHighlighted(speed));
        QCOMPARE(d->table()->item(speed, ProfileFilesDialog::AColumn)->text(),
                 QStringLiteral("420"));
        QCOMPARE(d->table()->item(speed, ProfileFilesDialog::BColumn)->text(),
                 QStringLiteral("600"));
        QCOMPARE(d->groupOf(pitch), ProfileFilesDialog::Group::Same);
        QVERIFY(!d->isHighlighted(pitch));
        QCOMPARE(d->groupOf(motor3), ProfileFilesDialog::Group::Outside);
        QVERIFY(d->isHighlighted(motor3)); // only B holds it
        QVERIFY(d->summary()->text().contains(QStringLiteral("1 differ")));
        d->differencesOnly()->setChecked(true);
        QVERIFY(d->table()->isRowHidden(pitch));
        QVERIFY(!d->table()->isRowHidden(speed));
        QCOMPARE(session->connection()->traffic()->entries().size(), 0); // no controller involved

        // A bad file is named, and no comparison opens.
        const QString bad = writeBytes(QStringLiteral("bad.json"), "{ not json");
        d->close();
        QVERIFY(!offline()->compareFiles(pathA, bad));
        QVERIFY(offline()->errorBox());
        QVERIFY(offline()->errorBox()->detailedText().contains(QStringLiteral("bad.json")));
    }

    // The report from a file, in the window, in both languages: written and marked as made
    // from a file (the file being edited too, its unsaved edits said).
    void reportFromFile_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("mark");
        QTest::newRow("en") << "en"
                            << "Commissioning report (from a profile file)";
        QTest::newRow("zh_CN") << "zh_CN"
                               << "调试报告（来自参数文件）";
    }
    void reportFromFile()
    {
        QFETCH(QString, language);
        QFETCH(QString, mark);
        Language::instance().setLanguage(language);
        const QString path = write(QStringLiteral("machine-a.json"), machineA());
        const QString html = dir.filePath(QStringLiteral("report-%1.html").arg(language));
        QVERIFY(offline()->reportFromFile(path, html, QStringLiteral("cabinet 2")));
        QFile f(html);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains(mark.toHtmlEscaped()), qPrintable(text.left(600)));
        QVERIFY(text.contains(QStringLiteral("machine-a.json")));
        QVERIFY(text.contains(QStringLiteral("cabinet 2")));
        const QString pdf = dir.filePath(QStringLiteral("report-%1.pdf").arg(language));
        QVERIFY(offline()->reportFromFile(path, pdf, QString()));
        QFile p(pdf);
        QVERIFY(p.open(QIODevice::ReadOnly));
        QCOMPARE(p.read(5), QByteArray("%PDF-"));

        // The file being edited, edits included.
        QVERIFY(offline()->openFile(path));
        field(QStringLiteral("motor1.speed"))->enterText(QStringLiteral("512"));
        const QString edited = dir.filePath(QStringLiteral("edited-%1.html").arg(language));
        QVERIFY(offline()->reportFromDocument(edited, QString()));
        QFile e(edited);
        QVERIFY(e.open(QIODevice::ReadOnly));
        const QString editedText = QString::fromUtf8(e.readAll());
        QVERIFY(editedText.contains(mark.toHtmlEscaped()));
        QVERIFY(editedText.contains(QStringLiteral("512")));
        QVERIFY(editedText.contains(
            OfflineActions::tr("(with edits not saved in the file)").toHtmlEscaped()));
        Language::instance().setLanguage(QStringLiteral("en"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestOffline, Gui)
#include "tst_offline.moc"
