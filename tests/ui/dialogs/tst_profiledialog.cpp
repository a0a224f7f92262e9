#include "base/language.h"
#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilesavedialog.h"
#include "profile/profileapply.h"
#include "profile/profilefile.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "testpaths.h"
#include "window/mainwindow.h"
#include "window/profileactions.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QCheckBox>
#include <QDate>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;

// Open a profile, compare, apply checked rows -- against the built-in simulator, offscreen.
class TestProfileDialog : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> window;
    QTemporaryDir dir;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    qint64 simValue(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }
    void connectSim() { test::connectToSimulator(*session); }
    // The controller's values with three changes (and another device id).
    Profile changedProfile() const
    {
        QHash<QString, qint64> values;
        for (const Parameter *p : Profile::profileParameters(session->map(), true))
            values.insert(p->key, *session->parameters()->store()->deviceValue(p->key));
        Profile p = Profile::fromValues(session->map(), values, true);
        p.name = QStringLiteral("Machine B");
        p.values[QStringLiteral("motor1.speed")] += 11;
        p.values[QStringLiteral("motor2.pitch")] += 250; // 32-bit
        p.values[QStringLiteral("arc.speed")] += 5;
        p.values[QStringLiteral("device.id")] = 7;
        return p;
    }
    int visibleRows(QTableWidget *t) const
    {
        int n = 0;
        for (int r = 0; r < t->rowCount(); ++r)
            n += t->isRowHidden(r) ? 0 : 1;
        return n;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
    }
    void init()
    {
        session = std::make_unique<DeviceSession>();
        window = std::make_unique<QWidget>();
    }
    void cleanup()
    {
        window.reset();
        session.reset();
    }

    void compareAndApplyOnlyTheCheckedRows()
    {
        connectSim();
        const Profile profile = changedProfile();
        const qint64 speed = simValue("motor1.speed");
        const qint64 arcSpeed = simValue("arc.speed");
        ProfileCompareDialog dialog(session.get(), profile, QStringLiteral("b.json"), window.get());
        dialog.open();
        QTableWidget *t = dialog.table();
        QTRY_COMPARE(t->rowCount(), int(Profile::profileParameters(session->map(), true).size()));
        // Opening (and the fresh read it does) writes nothing.
        QTRY_VERIFY(!dialog.isBusy());
        QCOMPARE(simValue("motor1.speed"), speed);
        // It opens on the differences only.
        QVERIFY(dialog.differencesOnly()->isChecked());
        QCOMPARE(visibleRows(t), 4);
        dialog.differencesOnly()->setChecked(false);
        // The user widens the key column; Apply below must not undo it.
        const int widened = t->columnWidth(ProfileCompareDialog::KeyColumn) + 120;
        t->setColumnWidth(ProfileCompareDialog::KeyColumn, widened);
        const int unitWidth = t->columnWidth(ProfileCompareDialog::UnitColumn);

        QCOMPARE(dialog.checkedKeys(),
                 (QStringList{"motor1.speed", "motor2.pitch", "arc.speed"})); // differing rows
        const int idRow = dialog.rowOf(QStringLiteral("device.id"));
        QVERIFY(!(t->item(idRow, 0)->flags() & Qt::ItemIsUserCheckable)); // needs the opt-in
        const int speedRow = dialog.rowOf(QStringLiteral("motor1.speed"));
        QCOMPARE(t->item(speedRow, ProfileCompareDialog::DeviceColumn)->text(),
                 QString::number(speed));
        QCOMPARE(t->item(speedRow, ProfileCompareDialog::ProfileColumn)->text(),
                 QString::number(speed + 11));
        QCOMPARE(t->item(speedRow, ProfileCompareDialog::UnitColumn)->text(),
                 QStringLiteral("rpm"));
        QVERIFY(t->item(speedRow, 1)->background() !=
                t->item(dialog.rowOf(QStringLiteral("motor1.microsteps")), 1)->background());

        dialog.differencesOnly()->setChecked(true);
        QCOMPARE(visibleRows(t), 4); // three settings and the device id
        dialog.differencesOnly()->setChecked(false);
        QCOMPARE(visibleRows(t), t->rowCount());

        // The user unchecks arc.speed: only the two other rows are written.
        t->item(dialog.rowOf(QStringLiteral("arc.speed")), 0)->setCheckState(Qt::Unchecked);
        QCOMPARE(dialog.checkedKeys(), (QStringList{"motor1.speed", "motor2.pitch"}));
        QVERIFY(dialog.applyButton()->isEnabled());
        QSignalSpy applied(&dialog, &ProfileCompareDialog::applied);
        QTest::mouseClick(dialog.applyButton(), Qt::LeftButton);
        QVERIFY(dialog.isBusy());
        QTRY_COMPARE_WITH_TIMEOUT(applied.size(), 1, 10000);
        QVERIFY(applied.at(0).at(0).toBool());
        QCOMPARE(applied.at(0).at(1).toStringList(), (QStringList{"motor1.speed", "motor2.pitch"}));
        // The dialog applies through ProfileApply and shows what its result says.
        const auto *applier = dialog.findChild<ProfileApply *>();
        QVERIFY(applier);
        QCOMPARE(applier->result().keysIn(AppliedKey::State::Verified),
                 (QStringList{"motor1.speed", "motor2.pitch"}));
        QCOMPARE(simValue("motor1.speed"), speed + 11);
        QCOMPARE(simValue("motor2.pitch"), profile.values.value(QStringLiteral("motor2.pitch")));
        QCOMPARE(simValue("arc.speed"), arcSpeed); // unchecked: untouched
        QCOMPARE(simValue("device.id"), 1);
        QVERIFY(dialog.resultLabel()->text().contains(QStringLiteral("Wrote and verified 2")));
        QCOMPARE(t->columnWidth(ProfileCompareDialog::KeyColumn), widened);
        QCOMPARE(t->columnWidth(ProfileCompareDialog::UnitColumn), unitWidth);

        // Then Save to flash is offered.
        QVERIFY(dialog.saveToFlashButton()->isVisible());
        QSignalSpy command(session.get(), &DeviceSession::commandFinished);
        QTest::mouseClick(dialog.saveToFlashButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(command.size(), 1, 10000);
        QCOMPARE(command.at(0).at(0).toString(), QStringLiteral("save_to_flash"));
        QVERIFY(dialog.resultLabel()->text().contains(QStringLiteral("Saved to flash")));
        // Written rows now match; arc.speed still differs and stays unchecked (the user's
        // choice is kept).
        QTRY_COMPARE(t->item(speedRow, ProfileCompareDialog::DeviceColumn)->text(),
                     QString::number(speed + 11));
        QVERIFY(dialog.checkedKeys().isEmpty());
        dialog.differencesOnly()->setChecked(true);
        QCOMPARE(visibleRows(t), 2); // arc.speed and the device id
    }

    // A controller that lacks a key of the profile: the row is left out with a note, and Apply
    // never tries to write it.
    void unsupportedKeysAreLeftOut()
    {
        connectSim();
        const Profile profile = changedProfile(); // differs in motor2.pitch, among others
        sim()->setLacking({QStringLiteral("motor2.pitch")});
        ProfileCompareDialog dialog(session.get(), profile, QStringLiteral("b.json"), window.get());
        dialog.open();
        QTRY_COMPARE_WITH_TIMEOUT(dialog.rowOf(QStringLiteral("motor2.pitch")), -1, 10000);
        QTRY_VERIFY(!dialog.isBusy());
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor2.pitch")),
                 ParameterStore::State::Unsupported);
        QCOMPARE(dialog.table()->rowCount(),
                 int(Profile::profileParameters(session->map(), true).size()) - 1);
        QCOMPARE(dialog.checkedKeys(), (QStringList{"motor1.speed", "arc.speed"}));
        QString note;
        for (const QLabel *l : dialog.findChildren<QLabel *>())
            note += l->text() + QLatin1Char('\n');
        QVERIFY2(note.contains(QLatin1String("Left out, not supported by this controller: "
                                             "motor2.pitch.")),
                 qPrintable(note));
    }

    void offlineEverythingIsUnknownNotDifferent()
    {
        Profile p;
        p.values.insert(QStringLiteral("motor1.speed"), 300);
        ProfileCompareDialog dialog(session.get(), p, QStringLiteral("p.json"), window.get());
        dialog.open();
        QVERIFY(dialog.checkedKeys().isEmpty());
        QVERIFY(!dialog.applyButton()->isEnabled());
        QCOMPARE(dialog.table()
                     ->item(dialog.rowOf(QStringLiteral("motor1.speed")),
                            ProfileCompareDialog::DeviceColumn)
                     ->text(),
                 QStringLiteral("—"));
        dialog.differencesOnly()->setChecked(true);
        QCOMPARE(visibleRows(dialog.table()), 0);
    }

    // Apply goes through ProfileApply: what the controller holds is read again first, and a
    // checked row it already holds is said so, not written.
    void aRowTheControllerAlreadyHoldsIsNotWritten()
    {
        connectSim();
        const Profile profile = changedProfile();
        ProfileCompareDialog dialog(session.get(), profile, QStringLiteral("b.json"), window.get());
        dialog.open();
        QTRY_VERIFY(!dialog.isBusy());
        QVERIFY(dialog.checkedKeys().contains(QStringLiteral("arc.speed")));
        // Someone else wrote it meanwhile: the controller holds the profile's value now.
        QVERIFY(sim()->setValue(QStringLiteral("arc.speed"),
                                profile.values.value(QStringLiteral("arc.speed"))));
        session->connection()->traffic()->clear();
        QSignalSpy applied(&dialog, &ProfileCompareDialog::applied);
        dialog.apply();
        QTRY_COMPARE_WITH_TIMEOUT(applied.size(), 1, 10000);
        QVERIFY(applied.at(0).at(0).toBool());
        QCOMPARE(applied.at(0).at(1).toStringList(), (QStringList{"motor1.speed", "motor2.pitch"}));
        const QString text = dialog.resultLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("1 value(s) the controller already held.")) ||
                     text.contains(QStringLiteral("1 value the controller already held.")),
                 qPrintable(text));
        const Parameter *arc = session->map().find(QStringLiteral("arc.speed"));
        for (const TrafficEntry &e : session->connection()->traffic()->entries()) {
            if (e.direction == TrafficEntry::Direction::Sent && e.bytes.size() > 3 &&
                quint8(e.bytes.at(1)) == 0x06)
                QVERIFY(((quint8(e.bytes.at(2)) << 8) | quint8(e.bytes.at(3))) != arc->address);
        }
    }

    void mismatchesAreNamed()
    {
        connectSim();
        Profile profile = changedProfile();
        ProfileCompareDialog dialog(session.get(), profile, QStringLiteral("b.json"), window.get());
        dialog.open();
        QTRY_VERIFY(!dialog.checkedKeys().isEmpty());
        // The link goes away while the write is queued: nothing can be written or verified,
        // and the dialog names the values that were not.
        QSignalSpy applied(&dialog, &ProfileCompareDialog::applied);
        dialog.apply();
        session->connection()->disconnectFrom();
        QTRY_COMPARE_WITH_TIMEOUT(applied.size(), 1, 10000);
        QVERIFY(!applied.at(0).at(0).toBool());
        const QString text = dialog.resultLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("Problems:")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("motor1.speed")), qPrintable(text));
        QVERIFY(!dialog.applyButton()->isEnabled()); // not connected any more
    }

    void linkSettingsNeedTheOptInAndTheLinkFollows()
    {
        connectSim();
        Profile profile = changedProfile();
        profile.values = {{QStringLiteral("device.id"), 7}};
        for (const Parameter *p : Profile::profileParameters(session->map(), false))
            profile.values.insert(p->key, *session->parameters()->store()->deviceValue(p->key));
        ProfileCompareDialog dialog(session.get(), profile, QStringLiteral("id.json"),
                                    window.get());
        dialog.open();
        QTRY_VERIFY(!dialog.isBusy());
        QVERIFY(dialog.checkedKeys().isEmpty());
        QVERIFY(!dialog.applyButton()->isEnabled());
        dialog.includeLink()->setChecked(true);
        QCOMPARE(dialog.checkedKeys(), QStringList{"device.id"});
        QSignalSpy linkChanged(session->line(), &SessionLine::linkChanged);
        QSignalSpy applied(&dialog, &ProfileCompareDialog::applied);
        dialog.apply();
        QTRY_COMPARE_WITH_TIMEOUT(applied.size(), 1, 10000);
        QVERIFY2(applied.at(0).at(0).toBool(),
                 qPrintable(applied.at(0).at(2).toStringList().join(QLatin1Char('\n'))));
        QCOMPARE(simValue("device.id"), 7);
        QCOMPARE(session->connection()->settings().deviceId, 7); // the link followed
        QCOMPARE(linkChanged.size(), 1);
    }

    void suggestedNames_data()
    {
        QTest::addColumn<QString>("machine");
        QTest::addColumn<int>("deviceId");
        QTest::addColumn<QString>("name");
        QTest::newRow("no machine") << QString() << 3 << "Controller id 3 2026-11-24";
        QTest::newRow("nothing known") << QString() << 0 << "Profile 2026-11-24";
        QTest::newRow("machine") << "Press 4" << 1 << "Press 4 2026-11-24";
        QTest::newRow("machine with a date") << "Press 4 2026-11-20" << 1 << "Press 4 2026-11-24";
        QTest::newRow("machine_date") << "press4_2026-11-20" << 1 << "press4 2026-11-24";
    }
    void suggestedNames()
    {
        QFETCH(QString, machine);
        QFETCH(int, deviceId);
        QFETCH(QString, name);
        QCOMPARE(ProfileSaveDialog::suggestName(machine, deviceId, QDate(2026, 11, 24)), name);
        QCOMPARE(ProfileSaveDialog::fileNameFor(QStringLiteral("Line 2/Station: 4")),
                 QStringLiteral("Line 2-Station- 4.json"));
        QCOMPARE(ProfileSaveDialog::fileNameFor(QStringLiteral("..")),
                 QStringLiteral("profile...json"));
    }

    // Saving asks for the name (suggested) and notes first; both go into the file, and the
    // next suggestion follows the machine's name.
    void saveAsksForNameAndNotes()
    {
        ProfileActions actions(session.get(), window.get());
        connectSim();
        const QString today = QDate::currentDate().toString(Qt::ISODate);
        QCOMPARE(actions.suggestedName(), QStringLiteral("Controller id 1 ") + today);
        QTRY_VERIFY(actions.saveFromEditedAction()->isEnabled());
        actions.saveFromEditedAction()->trigger();
        ProfileSaveDialog *ask = actions.saveDialog();
        QVERIFY(ask && ask->isVisible());
        QCOMPARE(ask->nameEdit()->text(), actions.suggestedName());
        ask->nameEdit()->setText(QStringLiteral("Press 4 ") + today);
        ask->notesEdit()->setPlainText(QStringLiteral("Hall B, set up by Li"));
        ask->accept();
        QFileDialog *where = nullptr;
        QTRY_VERIFY((where = window->findChild<QFileDialog *>()) != nullptr);
        QVERIFY2(where->selectedFiles().value(0).endsWith(QStringLiteral("/Press 4 ") + today +
                                                          QStringLiteral(".json")),
                 qPrintable(where->selectedFiles().join(QLatin1Char(' '))));
        const QString path = dir.filePath(QStringLiteral("press4.json"));
        QSignalSpy finished(&actions, &ProfileActions::finished);
        Q_EMIT where->fileSelected(path);
        QCOMPARE(finished.size(), 1);
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        const ProfileParseResult saved = ProfileFile::load(path, session->map());
        QVERIFY(saved.ok());
        QCOMPARE(saved.profile->name, QStringLiteral("Press 4 ") + today);
        QCOMPARE(saved.profile->notes, QStringLiteral("Hall B, set up by Li"));
        QCOMPARE(actions.suggestedName(), QStringLiteral("Press 4 ") + today);
        where->close();
    }

    void actionsOpenSaveAndRemember()
    {
        ProfileActions actions(session.get(), window.get());
        QVERIFY(!actions.saveFromDeviceAction()->isEnabled());
        QVERIFY(!actions.saveFromEditedAction()->isEnabled()); // nothing known yet
        // A broken file: every problem shown, no dialog, nothing written.
        QVERIFY(!actions.openFile(
            test::sourcePath(QStringLiteral("tests/core/profile/corpus/unknown-key.json"))));
        QVERIFY(actions.errorBox());
        QVERIFY(actions.errorBox()->detailedText().contains(
            QStringLiteral("unknown parameter \"motor3.speed\"")));
        QVERIFY(!actions.compareDialog());

        connectSim();
        QTRY_VERIFY(actions.saveFromDeviceAction()->isEnabled());
        const QString fromDevice = dir.filePath(QStringLiteral("device.json"));
        QSignalSpy finished(&actions, &ProfileActions::finished);
        actions.saveFromDeviceFile(fromDevice);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        const ProfileParseResult saved = ProfileFile::load(fromDevice, session->map());
        QVERIFY(saved.ok());
        QCOMPARE(saved.profile->values.value(QStringLiteral("motor1.speed")),
                 simValue("motor1.speed"));
        QCOMPARE(saved.profile->values.value(QStringLiteral("device.id")), 1);

        // From the edited values: the edit goes into the file, nothing to the controller.
        const qint64 speed = simValue("motor2.speed");
        QCOMPARE(session->parameters()->store()->edit(QStringLiteral("motor2.speed"), speed + 1),
                 QString());
        const QString fromEdits = dir.filePath(QStringLiteral("edited.json"));
        QVERIFY(actions.saveFromEditedFile(fromEdits));
        const ProfileParseResult edited = ProfileFile::load(fromEdits, session->map());
        QVERIFY(edited.ok());
        QCOMPARE(edited.profile->values.value(QStringLiteral("motor2.speed")), speed + 1);
        QCOMPARE(simValue("motor2.speed"), speed);

        QCOMPARE(ProfileActions::recentFiles().mid(0, 2), (QStringList{fromEdits, fromDevice}));
        QVERIFY(actions.recentMenu()->actions().size() >= 2);

        // Opening the edited profile shows the one difference; nothing is written by opening.
        QVERIFY(actions.openFile(fromEdits));
        QVERIFY(actions.compareDialog());
        QTRY_COMPARE(actions.compareDialog()->checkedKeys(), QStringList{"motor2.speed"});
        QCOMPARE(simValue("motor2.speed"), speed);
        actions.compareDialog()->close();
    }

    void fileMenuHasTheProfileActions()
    {
        MainWindow w(session.get());
        for (const char *name : {"openProfile", "saveProfileFromDevice", "saveProfileFromEdited",
                                 "commissioningReport"}) {
            QAction *a = WindowProbe(w).action(QLatin1String(name));
            QVERIFY2(a, name);
            QVERIFY2(!a->text().isEmpty(), name);
        }
        QVERIFY(WindowProbe(w).profileActions());
        QVERIFY(!WindowProbe(w)
                     .action(QStringLiteral("saveProfileFromDevice"))
                     ->isEnabled()); // offline
        QVERIFY(WindowProbe(w)
                    .action(QStringLiteral("openProfile"))
                    ->isEnabled()); // opening never writes
    }

    void reportFromTheWindow()
    {
        ProfileActions actions(session.get(), window.get());
        connectSim();
        const QString path = dir.filePath(QStringLiteral("report.pdf"));
        QSignalSpy finished(&actions, &ProfileActions::finished);
        actions.reportFile(path, QStringLiteral("first machine"));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.read(5), QByteArray("%PDF-"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProfileDialog, Gui)
#include "tst_profiledialog.moc"
