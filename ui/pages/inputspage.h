#pragma once

#include "base/page.h"
#include "device/wiringcheck.h"

#include <QHash>

class QGridLayout;
class QGroupBox;
class QLabel;

namespace stepcom {

class Led;
class ParameterField;
class WiringWarnings;

// Which input is each motor's positive limit, negative limit and home, the wiring check's
// warnings about them, and live lamps of the inputs and outputs.
class InputsPage : public Page
{
    Q_OBJECT
public:
    explicit InputsPage(DeviceSession *session, QWidget *parent = nullptr);

    QString title() const override;
    QString iconName() const override { return QStringLiteral("inputs"); }
    Stage stage() const override { return Stage::SetUp; }
    QStringList keys() const override;

    // `localKey`: "limit_positive", "limit_negative" or "home_input".
    ParameterField *field(int motor, const QString &localKey) const;
    WiringWarnings *warningsView() const { return m_warnings; }
    QList<WiringWarning> warnings() const;
    int inputCount() const { return int(m_inputLeds.size()); }
    int outputCount() const { return int(m_outputLeds.size()); }
    Led *inputLed(int n) const { return m_inputLeds.value(n - 1); }
    Led *outputLed(int n) const { return m_outputLeds.value(n - 1); }

protected:
    void retranslate() override;

private:
    QList<MotorWiring> wiring() const;
    void updateWiring();
    void updateLamps();

    int m_motors = 0;
    QStringList m_keys;        // the limit and home fields, motor by motor
    QStringList m_watchedKeys; // what the wiring check and the lamp captions depend on
    QHash<QString, ParameterField *> m_fields;
    QGroupBox *m_wiringBox;
    QGroupBox *m_checkBox;
    QGroupBox *m_inputsBox;
    QGroupBox *m_outputsBox;
    QList<QLabel *> m_columnHeads;
    QList<QLabel *> m_motorLabels;
    QLabel *m_homeNote;
    QLabel *m_modeLine;
    WiringWarnings *m_warnings;
    QList<Led *> m_inputLeds;
    QList<QLabel *> m_inputNames;
    QList<QLabel *> m_inputUses;
    QList<Led *> m_outputLeds;
    QList<QLabel *> m_outputNames;
};

} // namespace stepcom
