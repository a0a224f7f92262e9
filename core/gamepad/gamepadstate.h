#pragma once

#include <QSet>
#include <QString>

#include <optional>

namespace stepcom {

// One reading of a game pad, as SdlGamepad takes it from SDL's GameController API: the sticks
// and triggers scaled to −1..1 and 0..1, the buttons held (SDL_GameControllerButton values).
// Plain data, so GamepadJog can be driven without a pad.
struct GamepadState
{
    enum Button {
        A = 0,
        B = 1,
        X = 2,
        Y = 3,
        Back = 4,
        Guide = 5,
        Start = 6,
        LeftStick = 7,
        RightStick = 8,
        LeftShoulder = 9,
        RightShoulder = 10,
        DpadUp = 11,
        DpadDown = 12,
        DpadLeft = 13,
        DpadRight = 14,
    };
    // Triggers held past half way count as buttons of their own.
    static constexpr int kLeftTrigger = 100;
    static constexpr int kRightTrigger = 101;

    double leftX = 0; // −1 left .. 1 right
    double leftY = 0; // −1 up .. 1 down, as SDL gives it
    double leftTrigger = 0;
    double rightTrigger = 0;
    QSet<int> buttons;

    bool held(int button) const
    {
        if (button == kLeftTrigger)
            return leftTrigger > 0.5;
        if (button == kRightTrigger)
            return rightTrigger > 0.5;
        return buttons.contains(button);
    }
    bool operator==(const GamepadState &o) const = default;
};

// The pad SDL knows, for the Jog page: its name and, where SDL gives it, its battery.
struct GamepadInfo
{
    QString name;
    std::optional<int> batteryPercent; // SDL 2.26 gives a level, not a percentage: 5/33/70/100
    bool wired = false;
};

} // namespace stepcom
