#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/stepmove.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/motion/stepmovepanel.h"
#include "widgets/motion/travellimitseditor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include <memory>

using namespace stepcom;

// The Jog page's step jog, move-to and software travel limits, against the simulator.
class TestStepMovePanel : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    void clickAndWait(QPushButton *button)
    {
        QSignalSpy finished(session->stepMove(), &StepMove::finished);
        button->click();
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 20000);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().remove(QStringLiteral("connection/travelLimits"));
    }
    void init()
    {
        session = std::make_unique<DeviceSession>();
        test::connectToSimulator(*session);
    }
    void cleanup() { session.reset(); }

    void stepsAndMoveTo()
    {
        StepMovePanel panel(session.get(), 1);
        QTRY_VERIFY(panel.plusButton()->isEnabled());
        panel.stepChoice()->setCurrentIndex(3); // 10 mm
        clickAndWait(panel.plusButton());
        QCOMPARE(sim()->position(1), 1000);
        panel.stepChoice()->setCurrentIndex(4); // custom
        panel.customStep()->setValue(2.25);
        clickAndWait(panel.minusButton());
        QCOMPARE(sim()->position(1), 775);
        panel.targetField()->setValue(-1.5);
        clickAndWait(panel.moveToButton());
        QCOMPARE(sim()->position(1), -150);
        QVERIFY2(panel.resultText().contains(QStringLiteral("done at -1.50 mm")),
                 qPrintable(panel.resultText()));
        // Pending edits of the single move: the buttons refuse and say why.
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.direction"), 1).isEmpty());
        QVERIFY(!panel.plusButton()->isEnabled());
        QVERIFY(panel.plusButton()->toolTip().contains(QStringLiteral("Write or revert")));
    }

    void limitsAreCheckedAppliedSavedAndRefuseATarget()
    {
        TravelLimitsEditor editor(session.get());
        editor.minCheck(1)->setChecked(true);
        editor.minField(1)->setValue(9);
        editor.maxCheck(1)->setChecked(true);
        editor.maxField(1)->setValue(1);
        editor.applyButton()->click();
        QVERIFY2(editor.problemText().contains(QStringLiteral("must be below")),
                 qPrintable(editor.problemText()));
        QVERIFY(session->travelLimits().isEmpty()); // nothing half-applied
        editor.minField(1)->setValue(-5);
        editor.maxField(1)->setValue(5);
        editor.applyButton()->click();
        QVERIFY(editor.problemText().isEmpty());
        QCOMPARE(session->travelLimits().axis(1).max, std::optional<qint64>(500));
        // Saved with the connection settings: a new window's session gets them.
        DeviceSession other;
        TravelLimitsEditor::restoreSaved(&other);
        QCOMPARE(other.travelLimits(), session->travelLimits());
        // The overrun is worked out from the speed, pitch and the link's answers.
        QTRY_VERIFY(editor.overrunText(1).contains(QStringLiteral("up to")));

        StepMovePanel panel(session.get(), 1);
        panel.targetField()->setValue(6);
        clickAndWait(panel.moveToButton());
        QVERIFY2(panel.resultText().contains(QStringLiteral("beyond the software travel limit")),
                 qPrintable(panel.resultText()));
        QCOMPARE(sim()->position(1), 0);
        QSettings().remove(QStringLiteral("connection/travelLimits"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestStepMovePanel, Gui)
#include "tst_stepmovepanel.moc"
