#pragma once

#include "proof/marginfinder.h"
#include "proof/proofresult.h"
#include "widgets/checklist/checkliststepwidget.h"

#include <optional>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace stepcom {

class AxisProof;
class MarginPlot;

// "Motor N: keeps its steps" (docs/proving.md): the lost-step test at the motor's own speed and
// acceleration, and the margin search of the speed or the acceleration with its plot. Each asks
// first with what it will do, shows every step as it runs, stops at once on Stop, and records
// its verdict and figures (with "simulator" when it ran on one). Lost steps at the motor's own
// settings are said to the window (stepsLost), and the margin's recommendation can be written
// through the usual write dialog.
class ChecklistProofStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistProofStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                       QWidget *parent = nullptr);

    QPushButton *testButton() const { return m_test; }
    QPushButton *marginButton() const { return m_margin; }
    QPushButton *stopButton() const { return m_stop; }
    QPushButton *writeButton() const { return m_write; }
    QCheckBox *accelBox() const { return m_accel; }
    QSpinBox *cyclesField() const { return m_cycles; }
    QDoubleSpinBox *distanceField() const { return m_distance; }
    QSpinBox *fromField() const { return m_from; }
    QSpinBox *toField() const { return m_to; }
    QSpinBox *stepField() const { return m_step; }
    MarginPlot *plot() const { return m_plot; }
    QPlainTextEdit *log() const { return m_log; }
    bool isRunning() const;
    // The margin's recommendation, once a search found one.
    std::optional<qint64> recommended() const { return m_recommended; }
    // Opens the write dialog for the recommendation (the strip's button comes here).
    void writeRecommendation();
    // Answers the confirmation without a dialog: tests and the accessibility walk.
    void setConfirmer(std::function<bool(const QString &plan)> confirm)
    {
        m_confirm = std::move(confirm);
    }
    void retranslate() override;

Q_SIGNALS:
    // The motor lost steps at its own speed and acceleration; `recommended` when a margin
    // search gave one.
    void stepsLost(int motor, qint64 speedRpm, std::optional<qint64> recommended);
    // A later test kept its steps, or the recommendation was written: the warning is over.
    void stepsKept(int motor);

private:
    void startTest();
    void startMargin();
    void confirmThen(const QString &plan, std::function<void()> yes, std::function<void()> no);
    void say(const QString &text);
    void setRunning(bool running);
    void onTested(const LostStepResult &r);
    void onMargin(const MarginResult &r);

    AxisProof *m_proof;
    MarginFinder *m_finder;
    QSpinBox *m_cycles;
    QDoubleSpinBox *m_distance;
    QSpinBox *m_from;
    QSpinBox *m_to;
    QSpinBox *m_step;
    QCheckBox *m_accel;
    QPushButton *m_test;
    QPushButton *m_margin;
    QPushButton *m_stop;
    QPushButton *m_write;
    QPlainTextEdit *m_log;
    MarginPlot *m_plot;
    QLabel *m_cyclesLabel;
    QLabel *m_distanceLabel;
    QLabel *m_rangeLabel;
    std::optional<qint64> m_recommended;
    bool m_recommendedAccel = false;
    std::function<bool(const QString &)> m_confirm;
};

} // namespace stepcom
