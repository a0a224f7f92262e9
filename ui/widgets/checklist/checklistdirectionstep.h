#pragma once

#include "widgets/checklist/checkliststepwidget.h"

#include <optional>

class QDoubleSpinBox;
class QPushButton;

namespace stepcom {

struct StepMoveResult;

// "Motor N: direction": a small single move as configured, then "did the axis move toward + ?".
// No records a failure and offers to flip the direction register (written through WriteFlow).
class ChecklistDirectionStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistDirectionStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                           QWidget *parent = nullptr);

    QDoubleSpinBox *distanceField() const { return m_distance; }
    QPushButton *moveButton() const { return m_move; }
    QPushButton *yesButton() const { return m_yes; }
    QPushButton *noButton() const { return m_no; }
    QPushButton *flipButton() const { return m_flip; }
    void retranslate() override;

private:
    void onMoved(const StepMoveResult &result);
    void answer(bool towardPlus);

    QDoubleSpinBox *m_distance;
    QPushButton *m_move;
    QPushButton *m_yes;
    QPushButton *m_no;
    QPushButton *m_flip;
    bool m_mine = false;
    qint64 m_directionUsed = 0;
    std::optional<qint64> m_flipTo;
};

} // namespace stepcom
