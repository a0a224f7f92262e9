#pragma once

#include "proof/backlashtest.h"
#include "widgets/checklist/checkliststepwidget.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace stepcom {

// "Motor N: backlash" (docs/proving.md): with a dial gauge on the carriage, BacklashTest
// approaches a point from one side and moves on and back; after each move the user types the
// gauge's reading into the field. The result (the lost motion on reversal, its spread) is
// recorded, with the advice to approach from one side when it is more than the resolution.
class ChecklistBacklashStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistBacklashStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                          QWidget *parent = nullptr);

    QPushButton *startButton() const { return m_start; }
    QPushButton *stopButton() const { return m_stop; }
    QDoubleSpinBox *readingField() const { return m_reading; }
    QPushButton *enterButton() const { return m_enter; }
    QDoubleSpinBox *distanceField() const { return m_distance; }
    QSpinBox *cyclesField() const { return m_cycles; }
    bool isRunning() const { return m_test->isRunning(); }
    void setConfirmer(std::function<bool(const QString &plan)> confirm)
    {
        m_confirm = std::move(confirm);
    }
    void retranslate() override;

Q_SIGNALS:
    // The test waits for reading `index` (0: after the approach).
    void readingWanted(int index);

private:
    void onFinished(const BacklashResult &r);
    void setRunning(bool running);

    BacklashTest *m_test;
    QDoubleSpinBox *m_distance;
    QSpinBox *m_cycles;
    QPushButton *m_start;
    QPushButton *m_stop;
    QDoubleSpinBox *m_reading;
    QPushButton *m_enter;
    QLabel *m_distanceLabel;
    QLabel *m_cyclesLabel;
    int m_wanted = -1; // the reading asked for, -1 none
    QString m_where;
    std::function<bool(const QString &)> m_confirm;
};

} // namespace stepcom
