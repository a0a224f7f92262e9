#pragma once

#include "base/page.h"
#include "motion/motorderived.h"

class QGroupBox;
class QLabel;
class QPushButton;

namespace stepcom {

class DerivedValues;
class ParameterForm;

// One motor's parameters (any motor of the map: one class for all of them), the values a
// technician derives from them by hand, and the motor's stop button.
class MotorPage : public Page
{
    Q_OBJECT
public:
    MotorPage(DeviceSession *session, int motor, QWidget *parent = nullptr);

    QString title() const override;
    QString iconName() const override { return QStringLiteral("motor"); }
    Stage stage() const override { return Stage::SetUp; }
    QStringList keys() const override;
    int motor() const { return m_motor; }

    ParameterForm *form() const { return m_form; }
    DerivedValues *derivedValues() const { return m_derived; }
    QPushButton *stopButton() const { return m_stop; }
    // The derived values of what the page shows now (edits included).
    MotorDerived derived() const;

protected:
    void retranslate() override;

private:
    QString key(const QString &localKey) const;
    std::optional<double> shown(const QString &localKey) const;
    void updateDerived();
    void updateEnabled();

    int m_motor;
    QStringList m_keys;
    QGroupBox *m_parameterBox;
    QGroupBox *m_derivedBox;
    QGroupBox *m_motionBox;
    ParameterForm *m_form;
    DerivedValues *m_derived;
    QLabel *m_derivedNote;
    QLabel *m_stopNote;
    QPushButton *m_stop;
};

} // namespace stepcom
