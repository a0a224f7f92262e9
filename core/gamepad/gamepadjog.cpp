#include "gamepad/gamepadjog.h"

#include "session/jogcontroller.h"

#include <QJsonValue>

#include <cmath>

namespace stepcom {

namespace {

using Direction = JogController::Direction;
using Source = JogController::Source;

const QStringList kKeys{QStringLiteral("deadman"),  QStringLiteral("stop"),
                        QStringLiteral("home"),     QStringLiteral("emergency_stop"),
                        QStringLiteral("deadzone"), QStringLiteral("invert_y")};

bool validButton(int b)
{
    return (b >= GamepadState::A && b <= GamepadState::DpadRight) ||
           b == GamepadState::kLeftTrigger || b == GamepadState::kRightTrigger;
}

} // namespace

QJsonObject GamepadMapping::toJson() const
{
    return {
        {QStringLiteral("deadman"), deadman},   {QStringLiteral("stop"), stop},
        {QStringLiteral("home"), home},         {QStringLiteral("emergency_stop"), emergencyStop},
        {QStringLiteral("deadzone"), deadzone}, {QStringLiteral("invert_y"), invertY}};
}

std::optional<GamepadMapping> GamepadMapping::fromJson(const QJsonObject &o, QString *why)
{
    GamepadMapping m;
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!kKeys.contains(it.key())) {
            *why = tr("unknown key \"%1\" in the pad's mapping").arg(it.key());
            return std::nullopt;
        }
    }
    const auto button = [&](const char *key, int *out) {
        const QJsonValue v = o.value(QLatin1String(key));
        if (v.isUndefined())
            return true;
        if (!v.isDouble() || !validButton(v.toInt(-1)) || v.toDouble() != v.toInt()) {
            *why = tr("\"%1\" names no button of a pad").arg(QLatin1String(key));
            return false;
        }
        *out = v.toInt();
        return true;
    };
    if (!button("deadman", &m.deadman) || !button("stop", &m.stop) || !button("home", &m.home) ||
        !button("emergency_stop", &m.emergencyStop))
        return std::nullopt;
    if (const QJsonValue v = o.value(QStringLiteral("deadzone")); !v.isUndefined()) {
        if (!v.isDouble() || v.toDouble() < 0.05 || v.toDouble() > 0.9) {
            *why = tr("the dead zone must be a number from 0.05 to 0.9");
            return std::nullopt;
        }
        m.deadzone = v.toDouble();
    }
    if (const QJsonValue v = o.value(QStringLiteral("invert_y")); !v.isUndefined()) {
        if (!v.isBool()) {
            *why = tr("\"invert_y\" must be true or false");
            return std::nullopt;
        }
        m.invertY = v.toBool();
    }
    const QList<int> used{m.deadman, m.stop, m.home, m.emergencyStop};
    if (QSet<int>(used.begin(), used.end()).size() != used.size()) {
        *why = tr("one button cannot do two things in the pad's mapping");
        return std::nullopt;
    }
    return m;
}

QString GamepadMapping::buttonName(int button)
{
    switch (button) {
    case GamepadState::kLeftTrigger:
        return tr("left trigger");
    case GamepadState::kRightTrigger:
        return tr("right trigger");
    case GamepadState::A:
        return QStringLiteral("A");
    case GamepadState::B:
        return QStringLiteral("B");
    case GamepadState::X:
        return QStringLiteral("X");
    case GamepadState::Y:
        return QStringLiteral("Y");
    case GamepadState::Back:
        return tr("Back");
    case GamepadState::Start:
        return tr("Start");
    case GamepadState::LeftShoulder:
        return tr("left shoulder");
    case GamepadState::RightShoulder:
        return tr("right shoulder");
    default:
        break;
    }
    return tr("button %1").arg(button);
}

GamepadJog::GamepadJog(JogController *jog, QObject *parent)
    : QObject(parent)
    , m_jog(jog)
{
    m_silence.setSingleShot(true);
    m_silence.setInterval(kSilenceMs);
    connect(&m_silence, &QTimer::timeout, this, [this] { stopAll(tr("the pad went silent")); });
}

