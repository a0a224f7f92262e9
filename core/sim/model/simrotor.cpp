#include "sim/model/simrotor.h"

namespace stepcom {

namespace {

// Past a limit by more than rounding.
bool exceeds(double value, double limit)
{
    return value > limit * (1 + 1e-9) + 1e-9;
}

} // namespace

void SimRotor::observe(double rateHz, double startHz, const Limits &limits)
{
    const double speed = std::abs(rateHz);
    if (!m_stalled && speed > 0) {
        const bool fromRest = m_lastRateHz == 0;
        if (exceeds(speed, limits.pullOutHz))
            m_stalled = true;
        else if (fromRest && exceeds(std::abs(startHz), limits.pullInHz))
            m_stalled = true;
        else if (!fromRest && exceeds(std::abs(rateHz - m_lastRateHz), limits.accelHzPerMs))
            m_stalled = true;
    }
    m_lastRateHz = rateHz;
}

bool SimRotor::canRelock(double rateHz, const Limits &limits)
{
    return !exceeds(std::abs(rateHz), limits.pullInHz);
}

double SimRotor::relockTarget(double count, double chunk) const
{
    if (chunk <= 0)
        return count;
    return count - std::round((count - m_position) / chunk) * chunk;
}

void SimRotor::reset(double pulses)
{
    m_position = pulses;
    m_lastRateHz = 0;
    m_stalled = false;
}

} // namespace stepcom
