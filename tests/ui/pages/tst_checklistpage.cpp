#include "base/backupguard.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "commissioning/checklistfile.h"
#include "pages/checklistpage.h"
#include "profile/backupstore.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/checklist/checklistcalibrationstep.h"
#include "widgets/checklist/checklistdirectionstep.h"
#include "widgets/checklist/checklistflashstep.h"
#include "widgets/checklist/checklistinputstep.h"
#include "widgets/checklist/checklistmotionstep.h"
#include "window/profileactions.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;

// The commissioning checklist page against the simulator: each step with simulated switches,
// a miswired limit found and fixed, fixes written through the write dialog, progress kept in
// the file beside the profile and resumed by a new page.
class TestChecklistPage : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    std::unique_ptr<QWidget> window;
    std::unique_ptr<DeviceSession> session;
    WriteFlow *writes = nullptr;
    BackupGuard *guard = nullptr;
    ChecklistPage *page = nullptr;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    QString profile() const { return dir.filePath(QStringLiteral("machine-a.json")); }
    template<typename T>
    T *step(const QString &id) const
    {
        page->selectStep(id);
        auto *w = qobject_cast<T *>(page->stepWidget(id));
        return w;
    }
    const ChecklistStep &result(const QString &id) const { return *page->checklist().step(id); }
    // The write dialog the step opened: accept it, wait for the verified write.
    void acceptWrite()
    {
        QTRY_VERIFY(writes->dialog());
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        writes->dialog()->accept();
        QTRY_COMPARE(written.size(), 1);
    }
    // Two more status polls: a switch state set now has been sampled.
    void pollTwice()
    {
        QSignalSpy cycles(session->status(), &SessionStatus::statusCycleFinished);
        QTRY_VERIFY_WITH_TIMEOUT(cycles.size() >= 2, 10000);
    }
    void press(int input)
    {
        sim()->setInput(input, SimDevice::InputForce::On);
        pollTwice();
        sim()->setInput(input, SimDevice::InputForce::Off);
        pollTwice();
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init()
    {
        QFile::remove(ChecklistFile::pathFor(profile()));
        window = std::make_unique<QWidget>();
        session = std::make_unique<DeviceSession>();
        test::connectToSimulator(*session);
        writes = new WriteFlow(session.get(), window.get());
        guard = new BackupGuard(session.get(), window.get());
        guard->setDirectory(dir.filePath(QStringLiteral("backups")));
        page = new ChecklistPage(session.get(), writes, window.get());
        page->setProfilePath(profile());
    }
    void cleanup()
    {
        window.reset();
        session.reset();
    }

    void directionNoFlipsTheRegisterThenPasses()
    {
        auto *w = step<ChecklistDirectionStep>(QStringLiteral("motor1.direction"));
        QVERIFY(w);
        const qint64 from = sim()->position(1);
        w->moveButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(w->noButton()->isEnabled(), 20000);
        QCOMPARE(sim()->position(1), from + 100); // 1.00 mm, direction as configured (forward)
        w->noButton()->click();
        QCOMPARE(result(QStringLiteral("motor1.direction")).result(), StepResult::Failed);
        QVERIFY(w->flipButton()->isVisibleTo(w));
        w->flipButton()->click();
        acceptWrite();
        QCOMPARE(sim()->value(QStringLiteral("motor1.direction")).value_or(-1), 1);
        QVERIFY2(w->statusText().contains(QStringLiteral("written and verified")),
                 qPrintable(w->statusText()));
        // Repeated: it moves with the flipped register now, and Yes passes it.
        w->moveButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(w->yesButton()->isEnabled(), 20000);
        QCOMPARE(sim()->position(1), from);
        w->yesButton()->click();
        const ChecklistStep &s = result(QStringLiteral("motor1.direction"));
        QCOMPARE(s.result(), StepResult::Passed);
        QCOMPARE(s.attempts.size(), 2);
        // Saved beside the profile at once.
        const auto file = ChecklistFile::load(ChecklistFile::pathFor(profile()), session->map());
        QVERIFY(file.ok());
        QCOMPARE(file.checklist->step(QStringLiteral("motor1.direction"))->attempts.size(), 2);
        // With the fingerprint of the settings it ran against (direction flipped included).
        QCOMPARE(file.checklist->settingsFingerprint.size(), 19);
    }

    void calibrationProposesAndWritesThePitch()
    {
        auto *w = step<ChecklistCalibrationStep>(QStringLiteral("motor1.calibration"));
        QVERIFY(w);
        w->commandedField()->setValue(10.0);
        w->moveButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(w->proposeButton()->isEnabled(), 20000);
        w->measuredField()->setValue(10.03);
        w->proposeButton()->click();
        QVERIFY2(w->writeButton()->isVisibleTo(w), qPrintable(w->statusText()));
        QVERIFY(w->writeButton()->text().contains(QStringLiteral("5.02")));
        w->writeButton()->click();
        acceptWrite();
        QCOMPARE(sim()->value(QStringLiteral("motor1.pitch")).value_or(-1), 502);
        const ChecklistStep &s = result(QStringLiteral("motor1.calibration"));
        QCOMPARE(s.result(), StepResult::Passed);
        QStringList keys;
        for (const ChecklistMeasurement &m : s.latest()->measurements)
            keys << m.key + u'=' + m.value;
        QVERIFY2(keys.contains(QStringLiteral("pitch_after=5.02")), qPrintable(keys.join(u' ')));
        QVERIFY(keys.contains(QStringLiteral("pitch_before=5.00")));
        QVERIFY(keys.contains(QStringLiteral("measured=10.030")));
    }

    void miswiredLimitIsFoundAndFixed()
    {
        // The register says IN3; the switch is wired to IN1.
        QVERIFY(sim()->setValue(QStringLiteral("motor1.limit_positive"), 3));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        auto *w = step<ChecklistInputStep>(QStringLiteral("motor1.limit_positive"));
        QVERIFY(w);
        pollTwice();
        w->watchButton()->click();
        QVERIFY(w->isWatching());
        press(1);
        w->doneButton()->click();
        QCOMPARE(result(QStringLiteral("motor1.limit_positive")).result(), StepResult::Failed);
        QVERIFY2(w->fixButton()->isVisibleTo(w), qPrintable(w->statusText()));
        w->fixButton()->click();
        acceptWrite();
        QCOMPARE(sim()->value(QStringLiteral("motor1.limit_positive")).value_or(-1), 1);
        // Repeated: the configured input answers now.
        w->watchButton()->click();
        press(1);
        w->doneButton()->click();
        QCOMPARE(result(QStringLiteral("motor1.limit_positive")).result(), StepResult::Passed);
        // No switch pressed at all: failed, nothing proposed.
        auto *home = step<ChecklistInputStep>(QStringLiteral("motor1.home_input"));
        home->watchButton()->click();
        pollTwice();
        home->doneButton()->click();
        QCOMPARE(result(QStringLiteral("motor1.home_input")).result(), StepResult::Failed);
        QVERIFY(!home->fixButton()->isVisibleTo(home));
    }

    void interpolationHomingOrderAndFlash()
    {
        auto *line = step<ChecklistMotionStep>(QStringLiteral("machine.interpolation"));
        QVERIFY(sim()->setValue(QStringLiteral("line.speed"), 600));
        QVERIFY(sim()->setValue(QStringLiteral("line.enabled"), 1));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        line->pathChoice()->setCurrentIndex(1);
        line->runButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(
            result(QStringLiteral("machine.interpolation")).result() != StepResult::Pending, 60000);
        QVERIFY2(result(QStringLiteral("machine.interpolation")).result() == StepResult::Passed,
                 qPrintable(line->statusText()));
        QCOMPARE(sim()->position(1), 8000);
        QCOMPARE(sim()->position(2), 6000);
        // Homing after it: the axes stand on their home switches at 0 (the interpolation test
        // runs before homing here: the line cannot start from the negative limits).

        auto *homing = step<ChecklistMotionStep>(QStringLiteral("motor1.homing"));
        sim()->setMachinePosition(1, 20.0);
        homing->runButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(
            result(QStringLiteral("motor1.homing")).result() != StepResult::Pending, 30000);
        QVERIFY2(result(QStringLiteral("motor1.homing")).result() == StepResult::Passed,
                 qPrintable(homing->statusText()));

        auto *order = step<ChecklistMotionStep>(QStringLiteral("machine.homing_order"));
        order->runButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(
            result(QStringLiteral("machine.homing_order")).result() != StepResult::Pending, 30000);
        QVERIFY2(result(QStringLiteral("machine.homing_order")).result() == StepResult::Passed,
                 qPrintable(order->statusText()));

        auto *flash = step<ChecklistFlashStep>(QStringLiteral("machine.save_to_flash"));
        flash->saveButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(
            result(QStringLiteral("machine.save_to_flash")).result() != StepResult::Pending, 20000);
        QVERIFY2(result(QStringLiteral("machine.save_to_flash")).result() == StepResult::Passed,
                 qPrintable(flash->statusText()));
        // The backup guard saved the settings before the save to flash.
        const QList<BackupEntry> backups = BackupStore(guard->directory()).list(session->map());
        QCOMPARE(backups.size(), 1);
        QCOMPARE(backups.first().operation, QStringLiteral("save-to-flash"));
    }

    void interruptedChecklistResumes()
    {
        auto *d1 = step<ChecklistDirectionStep>(QStringLiteral("motor1.direction"));
        d1->noteField()->setText(QStringLiteral("no scale at hand"));
        d1->skipButton()->click();
        QCOMPARE(result(QStringLiteral("motor1.direction")).latest()->note,
                 QStringLiteral("no scale at hand"));
        step<ChecklistCalibrationStep>(QStringLiteral("motor1.calibration"))->skipButton()->click();
        QCOMPARE(page->checklist().nextPending()->id, QStringLiteral("motor1.limit_positive"));
        // The window closes; a new one (same settings) resumes at the first step not run.
        delete page;
        page = new ChecklistPage(session.get(), writes, window.get());
        QCOMPARE(page->profilePath(), profile());
        QCOMPARE(page->currentStepId(), QStringLiteral("motor1.limit_positive"));
        QCOMPARE(result(QStringLiteral("motor1.direction")).result(), StepResult::Skipped);
        QCOMPARE(result(QStringLiteral("motor1.calibration")).result(), StepResult::Skipped);
        QVERIFY(page->summaryText().contains(QStringLiteral("2 skipped")));
        QVERIFY(page->reportChecklist());
        // The report from the window carries the checklist run on the page.
        ProfileActions actions(session.get(), window.get());
        actions.setChecklistSource([this] { return page->reportChecklist(); });
        const QString html = dir.filePath(QStringLiteral("report.html"));
        QSignalSpy reported(&actions, &ProfileActions::finished);
        actions.reportFile(html, QString());
        QTRY_VERIFY_WITH_TIMEOUT(!reported.isEmpty(), 10000);
        QVERIFY2(reported.first().at(0).toBool(), qPrintable(reported.first().at(1).toString()));
        QFile report(html);
        QVERIFY(report.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(report.readAll());
        QVERIFY(text.contains(QStringLiteral("Motor 1: direction")));
        QVERIFY(text.contains(QStringLiteral("no scale at hand")));
        QVERIFY(text.contains(QStringLiteral("machine-a.checklist.json")));
        // A file that cannot be read is named and never saved over.
        QFile f(ChecklistFile::pathFor(profile()));
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("{ not json");
        f.close();
        page->setProfilePath(profile());
        QVERIFY(page->problemText().contains(QStringLiteral("cannot be used")));
        step<ChecklistDirectionStep>(QStringLiteral("motor1.direction"))->skipButton()->click();
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("{ not json"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestChecklistPage, Gui)
#include "tst_checklistpage.moc"
