#pragma once

#include "gamepad/gamepadstate.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonObject>
#include <QObject>
#include <QTimer>

#include <functional>

namespace stepcom {

class JogController;

// Which control of the pad does what. The left stick and the D-pad jog motor 1 (across) and
// motor 2 (up); nothing moves unless the dead-man is held.
struct GamepadMapping
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::GamepadMapping)
public:
    int deadman = GamepadState::kRightTrigger; // held for any motion
    int stop = GamepadState::B;
    int home = GamepadState::Y;
    int emergencyStop = GamepadState::Back;
    double deadzone = 0.25; // stick deflection below this is centred
    bool invertY = true;    // stick up jogs motor 2 forward

    QJsonObject toJson() const;
    // Unknown keys and values out of range are refused whole: nullopt and why.
    static std::optional<GamepadMapping> fromJson(const QJsonObject &o, QString *why);
    // "right trigger", "B", "Back", in the installed language.
    static QString buttonName(int button);
    bool operator==(const GamepadMapping &o) const = default;
};

// Jogging from a game pad, safe as the pendant is: off until enabled; motion only while the
// dead-man is held, and a stick or D-pad past the dead zone asks for it (both motors at once
// when the stick is at an angle); letting go of the dead-man or of the stick stops the jogs the
// pad started. A pad that detaches, or whose readings stop coming for longer than kSilenceMs,
// stops every jog it started: the pad is the hand on the machine, so a window losing focus
// does not. Another hand (the mouse, the keyboard, the pendant) jogging the same motor ends
// the pad's jog there (JogController). B stops both motors, Back sends the E-STOP (through
// the window's own E-STOP), Y asks for homing (the window confirms). The jog itself, the
// soft limits and the stop checks are JogController's.
class GamepadJog : public QObject
{
    Q_OBJECT
public:
    static constexpr int kSilenceMs = 250; // SdlGamepad reads every 10 ms while attached

    explicit GamepadJog(JogController *jog, QObject *parent = nullptr);

    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    void setMapping(const GamepadMapping &mapping) { m_mapping = mapping; }
    const GamepadMapping &mapping() const { return m_mapping; }
    void setEmergencyStop(std::function<void()> estop) { m_estop = std::move(estop); }

    // A reading of the pad (SdlGamepad::state).
    void update(const GamepadState &state);
    // The pad went away: every jog it started stops.
    void detached();
    // The motors the pad jogs now.
    QList<int> jogging() const;

Q_SIGNALS:
    // Y pressed with the dead-man held: the window asks, then homes.
    void homeRequested();
    // jogging() changed.
    void joggingChanged();
    void message(const QString &text);

private:
    void stopAll(const QString &reason);
    // Jogs motor `motor` toward `direction` (+1, −1) or lets it go (0).
    void want(int motor, int direction, const QString &reason);

    JogController *m_jog;
    GamepadMapping m_mapping;
    std::function<void()> m_estop;
    bool m_enabled = false;
    GamepadState m_last;
    QHash<int, int> m_held;    // motor → direction the pad holds
    QHash<int, int> m_refused; // motor → direction a press was refused for
    bool m_needCentre = false; // after B or the E-STOP
    QTimer m_silence;
};

} // namespace stepcom
