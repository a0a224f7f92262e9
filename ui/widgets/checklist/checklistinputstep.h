#pragma once

#include "commissioning/inputtest.h"
#include "widgets/checklist/checkliststepwidget.h"

class QPushButton;

namespace stepcom {

// "Motor N: positive limit / negative limit / home input": "press it now" takes the inputs of
// the last poll as the baseline, every poll after it is watched (InputObservation); "Done"
// judges which input answered against the configuration (InputTest) and, when another one
// did, offers the register values that fix it (written through WriteFlow).
class ChecklistInputStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistInputStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                       QWidget *parent = nullptr);

    QPushButton *watchButton() const { return m_watch; }
    QPushButton *doneButton() const { return m_done; }
    QPushButton *fixButton() const { return m_fix; }
    bool isWatching() const { return m_observation.started(); }
    void retranslate() override;

private:
    InputTest::Role role() const;
    QList<MotorWiring> wiring() const;
    void startWatching();
    void judge();

    QPushButton *m_watch;
    QPushButton *m_done;
    QPushButton *m_fix;
    InputObservation m_observation;
    QList<InputFix> m_fixes;
};

} // namespace stepcom
