#include "motion/rampmover.h"

#include <algorithm>
#include <cmath>

namespace stepcom {

void RampMover::setRates(const RampRates &rates)
{
    m_startRate = std::max(rates.start, 1e-6);
    m_maxRate = std::max(rates.top, 1e-6);
    m_accel = std::max(rates.accel, 1e-9);
}

double RampMover::effectiveStart() const
{
    // A start rate above the top speed means no ramp at all: the motor starts at the top speed.
    return std::min(m_startRate, m_maxRate);
}

void RampMover::run(int direction)
{
    const int dir = direction < 0 ? -1 : 1;
    if (m_mode == Mode::Idle || dir != m_dir)
        m_rate = effectiveStart();
    m_dir = dir;
    m_mode = Mode::Run;
}

void RampMover::moveTo(double target)
{
    m_target = target;
    if (std::abs(target - m_pos) < 1e-9) {
        m_pos = target;
        stop();
        return;
    }
    const int dir = target > m_pos ? 1 : -1;
    if (m_mode == Mode::Idle || dir != m_dir)
        m_rate = effectiveStart();
    m_dir = dir;
    m_mode = Mode::Target;
}

void RampMover::stop()
{
    m_mode = Mode::Idle;
    m_rate = 0;
}

double RampMover::tick(double dt)
{
    if (m_mode == Mode::Idle)
        return 0;
    const double start = effectiveStart();
    double wanted = m_maxRate;
    if (m_mode == Mode::Target) {
        const double remaining = std::abs(m_target - m_pos);
        // Distance needed to brake from the current rate down to the start rate.
        const double brake = (m_rate * m_rate - start * start) / (2 * m_accel);
        if (remaining <= brake + m_rate * dt)
            wanted = start;
    }
    if (m_rate < wanted)
        m_rate = std::min(m_rate + m_accel * dt, wanted);
    else if (m_rate > wanted)
        m_rate = std::max(m_rate - m_accel * dt, wanted);

    double step = m_rate * dt;
    if (m_mode == Mode::Target) {
        const double remaining = std::abs(m_target - m_pos);
        if (step >= remaining) {
            const double moved = m_target - m_pos;
            m_pos = m_target;
            stop();
            return moved;
        }
    }
    const double moved = m_dir * step;
    m_pos += moved;
    return moved;
}

} // namespace stepcom
