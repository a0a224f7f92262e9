#pragma once

#include <QList>

namespace stepcom {

// The special system modes 1-5 of register 40300: motor 1 driven by the inputs, exactly as the
// manual describes them. "Triggered" means a rising edge; mode 4 is level (held) control.
class SpecialModes
{
public:
    // What a mode may do with motor 1; the machine implements it.
    class Axis
    {
    public:
        virtual ~Axis() = default;
        virtual void run(int direction) = 0;
        virtual void moveBy(int direction) = 0; // the single-move distance
        virtual void stop() = 0;
        virtual bool isRunning() const = 0;
        virtual int runDirection() const = 0; // +1/-1 while moving, 0 when idle
        virtual bool startedByMode() const = 0;
        virtual bool limitActive(int direction) const = 0;
    };

    // Forget all mode state (the mode changed, emergency stop).
    void reset();
    // Called whenever the inputs may have changed; inputs[0] is IN1.
    void evaluate(int mode, const QList<bool> &inputs, int roundTrips, Axis &axis);
    int completedRoundTrips() const { return m_trips; }

private:
    enum class Trip { Idle, Forward, Reverse };

    bool rose(int input) const;
    bool level(int input) const;
    void roundTrip(int roundTrips, Axis &axis);
    void singleTrigger(Axis &axis);
    void forwardReverseTrigger(Axis &axis);
    void holdToJog(Axis &axis);
    void fixedDistance(Axis &axis);

    QList<bool> m_previous;
    QList<bool> m_current;
    Trip m_trip = Trip::Idle;
    int m_trips = 0;
    int m_lastDirection = 1;
    int m_nextDirection = 1;
};

} // namespace stepcom
