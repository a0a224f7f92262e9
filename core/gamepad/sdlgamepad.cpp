#include "gamepad/sdlgamepad.h"

#include <SDL2/SDL.h>

#include <QString>

namespace stepcom {

namespace {

SDL_GameController *pad(void *p)
{
    return static_cast<SDL_GameController *>(p);
}

double axis(SDL_GameController *c, SDL_GameControllerAxis a)
{
    return std::clamp(SDL_GameControllerGetAxis(c, a) / 32767.0, -1.0, 1.0);
}

} // namespace

SdlGamepad::SdlGamepad(QObject *parent)
    : QObject(parent)
{
    m_timer.setInterval(kPollMs);
    connect(&m_timer, &QTimer::timeout, this, &SdlGamepad::poll);
}

SdlGamepad::~SdlGamepad()
{
    stop();
}

bool SdlGamepad::start(QString *why)
{
    if (m_sdl)
        return true;
    // The pad is read with or without a window of SDL's own, whatever has the focus.
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
        *why = QString::fromUtf8(SDL_GetError());
        return false;
    }
    m_sdl = true;
    m_timer.start();
    poll();
    return true;
}

void SdlGamepad::stop()
{
    m_timer.stop();
    close();
    if (m_sdl)
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
    m_sdl = false;
}

std::optional<GamepadInfo> SdlGamepad::info() const
{
    if (!m_pad)
        return std::nullopt;
    GamepadInfo i;
    i.name = QString::fromUtf8(SDL_GameControllerName(pad(m_pad)));
    SDL_Joystick *j = SDL_GameControllerGetJoystick(pad(m_pad));
    switch (SDL_JoystickCurrentPowerLevel(j)) {
    case SDL_JOYSTICK_POWER_EMPTY:
        i.batteryPercent = 5;
        break;
    case SDL_JOYSTICK_POWER_LOW:
        i.batteryPercent = 33;
        break;
    case SDL_JOYSTICK_POWER_MEDIUM:
        i.batteryPercent = 70;
        break;
    case SDL_JOYSTICK_POWER_FULL:
        i.batteryPercent = 100;
        break;
    case SDL_JOYSTICK_POWER_WIRED:
        i.wired = true;
        break;
    default:
        break;
    }
    return i;
}

void SdlGamepad::poll()
{
    SDL_GameControllerUpdate();
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
        if (e.type == SDL_CONTROLLERDEVICEREMOVED && e.cdevice.which == m_instance) {
            close();
            Q_EMIT detached();
        }
    }
    if (m_pad && !SDL_GameControllerGetAttached(pad(m_pad))) {
        close();
        Q_EMIT detached();
    }
    if (!m_pad) {
        for (int i = 0; i < SDL_NumJoysticks(); ++i) {
            if (SDL_IsGameController(i)) {
                open(i);
                break;
            }
        }
    }
    if (m_pad)
        Q_EMIT state(read());
}

void SdlGamepad::open(int index)
{
    SDL_GameController *c = SDL_GameControllerOpen(index);
    if (!c)
        return;
    m_pad = c;
    m_instance = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(c));
    Q_EMIT attached(*info());
}

void SdlGamepad::close()
{
    if (m_pad)
        SDL_GameControllerClose(pad(m_pad));
    m_pad = nullptr;
    m_instance = -1;
}

GamepadState SdlGamepad::read() const
{
    SDL_GameController *c = pad(m_pad);
    GamepadState s;
    s.leftX = axis(c, SDL_CONTROLLER_AXIS_LEFTX);
    s.leftY = axis(c, SDL_CONTROLLER_AXIS_LEFTY);
    s.leftTrigger = std::max(0.0, axis(c, SDL_CONTROLLER_AXIS_TRIGGERLEFT));
    s.rightTrigger = std::max(0.0, axis(c, SDL_CONTROLLER_AXIS_TRIGGERRIGHT));
    for (int b = SDL_CONTROLLER_BUTTON_A; b <= SDL_CONTROLLER_BUTTON_DPAD_RIGHT; ++b) {
        if (SDL_GameControllerGetButton(c, SDL_GameControllerButton(b)))
            s.buttons.insert(b);
    }
    return s;
}

} // namespace stepcom
