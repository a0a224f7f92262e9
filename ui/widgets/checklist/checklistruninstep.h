#pragma once

#include "widgets/checklist/checkliststepwidget.h"

class QPushButton;

namespace stepcom {

// "Machine: run-in of its cycle": the run itself is the Sequence page's (its points, steps and
// Run); this step sends the user there and records what a run-in of more than one cycle ended
// with, so the certificate carries the cycles, the cycle time and the lost-step check.
class ChecklistRunInStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistRunInStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                       QWidget *parent = nullptr);

    QPushButton *openButton() const { return m_open; }
    // A run-in ended: `summary` is what the Sequence page said of it.
    void record(StepResult result, const QList<ChecklistMeasurement> &measurements,
                const QString &summary);
    void retranslate() override;

Q_SIGNALS:
    void sequencePageWanted();

private:
    QPushButton *m_open;
};

} // namespace stepcom
