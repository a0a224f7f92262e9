#pragma once

#include "widgets/checklist/checkliststepwidget.h"

#include <optional>

class QDoubleSpinBox;
class QPushButton;

namespace stepcom {

struct StepMoveResult;

// "Motor N: travel calibration": move a distance the user chooses, the user types what was
// measured, StepCom proposes pitch × measured ÷ commanded (TravelCalibration) and writes it on
// Yes through WriteFlow.
class ChecklistCalibrationStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistCalibrationStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                             QWidget *parent = nullptr);

    QDoubleSpinBox *commandedField() const { return m_commanded; }
    QPushButton *moveButton() const { return m_move; }
    QDoubleSpinBox *measuredField() const { return m_measured; }
    QPushButton *proposeButton() const { return m_propose; }
    QPushButton *writeButton() const { return m_write; }
    void retranslate() override;

private:
    void onMoved(const StepMoveResult &result);
    void propose();
    QList<ChecklistMeasurement> measurements(qint64 before, std::optional<qint64> after) const;

    QDoubleSpinBox *m_commanded;
    QPushButton *m_move;
    QDoubleSpinBox *m_measured;
    QPushButton *m_propose;
    QPushButton *m_write;
    bool m_mine = false;
    double m_moved = 0;               // the distance commanded by the last move that arrived
    std::optional<qint64> m_pitchNow; // the pitch it was moved with
    std::optional<qint64> m_proposal;
};

} // namespace stepcom
