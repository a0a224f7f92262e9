#pragma once

#include "gamepad/gamepadstate.h"

#include <QObject>
#include <QTimer>

#include <optional>

namespace stepcom {

// The game pads SDL's GameController API knows (its controller database), hot-plugged: the
// first one attached is opened and read every kPollMs while it stays attached; its readings go
// out as `state`, its coming and going as `attached`/`detached`. SDL runs without a window
// (background events allowed): the pad works whichever window has the focus.
class SdlGamepad : public QObject
{
    Q_OBJECT
public:
    static constexpr int kPollMs = 10;

    explicit SdlGamepad(QObject *parent = nullptr);
    ~SdlGamepad() override;

    // False and why (SDL_GetError) when SDL's game controller subsystem cannot start.
    bool start(QString *why);
    void stop();
    bool isRunning() const { return m_timer.isActive(); }
    // The pad open now, if any.
    std::optional<GamepadInfo> info() const;

Q_SIGNALS:
    void attached(const stepcom::GamepadInfo &info);
    void detached();
    void state(const stepcom::GamepadState &state);

private:
    void poll();
    void open(int index);
    void close();
    GamepadState read() const;

    QTimer m_timer;
    void *m_pad = nullptr; // SDL_GameController*, kept out of the header
    int m_instance = -1;   // its SDL_JoystickID
    bool m_sdl = false;
};

} // namespace stepcom
