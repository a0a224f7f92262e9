#pragma once

#include "gamepad/gamepadjog.h"

#include <QGroupBox>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace stepcom {

class DeviceSession;
class SdlGamepad;

// The Jog page's game pad: "Jog with a game pad" (off until the user ticks it, remembered),
// which pad is connected with its name and battery, what it does now, and its mapping (the
// dead-man, stop, home and E-STOP buttons, the dead zone), saved as it is changed. It owns the
// pad's reader and its jog; the E-STOP goes through the window's own, homing through the
// window's question.
class GamepadPanel : public QGroupBox
{
    Q_OBJECT
public:
    explicit GamepadPanel(DeviceSession *session, QWidget *parent = nullptr);
    ~GamepadPanel() override;

    // The window's E-STOP (EmergencyStop::trigger).
    void setEmergencyStop(std::function<void()> estop);
    // Asks before homing on the pad's Y: true goes on (tests answer without a box).
    void setConfirmer(std::function<bool(const QString &question)> confirm)
    {
        m_confirm = std::move(confirm);
    }

    SdlGamepad *reader() const { return m_reader; }
    GamepadJog *jog() const { return m_pad; }
    QCheckBox *enableBox() const { return m_enable; }
    QLabel *padLabel() const { return m_padLabel; }
    QLabel *stateLabel() const { return m_state; }
    QComboBox *deadmanBox() const { return m_deadman; }

    static QString settingsGroup() { return QStringLiteral("gamepad"); }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void setPadEnabled(bool enabled);
    void mappingEdited();
    void showMapping();
    void showPad();
    void home();

    DeviceSession *m_session;
    SdlGamepad *m_reader;
    GamepadJog *m_pad;
    QCheckBox *m_enable;
    QLabel *m_padLabel;
    QLabel *m_state;
    QComboBox *m_deadman;
    QComboBox *m_stop;
    QComboBox *m_home;
    QComboBox *m_estopBox;
    QDoubleSpinBox *m_deadzone;
    QList<QLabel *> m_captions;
    QString m_sdlError;
    std::function<bool(const QString &)> m_confirm;
    bool m_filling = false;
};

} // namespace stepcom
