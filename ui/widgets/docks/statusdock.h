#pragma once

#include <QDockWidget>
#include <QTimer>

class QGroupBox;
class QLabel;

namespace stepcom {

class DeviceSession;
class Led;

// The live status, visible beside every page: each motor's position in the map's distance unit
// (large digits), its running state, the inputs and outputs as lamps. Off at first: the
// machine strip shows the same on every page (View → Status brings it back); how often the
// status is read is the Connection page's. Everything reads "unknown" while nothing is known.
// Motor, input and output counts follow the register map.
class StatusDock : public QDockWidget
{
    Q_OBJECT
public:
    explicit StatusDock(DeviceSession *session, QWidget *parent = nullptr);

    int motorCount() const { return int(m_positions.size()); }
    int inputCount() const { return int(m_inputLeds.size()); }
    int outputCount() const { return int(m_outputLeds.size()); }
    QString positionText(int motor) const;
    QString runningText(int motor) const;
    // "referenced" / "not referenced (E-STOP)" for the motor.
    QString referenceText(int motor) const;
    Led *runningLed(int motor) const { return m_runningLeds.value(motor - 1); }
    Led *inputLed(int n) const { return m_inputLeds.value(n - 1); }
    Led *outputLed(int n) const { return m_outputLeds.value(n - 1); }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void scheduleRefresh();
    void refresh();

    DeviceSession *m_session;
    QStringList m_positionKeys;
    QStringList m_runningKeys;
    QStringList m_inputKeys;
    QStringList m_outputKeys;
    QList<QGroupBox *> m_motorBoxes;
    QList<QLabel *> m_positions;
    QList<Led *> m_runningLeds;
    QList<QLabel *> m_running;
    QList<QLabel *> m_references;
    QGroupBox *m_ioBox;
    QLabel *m_inputsCaption;
    QLabel *m_outputsCaption;
    QList<Led *> m_inputLeds;
    QList<QLabel *> m_inputNames;
    QList<Led *> m_outputLeds;
    QList<QLabel *> m_outputNames;
    QTimer m_refresh; // coalesces the store's per-key signals into one update a cycle
};

} // namespace stepcom
