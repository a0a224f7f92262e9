#pragma once

#include "sequence/sequencestep.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSpinBox;

namespace stepcom {

class RegisterMap;

// The fields of one step of a sequence: what it does (home, move to, wait for an input, ...)
// and the values that kind has, the others hidden. It holds no judgement of its own: the
// page checks the whole sequence with the file's checks (SequenceParser, SequenceCheck) after
// every edit, so a step is judged exactly as the same step in a file would be.
class SequenceStepForm : public QWidget
{
    Q_OBJECT
public:
    SequenceStepForm(const RegisterMap &map, QWidget *parent = nullptr);

    // Shows `step`; `points` are the names a move_to may use.
    void setStep(const SequenceStep &step, const QStringList &points);
    // The step as the fields say now (its path and inner steps as given to setStep).
    SequenceStep step() const;
    void clear();
    bool hasStep() const { return m_has; }

    QComboBox *kindBox() const { return m_kind; }
    QComboBox *homeBox() const { return m_home; }
    QComboBox *pointBox() const { return m_point; }
    QCheckBox *axisBox(int motor) const { return m_axisOn.value(motor - 1); }
    QDoubleSpinBox *axisValue(int motor) const { return m_axisValue.value(motor - 1); }
    QSpinBox *numberBox() const { return m_number; }
    QCheckBox *onBox() const { return m_on; }
    QDoubleSpinBox *timeoutBox() const { return m_timeout; }
    QComboBox *outputsBox() const { return m_outputs; }
    QSpinBox *dwellBox() const { return m_dwell; }
    QSpinBox *countBox() const { return m_count; }

    // "Move to a point", translated: the kind's name in the list.
    static QString kindLabel(SequenceStep::Kind kind);
    // A new step of `kind` with values that make sense to start from.
    static SequenceStep defaultStep(SequenceStep::Kind kind, const QStringList &points);

Q_SIGNALS:
    // The user changed a field.
    void edited();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void showRows();
    void changed();

    const RegisterMap &m_map;
    QFormLayout *m_form;
    QComboBox *m_kind;
    QComboBox *m_home;
    QComboBox *m_point;
    QList<QCheckBox *> m_axisOn;
    QList<QDoubleSpinBox *> m_axisValue;
    QList<QLabel *> m_axisLabel;
    QSpinBox *m_number;
    QCheckBox *m_on;
    QDoubleSpinBox *m_timeout;
    QComboBox *m_outputs;
    QSpinBox *m_dwell;
    QSpinBox *m_count;
    QLabel *m_labels[8] = {};
    SequenceStep m_step;
    QStringList m_points;
    bool m_has = false;
    bool m_filling = false;
};

} // namespace stepcom
