#pragma once

#include <cmath>
#include <limits>

namespace stepcom {

// The rotor of an open-loop stepper in pulses of the count's frame: it follows the pulses while
// in sync and stands still once it stalls (pulse rate past pull-out, a too fast change of rate, a
// start above pull-in). The caller moves it while in sync and relocks it; the rules live here.
class SimRotor
{
public:
    // Pulse rates in Hz (infinity: no limit).
    struct Limits
    {
        double pullOutHz = std::numeric_limits<double>::infinity();
        double pullInHz = std::numeric_limits<double>::infinity();
        double accelHzPerMs = std::numeric_limits<double>::infinity();
    };

    // One millisecond of pulses at `rateHz` (signed, 0: no motion); `startHz` is the rate a
    // motion from rest starts at. Loses sync when a limit is broken.
    void observe(double rateHz, double startHz, const Limits &limits);
    // Whether a stalled rotor may lock in again at `rateHz` (at or below pull-in, or at rest).
    static bool canRelock(double rateHz, const Limits &limits);
    // The position congruent to `count` modulo `chunk` nearest to where the rotor is.
    double relockTarget(double count, double chunk) const;

    double position() const { return m_position; }
    void setPosition(double pulses) { m_position = pulses; }
    bool stalled() const { return m_stalled; }
    void setStalled(bool stalled) { m_stalled = stalled; }
    // A new start: in sync at `pulses`, at rest.
    void reset(double pulses);

private:
    double m_position = 0;
    double m_lastRateHz = 0;
    bool m_stalled = false;
};

} // namespace stepcom
