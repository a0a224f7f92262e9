#pragma once

#include "session/stepmove.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace stepcom {

class DeviceSession;

// One motor's step jog and move-to: a step of 0.01 / 0.1 / 1 / 10 axis units or a custom one,
// − and + buttons, a "move to" position. It runs through the session's StepMove, which uses
// the single move's distance and direction registers and puts the user's values back (the
// panel says so); the last result, with where a cut-off step ended, stays shown.
class StepMovePanel : public QWidget
{
    Q_OBJECT
public:
    StepMovePanel(DeviceSession *session, int motor, QWidget *parent = nullptr);

    QComboBox *stepChoice() const { return m_step; }
    QDoubleSpinBox *customStep() const { return m_custom; }
    QPushButton *minusButton() const { return m_minus; }
    QPushButton *plusButton() const { return m_plus; }
    QDoubleSpinBox *targetField() const { return m_target; }
    QPushButton *moveToButton() const { return m_moveTo; }
    QString resultText() const;
    // The step chosen (axis units, > 0).
    double stepSize() const;
    void retranslate();
    // How steps and move-to work: the buttons' tooltip and What's This, and the Jog page's
    // "About this page".
    static QString explanation();

protected:
    void changeEvent(QEvent *event) override;

private:
    void run(StepMoveRequest::Kind kind, double value);
    void refresh();

    DeviceSession *m_session;
    int m_motor;
    QLabel *m_stepLabel;
    QComboBox *m_step;
    QDoubleSpinBox *m_custom;
    QPushButton *m_minus;
    QPushButton *m_plus;
    QLabel *m_targetLabel;
    QDoubleSpinBox *m_target;
    QPushButton *m_moveTo;
    QLabel *m_result;
    bool m_mine = false; // the step running is this panel's
};

} // namespace stepcom
