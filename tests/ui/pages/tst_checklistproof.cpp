#include "base/emergencystop.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "commissioning/checklistfile.h"
#include "pages/checklistpage.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/checklist/checklistbacklashstep.h"
#include "widgets/checklist/checklistproofstep.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/plots/marginplot.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <cmath>
#include <memory>

using namespace stepcom;

// The checklist's proofs of an axis against the built-in simulator given a load that stalls
// and play in its drive: the lost-step test records its verdict and warns in the strip, the
// margin search plots its steps and writes its recommendation through the write dialog, the
// backlash test takes the gauge's readings from its field.
class TestChecklistProof : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    std::unique_ptr<QWidget> window;
    std::unique_ptr<DeviceSession> session;
    WriteFlow *writes = nullptr;
    ChecklistPage *page = nullptr;

    std::unique_ptr<SimHost> host; // the fast controller on TCP, when the test uses one

    SimDevice *sim() const { return host ? host->device() : test::simHost(*session)->device(); }
    const ChecklistStep &result(const QString &id) const { return *page->checklist().step(id); }
    QString measured(const QString &id, const QString &key) const
    {
        for (const ChecklistMeasurement &m : result(id).latest()->measurements) {
            if (m.key == key)
                return m.value;
        }
        return {};
    }
    // Motor 1's carriage 1 mm off its home switch (IN2, the negative limit), a start frequency
    // of 60 rpm, and the physics given.
    void machine(const AxisPhysics &motor1)
    {
        MachineSettings m = MachineSettings::ideal();
        m.axes.insert(1, motor1);
        sim()->setMachine(m);
        QVERIFY(sim()->setValue(QStringLiteral("motor1.start_frequency"), 1600));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
    }
    static AxisPhysics axis()
    {
        AxisPhysics p = AxisPhysics::ideal();
        p.startMm = 1.0;
        return p;
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init()
    {
        window = std::make_unique<QWidget>();
        // The margin and lost-step tests make hundreds of moves: a controller on TCP that
        // answers at once; the backlash test the built-in simulator the window offers.
        if (QLatin1String(QTest::currentTestFunction()) ==
            QLatin1String("backlashFromTheGaugeField")) {
            session = std::make_unique<DeviceSession>();
            test::connectToSimulator(*session);
        } else {
            host = std::make_unique<SimHost>();
            QVERIFY(test::startProofSim(*host, test::proofAxis()));
            session = test::proofSession(*host);
        }
        writes = new WriteFlow(session.get(), window.get());
        page = new ChecklistPage(session.get(), writes, window.get());
        page->setProfilePath(dir.filePath(QStringLiteral("machine-p.json")));
    }
    void cleanup()
    {
        window.reset();
        session.reset();
        host.reset();
        QFile::remove(ChecklistFile::pathFor(dir.filePath(QStringLiteral("machine-p.json"))));
    }

    void lostStepsFailTheStepAndWarnInTheStrip()
    {
        AxisPhysics p = axis();
        p.pullOutRpm = 200;
        p.pullInRpm = 100;
        machine(p);
        auto *w = qobject_cast<ChecklistProofStep *>(page->stepWidget("motor1.keeps_steps"));
        QVERIFY(w);
        page->selectStep(QStringLiteral("motor1.keeps_steps"));
        QString plan;
        w->setConfirmer([&plan](const QString &shown) {
            plan = shown;
            return true;
        });
        w->cyclesField()->setValue(1);
        w->distanceField()->setValue(2);
        EmergencyStop estop(session.get());
        MachineStrip strip(session.get(), &estop);
        connect(page, &ChecklistPage::stepsLost, &strip,
                [&strip](int motor, qint64 rpm, std::optional<qint64>) {
                    strip.setProofWarning(
                        QStringLiteral("Motor %1 lost steps at %2 rpm").arg(motor).arg(rpm),
                        QStringLiteral("Find a safe speed…"), [] {});
                });
        QSignalSpy lost(page, &ChecklistPage::stepsLost);
        QVERIFY(w->testButton()->isEnabled());
        w->testButton()->click();
        QVERIFY2(w->stopButton()->isEnabled(), qPrintable(w->log()->toPlainText()));
        QTRY_VERIFY_WITH_TIMEOUT(!w->isRunning(), 120000);
        QVERIFY2(plan.contains(QLatin1String("IN2")), qPrintable(plan));
        QCOMPARE(result("motor1.keeps_steps").result(), StepResult::Failed);
        QCOMPARE(measured("motor1.keeps_steps", "verdict"), QStringLiteral("lost"));
        QCOMPARE(measured("motor1.keeps_steps", "speed_rpm"), QStringLiteral("300"));
        QCOMPARE(measured("motor1.keeps_steps", "simulator"), QStringLiteral("machine")); // TCP
        QCOMPARE(lost.size(), 1);
        QCOMPARE(lost.first().at(1).toLongLong(), 300);
        QVERIFY(strip.proofWarningLabel()->isVisibleTo(&strip));
        QVERIFY(strip.proofWarningLabel()->text().contains(QLatin1String("300 rpm")));
        QCOMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 300); // put back
        QVERIFY(!w->stopButton()->isEnabled());
    }

    void marginPlotsAndWritesItsRecommendation()
    {
        AxisPhysics p = axis();
        p.pullOutRpm = 250;
        p.pullInRpm = 100;
        machine(p);
        auto *w = qobject_cast<ChecklistProofStep *>(page->stepWidget("motor1.keeps_steps"));
        QVERIFY(w);
        w->setConfirmer([](const QString &) { return true; });
        w->cyclesField()->setValue(1);
        w->distanceField()->setValue(2);
        w->fromField()->setValue(200);
        w->toField()->setValue(300);
        w->stepField()->setValue(100);
        QSignalSpy lost(page, &ChecklistPage::stepsLost);
        w->marginButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!w->isRunning(), 150000);
        QCOMPARE(w->plot()->pointCount(), 2);
        QCOMPARE(w->plot()->keptSeries()->count(), 1);
        QCOMPARE(w->plot()->lostSeries()->count(), 1);
        QCOMPARE(w->recommended(), std::optional<qint64>(150));
        QCOMPARE(measured("motor1.keeps_steps", "stall_rpm"), QStringLiteral("300"));
        // The motor's own 300 rpm is past the stall: the step fails and the strip hears it.
        QCOMPARE(result("motor1.keeps_steps").result(), StepResult::Failed);
        QCOMPARE(lost.size(), 1);
        QCOMPARE(lost.first().at(2).value<std::optional<qint64>>(), std::optional<qint64>(150));
        QVERIFY(w->writeButton()->isVisibleTo(w));
        QVERIFY(w->writeButton()->text().contains(QLatin1String("150")));
        QSignalSpy kept(page, &ChecklistPage::stepsKept);
        page->writeRecommendation(1);
        QTRY_VERIFY(writes->dialog());
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        writes->dialog()->accept();
        QTRY_COMPARE(written.size(), 1);
        QTRY_COMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 150);
        QTRY_COMPARE(kept.size(), 1);
    }

    void backlashFromTheGaugeField()
    {
        AxisPhysics p = axis();
        p.startMm = 20;
        p.backlashMm = 0.1;
        machine(p);
        auto *w = qobject_cast<ChecklistBacklashStep *>(page->stepWidget("motor1.backlash"));
        QVERIFY(w);
        page->selectStep(QStringLiteral("motor1.backlash"));
        w->setConfirmer([](const QString &) { return true; });
        w->cyclesField()->setValue(2);
        // The gauge is the simulator's carriage.
        connect(w, &ChecklistBacklashStep::readingWanted, w, [this, w] {
            w->readingField()->setValue(sim()->truth().axes.at(0).carriageMm);
            w->enterButton()->click();
        });
        w->startButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!w->isRunning(), 60000);
        QVERIFY2(result("motor1.backlash").result() == StepResult::Passed,
                 qPrintable(w->findChild<QLabel *>(QStringLiteral("stepStatus"))
                                ? w->findChild<QLabel *>(QStringLiteral("stepStatus"))->text()
                                : QString()));
        const double backlash = measured("motor1.backlash", "backlash").toDouble();
        QVERIFY2(std::abs(backlash - 0.1) <= 0.02, qPrintable(QString::number(backlash)));
        QCOMPARE(measured("motor1.backlash", "readings").split(QLatin1Char(' ')).size(), 5);
        QCOMPARE(measured("motor1.backlash", "simulator"), QStringLiteral("simulator"));
        QCOMPARE(sim()->value(QStringLiteral("motor1.speed")).value_or(-1), 300);
    }

    void stripWarningRunsItsAction()
    {
        EmergencyStop estop(session.get());
        MachineStrip strip(session.get(), &estop);
        QVERIFY(!strip.proofWarningLabel()->isVisibleTo(&strip));
        int clicked = 0;
        strip.setProofWarning(QStringLiteral("Motor 1 lost steps at 300 rpm"),
                              QStringLiteral("Use 225 rpm…"), [&clicked] { ++clicked; });
        QVERIFY(strip.proofActionButton()->isVisibleTo(&strip));
        strip.proofActionButton()->click();
        QCOMPARE(clicked, 1);
        strip.setProofWarning({}, {}, {});
        QVERIFY(!strip.proofWarningLabel()->isVisibleTo(&strip));
        QVERIFY(!strip.proofActionButton()->isVisibleTo(&strip));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestChecklistProof, Gui)
#include "tst_checklistproof.moc"
