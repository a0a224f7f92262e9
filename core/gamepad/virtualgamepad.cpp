#include "gamepad/virtualgamepad.h"

#include <SDL2/SDL.h>

#include <cmath>

namespace stepcom {

VirtualGamepad::~VirtualGamepad()
{
    detach();
}

bool VirtualGamepad::attach(const QString &name, QString *why)
{
    detach();
    const QByteArray utf8 = name.toUtf8();
    SDL_VirtualJoystickDesc desc;
    SDL_zero(desc);
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
    desc.naxes = SDL_CONTROLLER_AXIS_MAX;
    desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
    desc.name = utf8.constData();
    m_device = SDL_JoystickAttachVirtualEx(&desc);
    if (m_device >= 0)
        m_stick = SDL_JoystickOpen(m_device);
    if (!m_stick) {
        *why = QString::fromUtf8(SDL_GetError());
        detach();
        return false;
    }
    // Triggers rest at 0 (SDL scales a trigger's −32768..32767 to 0..1).
    setAxis(Axis::LeftTrigger, 0);
    setAxis(Axis::RightTrigger, 0);
    return true;
}

void VirtualGamepad::detach()
{
    if (m_stick)
        SDL_JoystickClose(static_cast<SDL_Joystick *>(m_stick));
    m_stick = nullptr;
    if (m_device >= 0 && SDL_JoystickIsVirtual(m_device))
        SDL_JoystickDetachVirtual(m_device);
    m_device = -1;
}

bool VirtualGamepad::setAxis(Axis axis, double value)
{
    if (!m_stick)
        return false;
    SDL_GameControllerAxis a = SDL_CONTROLLER_AXIS_LEFTX;
    switch (axis) {
    case Axis::LeftX:
        a = SDL_CONTROLLER_AXIS_LEFTX;
        break;
    case Axis::LeftY:
        a = SDL_CONTROLLER_AXIS_LEFTY;
        break;
    case Axis::LeftTrigger:
        a = SDL_CONTROLLER_AXIS_TRIGGERLEFT;
        break;
    case Axis::RightTrigger:
        a = SDL_CONTROLLER_AXIS_TRIGGERRIGHT;
        break;
    }
    return SDL_JoystickSetVirtualAxis(static_cast<SDL_Joystick *>(m_stick), a,
                                      Sint16(std::lround(std::clamp(value, -1.0, 1.0) * 32767))) ==
           0;
}

bool VirtualGamepad::setButton(int button, bool down)
{
    return m_stick && SDL_JoystickSetVirtualButton(static_cast<SDL_Joystick *>(m_stick), button,
                                                   down ? 1 : 0) == 0;
}

} // namespace stepcom
