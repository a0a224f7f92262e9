#pragma once

#include "commissioning/checkliststep.h"
#include "motion/travellimits.h"
#include "proof/proofresult.h"
#include "sequence/sequence.h"
#include "sequence/sequenceresult.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <optional>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace stepcom {

class AxisProof;
class DeviceSession;
class SequenceRunner;

// Runs the page's sequence on the controller: the number of cycles, single-step mode and the
// lost-step check at the end; Run (after a question with the plan), Pause after the current
// step, Step, Resume and Stop; the cycle counter, the last and median cycle time and the step
// running. A run of two cycles or more is a run-in: its result (cycles, cycle time, the check's
// verdict) goes to the commissioning checklist, and from there on the certificate.
class SequenceRunPanel : public QWidget
{
    Q_OBJECT
public:
    SequenceRunPanel(DeviceSession *session, QWidget *parent = nullptr);
    ~SequenceRunPanel() override;

    // The sequence to run, or nullopt when it has problems (the page shows them).
    void setSource(std::function<std::optional<Sequence>()> source)
    {
        m_source = std::move(source);
    }
    // Answers the question before a run instead of a message box (tests, the shots).
    void setConfirmer(std::function<bool(const QString &plan)> confirm)
    {
        m_confirm = std::move(confirm);
    }
    // The sequence has problems (false): Run waits.
    void setRunnable(bool runnable);
    bool isBusy() const;

    // Starts as Run does, after the question; false when it could not start (said).
    bool run();
    void stop();

    SequenceRunner *runner() const { return m_runner; }
    QSpinBox *cyclesBox() const { return m_cycles; }
    QCheckBox *singleStepBox() const { return m_single; }
    QCheckBox *checkStepsBox() const { return m_check; }
    QPushButton *runButton() const { return m_run; }
    QPushButton *pauseButton() const { return m_pause; }
    QPushButton *stepButton() const { return m_step; }
    QPushButton *resumeButton() const { return m_resume; }
    QPushButton *stopButton() const { return m_stop; }
    QLabel *statusLabel() const { return m_status; }
    QLabel *cycleLabel() const { return m_cycle; }
    // The last run's result and the check's, while none runs.
    std::optional<SequenceResult> lastResult() const { return m_last; }
    QList<LostStepResult> lastChecks() const { return m_checks; }

Q_SIGNALS:
    // The step running (its path), empty when none.
    void currentStepChanged(const QString &path);
    void busyChanged(bool busy);
    // "Running sequence: cycle 3 of 10, step 4" while a run goes on; empty when it ended.
    void stripText(const QString &text);
    // A run-in ended: the checklist's result.
    void runInFinished(stepcom::StepResult result,
                       const QList<stepcom::ChecklistMeasurement> &measurements,
                       const QString &summary);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateButtons();
    void onStep(int cycle, const QString &path);
    void onFinished(const SequenceResult &result);
    void checkNext(QList<int> motors);
    void finishAll();
    QString stripLine() const;

    DeviceSession *m_session;
    SequenceRunner *m_runner;
    QPointer<AxisProof> m_proof;
    std::function<std::optional<Sequence>()> m_source;
    std::function<bool(const QString &)> m_confirm;
    Sequence m_sequence; // the one running
    int m_cyclesWanted = 1;
    int m_stepNumber = 0;
    bool m_runnable = false;
    bool m_checking = false;
    std::optional<TravelLimits> m_userLimits; // put back after the check
    std::optional<SequenceResult> m_last;
    QList<LostStepResult> m_checks;
    QSpinBox *m_cycles;
    QCheckBox *m_single;
    QCheckBox *m_check;
    QPushButton *m_run;
    QPushButton *m_pause;
    QPushButton *m_step;
    QPushButton *m_resume;
    QPushButton *m_stop;
    QLabel *m_cycle;
    QLabel *m_status;
};

} // namespace stepcom
