#pragma once

#include "motion/motionoutcome.h"
#include "widgets/checklist/checkliststepwidget.h"

class QComboBox;
class QPushButton;

namespace stepcom {

// The steps that run a motion command and take MotionSupervisor's verdict: a motor's homing
// (passed only "referenced"), the machine's homing order (every axis in the order referenced)
// and the interpolation test (the configured arc or line, passed only "done" at its end point).
class ChecklistMotionStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistMotionStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                        QWidget *parent = nullptr);

    QPushButton *runButton() const { return m_run; }
    QComboBox *pathChoice() const { return m_path; } // the interpolation test's arc or line
    void retranslate() override;

private:
    QString commandKey() const;
    void onFinished(const MotionOutcome &outcome);

    QPushButton *m_run;
    QComboBox *m_path = nullptr;
    QString m_running; // the command this step sent and waits for
};

} // namespace stepcom
