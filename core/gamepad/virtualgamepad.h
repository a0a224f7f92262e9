#pragma once

#include <QString>

namespace stepcom {

// A game pad of SDL's own making (SDL_JoystickAttachVirtualEx), seen by SdlGamepad as a real
// one: the tests drive the pad jog with it, and the guide's picture shows one. Needs SdlGamepad
// started (SDL's joystick subsystem up) before attach().
class VirtualGamepad
{
public:
    enum class Axis { LeftX, LeftY, LeftTrigger, RightTrigger };

    VirtualGamepad() = default;
    ~VirtualGamepad();
    VirtualGamepad(const VirtualGamepad &) = delete;
    VirtualGamepad &operator=(const VirtualGamepad &) = delete;

    // False and SDL's reason when it cannot be made.
    bool attach(const QString &name, QString *why);
    // Unplugs it (SdlGamepad sees it go).
    void detach();
    bool isAttached() const { return m_device >= 0; }
    // −1..1 for the stick, 0..1 for a trigger.
    bool setAxis(Axis axis, double value);
    // A GamepadState::Button.
    bool setButton(int button, bool down);

private:
    int m_device = -1;
    void *m_stick = nullptr; // SDL_Joystick*
};

} // namespace stepcom