void GamepadJog::setEnabled(bool enabled)
{
    if (m_enabled == enabled)
        return;
    m_enabled = enabled;
    if (!enabled)
        stopAll(tr("the pad was switched off"));
}

QList<int> GamepadJog::jogging() const
{
    QList<int> motors = m_held.keys();
    std::sort(motors.begin(), motors.end());
    return motors;
}

void GamepadJog::update(const GamepadState &state)
{
    const GamepadState last = m_last;
    m_last = state;
    if (!m_enabled)
        return;
    // The E-STOP and the stop work with or without the dead-man: stopping is never refused.
    if (state.held(m_mapping.emergencyStop) && !last.held(m_mapping.emergencyStop)) {
        stopAll(tr("E-STOP on the pad"));
        m_needCentre = true;
        if (m_estop)
            m_estop();
        return;
    }
    if (state.held(m_mapping.stop) && !last.held(m_mapping.stop)) {
        stopAll(tr("stop on the pad"));
        m_needCentre = true;
        for (int m = 1; m <= m_jog->motorCount(); ++m)
            m_jog->stop(m, tr("stop on the pad"));
        return;
    }
    if (!state.held(m_mapping.deadman)) {
        if (!m_held.isEmpty())
            stopAll(tr("the dead-man was let go"));
        m_silence.stop();
        return;
    }
    m_silence.start(); // readings must keep coming while the pad may move anything
    if (state.held(m_mapping.home) && !last.held(m_mapping.home))
        Q_EMIT homeRequested();
    const auto axis = [this](double v) {
        return std::abs(v) < m_mapping.deadzone ? 0 : v > 0 ? 1 : -1;
    };
    int x = axis(state.leftX);
    int y = axis(state.leftY) * (m_mapping.invertY ? -1 : 1);
    if (state.buttons.contains(GamepadState::DpadRight))
        x = 1;
    else if (state.buttons.contains(GamepadState::DpadLeft))
        x = -1;
    if (state.buttons.contains(GamepadState::DpadUp))
        y = 1;
    else if (state.buttons.contains(GamepadState::DpadDown))
        y = -1;
    // After a stop from the pad nothing moves again until the stick has been centred.
    if (m_needCentre) {
        if (x != 0 || y != 0)
            return;
        m_needCentre = false;
    }
    want(1, x, tr("the stick was let go"));
    if (m_jog->motorCount() >= 2)
        want(2, y, tr("the stick was let go"));
}

void GamepadJog::want(int motor, int direction, const QString &reason)
{
    const int held = m_held.value(motor, 0);
    // The pad's jog ended elsewhere (a limit, another hand, an E-STOP): press again to go on.
    if (held != 0 && !(m_jog->isJogging(motor) && m_jog->source(motor) == Source::Gamepad)) {
        // Not pressed again while the stick still asks for the same: centre it first.
        m_held.remove(motor);
        m_refused.insert(motor, held);
        Q_EMIT joggingChanged();
        return;
    }
    if (held == direction)
        return;
    if (m_refused.value(motor) != direction)
        m_refused.remove(motor);
    if (held != 0) {
        m_jog->release(motor, Source::Gamepad, reason);
        m_held.remove(motor);
        Q_EMIT joggingChanged();
    }
    // A press refused (at a limit, not connected, another hand's jog) is said once, and not
    // tried again until the stick asks for something else.
    if (direction != 0 && !m_held.contains(motor) && !m_refused.contains(motor)) {
        if (m_jog->press(motor, direction > 0 ? Direction::Forward : Direction::Reverse,
                         Source::Gamepad)) {
            m_held.insert(motor, direction);
            Q_EMIT joggingChanged();
        } else
            m_refused.insert(motor, direction);
    }
}

void GamepadJog::detached()
{
    m_last = {};
    stopAll(tr("the pad was unplugged"));
}

void GamepadJog::stopAll(const QString &reason)
{
    m_silence.stop();
    m_refused.clear();
    const QList<int> motors = m_held.keys();
    m_held.clear();
    for (int motor : motors)
        m_jog->release(motor, Source::Gamepad, reason);
    if (!motors.isEmpty()) {
        Q_EMIT joggingChanged();
        Q_EMIT message(tr("Pad: %1, the jog stopped").arg(reason));
    }
}

} // namespace stepcom
