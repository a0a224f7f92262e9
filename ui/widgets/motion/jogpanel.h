#pragma once

#include "session/jogcontroller.h"

#include <QGroupBox>

class QLabel;
class QPushButton;

namespace stepcom {

class DeviceSession;
class JogButton;
class Led;
class ParameterField;
class StepMovePanel;
class WriteFlow;

// One motor's hands-on controls: hold-to-move reverse/forward, stop, the jog speed with its own
// "apply", the running lamp and what the jog is doing (the position is the machine strip's,
// under every page: one place for a live value), the single move with the distance, direction
// and speed it will use, and homing. Everything shown comes from the session's store; the
// speed is written through the window's WriteFlow, as "Write changes" writes.
class JogPanel : public QGroupBox
{
    Q_OBJECT
public:
    JogPanel(DeviceSession *session, JogController *jog, WriteFlow *writes, int motor,
             QWidget *parent = nullptr);

    int motor() const { return m_motor; }
    JogButton *reverseButton() const { return m_reverse; }
    JogButton *forwardButton() const { return m_forward; }
    QPushButton *stopButton() const { return m_stop; }
    ParameterField *speedField() const { return m_speed; }
    QPushButton *applySpeedButton() const { return m_applySpeed; }
    QPushButton *moveButton() const { return m_move; }
    QPushButton *homeButton() const { return m_home; }
    Led *runningLed() const { return m_led; }
    StepMovePanel *stepPanel() const { return m_steps; }
    // "referenced" / "not referenced (E-STOP)": homed onto the home input since the last loss.
    QString referenceText() const;
    QString statusText() const;
    // The motor's position in the map's unit, as the strip shows it ("—" when not known).
    QString positionText() const;
    QString moveText() const;
    QStringList keys() const { return m_keys; }
    // Focusable widgets in the order Tab visits them.
    QList<QWidget *> tabChain() const;
    void retranslate();
    // Release the hold buttons (after an E-STOP or a stop): nothing stays pressed.
    void letGo();

protected:
    void changeEvent(QEvent *event) override;

private:
    QString key(const QString &localKey) const;
    const Parameter *param(const QString &localKey) const;
    void applySpeed();
    void command(const QString &localKey);
    void refresh();
    // Why the single move cannot go now; empty when it can.
    QString moveBlocker() const;
    bool motorBusy() const;

    DeviceSession *m_session;
    JogController *m_jog;
    WriteFlow *m_writes;
    int m_motor;
    QStringList m_keys;
    JogButton *m_reverse;
    JogButton *m_forward;
    QPushButton *m_stop;
    Led *m_led;
    QLabel *m_status;
    QLabel *m_speedLabel;
    ParameterField *m_speed = nullptr;
    QPushButton *m_applySpeed;
    QLabel *m_speedNote;
    QLabel *m_moveLabel;
    QLabel *m_moveInfo;
    QPushButton *m_move;
    QLabel *m_reference;
    QLabel *m_homeLabel;
    QLabel *m_homeInfo;
    QPushButton *m_home;
    StepMovePanel *m_steps = nullptr;
    bool m_hideOutcome = false; // a jog since the last outcome: it no longer describes the axis
};

} // namespace stepcom
