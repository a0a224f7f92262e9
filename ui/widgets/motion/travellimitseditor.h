#pragma once

#include <QGroupBox>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace stepcom {

class DeviceSession;

// The software travel limits per axis (StepCom's, not the controller's): a min and a max, each
// optional; "Apply" checks and puts them in the session and saves them with the connection
// settings. Per axis it says how far a hold-to-move jog can overrun a limit at the current
// speed and poll rate (TravelLimits::describeOverrun) and that a lost link is not covered.
class TravelLimitsEditor : public QGroupBox
{
    Q_OBJECT
public:
    explicit TravelLimitsEditor(DeviceSession *session, QWidget *parent = nullptr);

    QCheckBox *minCheck(int motor) const { return m_rows.value(motor - 1).minOn; }
    QDoubleSpinBox *minField(int motor) const { return m_rows.value(motor - 1).min; }
    QCheckBox *maxCheck(int motor) const { return m_rows.value(motor - 1).maxOn; }
    QDoubleSpinBox *maxField(int motor) const { return m_rows.value(motor - 1).max; }
    QPushButton *applyButton() const { return m_apply; }
    QString overrunText(int motor) const;
    QString problemText() const;
    // What the limits are and are not, for the page's "About this page" and the note's tooltip.
    QString explanation() const;

    // The limits saved with the connection settings (QSettings), into the session.
    static void restoreSaved(DeviceSession *session);

protected:
    void changeEvent(QEvent *event) override;

private:
    struct Row
    {
        QLabel *name = nullptr;
        QCheckBox *minOn = nullptr;
        QDoubleSpinBox *min = nullptr;
        QCheckBox *maxOn = nullptr;
        QDoubleSpinBox *max = nullptr;
        QLabel *overrun = nullptr;
    };
    void apply();
    void showLimits();
    void refreshOverrun();
    void retranslate();

    DeviceSession *m_session;
    QList<Row> m_rows;
    QPushButton *m_apply;
    QLabel *m_problem;
    QLabel *m_note;
};

} // namespace stepcom
