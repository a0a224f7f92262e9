#include "base/emergencystop.h"
#include "base/writeflow.h"
#include "commissioning/checklistfile.h"
#include "map/parameter.h"
#include "motion/travellimits.h"
#include "pages/checklistpage.h"
#include "pages/sequencepage.h"
#include "proofsim.h"
#include "report/commissioningreport.h"
#include "report/reportinput.h"
#include "sequence/sequenceparser.h"
#include "sequence/sequencerunner.h"
#include "sequence/sequencewriter.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/motion/jogbutton.h"
#include "widgets/plots/xyplot.h"
#include "widgets/sequence/sequenceeditor.h"
#include "widgets/sequence/sequencepoints.h"
#include "widgets/sequence/sequencerunpanel.h"
#include "widgets/sequence/sequencestepform.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonDocument>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include <memory>

using namespace stepcom;
using StepKind = SequenceStep::Kind;

// The Sequence page against a simulated controller: a point taught from where the jog left the
// axis, the manual's example built in the editor as a user builds it, saved and opened again
// unchanged, run for two cycles (the strip's line, the current step, the run-in on the
// checklist with its lost-step check) and stopped by Stop and by the E-STOP.
class TestSequencePage : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> window;
    SequencePage *page = nullptr;

    SimDevice *sim() const { return host->device(); }
    QByteArray example() const
    {
        return R"({"format": "stepcom-sequence", "version": 1,
            "points": {"load": {"motor1": 30.0}, "unload": {"motor1": 10.0, "motor2": 0.0}},
            "limits": {"motor1": {"min": 0, "max": 300}},
            "steps": [
              {"home": "order"},
              {"repeat": 3, "steps": [
                {"move_to": "load"},
                {"wait_input": 3, "on": true, "timeout_s": 20},
                {"output": 1, "on": true},
                {"dwell_ms": 500},
                {"move_to": "unload"},
                {"output": 1, "on": false}]}]})";
    }
    QJsonObject normalised(const QByteArray &json) const
    {
        QStringList errors;
        const auto s = SequenceParser::parse(json, QStringLiteral("x"), session->map(), &errors);
        if (!s)
            qWarning("%s", qPrintable(errors.join(QLatin1Char('\n'))));
        return s ? SequenceWriter::toJson(*s, session->map()) : QJsonObject();
    }
    QString write(const QString &name, const QByteArray &json) const
    {
        QFile f(dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly) || f.write(json) != json.size())
            return {};
        return f.fileName();
    }
    // Selects the step at `path` and makes it a `kind` through the form's list.
    SequenceStepForm *edit(const QString &path, StepKind kind)
    {
        page->editor()->selectPath(path);
        SequenceStepForm *form = page->editor()->form();
        form->kindBox()->setCurrentIndex(form->kindBox()->findData(int(kind)));
        return form;
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init()
    {
        host = std::make_unique<SimHost>();
        QVERIFY(test::startProofSim(*host, test::proofAxis()));
        session = test::proofSession(*host);
        window = std::make_unique<QWidget>();
        page = new SequencePage(session.get(), window.get());
        page->setConfirmer([](const QString &) { return true; });
    }
    void cleanup()
    {
        QFile::remove(ChecklistFile::pathFor(dir.filePath(QStringLiteral("machine-s.json"))));
        window.reset();
        session.reset();
        host.reset();
    }

    void teachesThePointTheJogLeftTheAxisAt()
    {
        SequencePoints *points = page->points();
        QSignalSpy changed(points, &SequencePoints::changed);
        JogButton *forward = points->jogButton(1, true);
        QVERIFY(forward);
        Q_EMIT forward->jogPressed();
        QTRY_VERIFY_WITH_TIMEOUT(session->jog()->isJogging(1), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(sim()->value(QStringLiteral("motor1.position")).value_or(0) > 200,
                                 10000);
        Q_EMIT forward->jogReleased();
        const Parameter *p = TravelLimits::positionParameter(session->map(), 1);
        // The axis has stopped and the poll has read where: the store holds the controller's.
        QTRY_VERIFY_WITH_TIMEOUT(!session->jog()->isJogging(1) &&
                                     session->parameters()->store()->deviceValue(p->key) ==
                                         sim()->value(QStringLiteral("motor1.position")),
                                 10000);
        QVERIFY(points->teach());
        QCOMPARE(changed.size(), 1);
        QCOMPARE(points->points().keys(), QStringList{QStringLiteral("p1")});
        const double taught = points->points().value(QStringLiteral("p1")).value(1);
        QCOMPARE(qRound64(taught * 100), *sim()->value(QStringLiteral("motor1.position")));
        QCOMPARE(points->table()->item(0, 0)->text(), QStringLiteral("p1"));
        // Renamed in its cell: a move_to step that used it follows.
        page->editor()->addStep(StepKind::MoveTo);
        QCOMPARE(page->editor()->steps().first().point, QStringLiteral("p1"));
        points->table()->item(0, 0)->setText(QStringLiteral("load"));
        QCOMPARE(points->points().keys(), QStringList{QStringLiteral("load")});
        QCOMPARE(page->editor()->steps().first().point, QStringLiteral("load"));
        // A bad name is refused and said; the point keeps its name.
        points->table()->item(0, 0)->setText(QStringLiteral("no spaces"));
        QCOMPARE(points->points().keys(), QStringList{QStringLiteral("load")});
        QVERIFY(points->messageLabel()->text().contains(QLatin1String("no spaces")));
        // The preview shows the point where both motors were.
        const QList<QPointF> dots = page->preview()->path(QStringLiteral("points"));
        QCOMPARE(dots.size(), 1);
        QCOMPARE(dots.first().x(), taught);
    }

    void anUnknownPositionIsNeverTaught()
    {
        session->connection()->disconnectFrom();
        QTRY_VERIFY(!session->connection()->isConnected());
        QVERIFY(!page->points()->teach());
        QVERIFY(page->points()->points().isEmpty());
        QVERIFY2(page->points()->messageLabel()->text().contains(QLatin1String("not known")),
                 qPrintable(page->points()->messageLabel()->text()));
    }

    void buildsTheExampleInTheEditorThenSavesAndReopensIt()
    {
        SequencePoints *points = page->points();
        points->setPoints({{QStringLiteral("load"), {{1, 30.0}}},
                           {QStringLiteral("unload"), {{1, 10.0}, {2, 0.0}}}});
        Q_EMIT points->changed();
        SequenceEditor *editor = page->editor();
        editor->addStep(StepKind::Home); // steps[0]: in the set order, as it starts
        editor->addStep(StepKind::Repeat);
        SequenceStepForm *form = editor->form();
        form->countBox()->setValue(3);
        editor->addStep(StepKind::MoveTo); // into the empty loop
        QCOMPARE(editor->selectedPath(), QStringLiteral("steps[1].steps[0]"));
        form->pointBox()->setCurrentIndex(form->pointBox()->findData(QStringLiteral("load")));
        editor->addStep(StepKind::WaitInput);
        form->numberBox()->setValue(3);
        form->onBox()->setChecked(true);
        form->timeoutBox()->setValue(20);
        editor->addStep(StepKind::Output);
        form->onBox()->setChecked(true);
        editor->addStep(StepKind::Dwell);
        form->dwellBox()->setValue(500);
        editor->addStep(StepKind::MoveTo);
        form->pointBox()->setCurrentIndex(form->pointBox()->findData(QStringLiteral("unload")));
        editor->addStep(StepKind::Output);
        form->onBox()->setChecked(false);
        QCOMPARE(editor->tree()->topLevelItemCount(), 2);
        QCOMPARE(editor->tree()->topLevelItem(1)->childCount(), 6);
        // The file's limits are not the editor's: this example's come with the file, so compare
        // with them set apart.
        QJsonObject built = SequenceWriter::toJson(*page->sequence(), session->map());
        QJsonObject wanted = normalised(example());
        wanted.remove(QStringLiteral("limits"));
        QCOMPARE(built, wanted);

        // Validation as you type: a wait on an input the controller has not is said at once,
        // on that step, with the file's words.
        edit(QStringLiteral("steps[1].steps[1]"), StepKind::WaitInput)->numberBox()->setValue(9);
        QVERIFY2(page->problems().join(' ').contains(
                     QLatin1String("steps[1].steps[1].wait_input: the controller has no input 9")),
                 qPrintable(page->problems().join('\n')));
        QVERIFY(!page->runPanel()->runButton()->isEnabled());
        QVERIFY(!editor->itemFor(QStringLiteral("steps[1].steps[1]"))->toolTip(0).isEmpty());
        editor->form()->numberBox()->setValue(3);
        editor->form()->timeoutBox()->setValue(20);
        QVERIFY(!page->problems().join(' ').contains(QLatin1String("input 9")));

        // Saved, then opened in a page of its own: the same sequence.
        const QString path = dir.filePath(QStringLiteral("cycle.stepseq"));
        QVERIFY(page->saveFile(path));
        QVERIFY(!page->isModified());
        QWidget other;
        SequencePage reopened(session.get(), &other);
        QVERIFY(reopened.openFile(path));
        QCOMPARE(SequenceWriter::toJson(*reopened.sequence(), session->map()), wanted);

        // The example as written, with its limits: opened and written back unchanged.
        QVERIFY(reopened.openFile(write(QStringLiteral("example.stepseq"), example())));
        QCOMPARE(SequenceWriter::toJson(*reopened.sequence(), session->map()),
                 normalised(example()));
    }

    void editsMoveStepsInAndOutOfLoops()
    {
        SequenceEditor *editor = page->editor();
        editor->addStep(StepKind::Dwell);  // steps[0]
        editor->addStep(StepKind::Repeat); // steps[1]
        editor->addStep(StepKind::Dwell);  // steps[1].steps[0]
        editor->selectPath(QStringLiteral("steps[1]"));
        editor->addStep(StepKind::Output); // steps[2]
        QCOMPARE(editor->selectedPath(), QStringLiteral("steps[2]"));
        QVERIFY(editor->inButton()->isEnabled());
        editor->inButton()->click();
        QCOMPARE(editor->selectedPath(), QStringLiteral("steps[1].steps[1]"));
        QCOMPARE(editor->steps().at(1).steps.at(1).kind, StepKind::Output);
        editor->upButton()->click();
        QCOMPARE(editor->steps().at(1).steps.at(0).kind, StepKind::Output);
        editor->outButton()->click();
        QCOMPARE(editor->selectedPath(), QStringLiteral("steps[2]"));
        QCOMPARE(editor->steps().size(), 3);
        editor->removeButton()->click();
        QCOMPARE(editor->steps().size(), 2);
        // A loop emptied is said to be empty, as a file with it would be.
        editor->selectPath(QStringLiteral("steps[1].steps[0]"));
        editor->removeButton()->click();
        QVERIFY2(page->problems().join(' ').contains(QLatin1String("holds no step")),
                 qPrintable(page->problems().join('\n')));
    }

    void runsTwoCyclesAndRecordsTheRunIn()
    {
        // Motor 1 only (its home switch is IN2), fast dwell: the example's shape.
        QVERIFY(page->openFile(write(QStringLiteral("run.stepseq"), R"({
            "format": "stepcom-sequence", "version": 1,
            "points": {"load": {"motor1": 3.0}, "unload": {"motor1": 1.5}},
            "steps": [{"home": "motor1"},
              {"repeat": 2, "steps": [{"move_to": "load"},
                {"wait_input": 3, "on": true, "timeout_s": 20}, {"output": 1, "on": true},
                {"dwell_ms": 20}, {"move_to": "unload"}, {"output": 1, "on": false}]}]})")));
        QVERIFY2(page->problems().isEmpty(), qPrintable(page->problems().join('\n')));
        sim()->setInput(3, SimDevice::InputForce::On);
        SequenceRunPanel *run = page->runPanel();
        run->cyclesBox()->setValue(2);
        run->checkStepsBox()->setChecked(true);
        QStringList stripLines;
        connect(page, &SequencePage::runText, this,
                [&stripLines](const QString &t) { stripLines << t; });
        QSignalSpy runIn(run, &SequenceRunPanel::runInFinished);
        // The checklist beside a profile of this test, wired as the window wires it.
        WriteFlow writes(session.get(), window.get());
        ChecklistPage checklist(session.get(), &writes, window.get());
        checklist.setProfilePath(dir.filePath(QStringLiteral("machine-s.json")));
        connect(run, &SequenceRunPanel::runInFinished, &checklist, &ChecklistPage::recordRunIn);
        QStringList highlighted;
        connect(run, &SequenceRunPanel::currentStepChanged, this,
                [&highlighted, this](const QString &p) {
                    if (!p.isEmpty() && page->editor()->current() == p)
                        highlighted << p;
                });
        QVERIFY(run->runButton()->isEnabled());
        run->runButton()->click();
        QVERIFY(run->isBusy());
        QVERIFY(!page->editor()->form()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!run->isBusy(), 120000);
        QVERIFY(run->lastResult());
        QCOMPARE(run->lastResult()->word(), QStringLiteral("done"));
        QCOMPARE(run->lastResult()->cyclesDone, 2);
        QVERIFY2(stripLines.contains(QStringLiteral("Running sequence: cycle 2 of 2, step 5")),
                 qPrintable(stripLines.join('\n')));
        QCOMPARE(stripLines.last(), QString()); // the strip's line gone at the end
        QVERIFY(highlighted.contains(QStringLiteral("steps[1].steps[1]")));
        QVERIFY(run->cycleLabel()->text().contains(QLatin1String("median")));
        QCOMPARE(run->lastChecks().size(), 1);
        QCOMPARE(runIn.size(), 1);
        QCOMPARE(runIn.first().at(0).value<StepResult>(), StepResult::Passed);
        const auto m = runIn.first().at(1).value<QList<ChecklistMeasurement>>();
        QHash<QString, QString> byKey;
        for (const ChecklistMeasurement &x : m)
            byKey.insert(x.key, x.value);
        QCOMPARE(byKey.value("cycles"), QStringLiteral("2"));
        QCOMPARE(byKey.value("cycles_done"), QStringLiteral("2"));
        QCOMPARE(byKey.value("check_steps"), QStringLiteral("kept"));
        QVERIFY(byKey.value("cycle_median").toDouble() > 0);
        QVERIFY(page->editor()->form()->isEnabled());
        // On the checklist, and from there on the certificate.
        const ChecklistStep *step = checklist.checklist().step(QStringLiteral("machine.run_in"));
        QVERIFY(step);
        QCOMPARE(step->result(), StepResult::Passed);
        ReportInput in = ReportInput::fromSession(*session, 1, {}, QDateTime::currentDateTime());
        in.checklist = checklist.checklist();
        const QString html = CommissioningReport(in).html(QStringLiteral("x.png"));
        for (const char *s : {"Machine: run-in of its cycle", "Median cycle", "Lost-step check"})
            QVERIFY2(html.contains(QLatin1String(s)), s);
    }

    void stopAndTheEmergencyStopEndTheRun()
    {
        // A wait without a timeout: only a stop ends it.
        QVERIFY(page->openFile(write(QStringLiteral("wait.stepseq"), R"({
            "format": "stepcom-sequence", "version": 1,
            "steps": [{"move_by": {"motor1": 40}}, {"wait_input": 3, "on": true}]})")));
        QVERIFY2(page->problems().isEmpty(), qPrintable(page->problems().join('\n')));
        sim()->setInput(3, SimDevice::InputForce::Off);
        SequenceRunPanel *run = page->runPanel();
        QVERIFY(run->run());
        QTRY_VERIFY_WITH_TIMEOUT(sim()->value(QStringLiteral("motor1.running")).value_or(0) != 0,
                                 10000);
        run->stopButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!run->isBusy(), 20000);
        QCOMPARE(run->lastResult()->word(), QStringLiteral("interrupted"));
        QTRY_COMPARE_WITH_TIMEOUT(sim()->value(QStringLiteral("motor1.running")).value_or(-1),
                                  qint64(0), 5000);

        // The E-STOP, mid-move.
        EmergencyStop estop(session.get());
        MachineStrip strip(session.get(), &estop);
        connect(page, &SequencePage::runText, &strip, &MachineStrip::setSequenceText);
        QVERIFY(run->run());
        QTRY_VERIFY_WITH_TIMEOUT(sim()->value(QStringLiteral("motor1.running")).value_or(0) != 0,
                                 10000);
        QTRY_VERIFY(!strip.sequenceLabel()->isHidden());
        estop.trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!run->isBusy(), 20000);
        QCOMPARE(run->lastResult()->word(), QStringLiteral("estop"));
        QTRY_COMPARE_WITH_TIMEOUT(sim()->value(QStringLiteral("motor1.running")).value_or(-1),
                                  qint64(0), 5000);
        QVERIFY(strip.sequenceLabel()->isHidden());
    }

    void aRefusedFileLeavesThePageAsItWas()
    {
        QVERIFY(page->openFile(write(QStringLiteral("good.stepseq"),
                                     R"({"format": "stepcom-sequence", "version": 1,
                                         "steps": [{"dwell_ms": 5}]})")));
        const QJsonObject before = SequenceWriter::toJson(*page->sequence(), session->map());
        QVERIFY(!page->openFile(write(QStringLiteral("bad.stepseq"),
                                      R"({"format": "stepcom-sequence", "version": 1,
                                          "steps": [{"dwell_ms": 5, "colour": 1}]})")));
        QVERIFY(page->errorBox());
        QVERIFY2(page->errorBox()->detailedText().contains(QLatin1String("unknown key \"colour\"")),
                 qPrintable(page->errorBox()->detailedText()));
        QCOMPARE(SequenceWriter::toJson(*page->sequence(), session->map()), before);
        QVERIFY(page->fileName().endsWith(QLatin1String("good.stepseq")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestSequencePage, Gui)
#include "tst_sequencepage.moc"
