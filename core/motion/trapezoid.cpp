#include "motion/trapezoid.h"

#include <algorithm>
#include <cmath>

namespace stepcom {

Trapezoid::Trapezoid(double distance, const RampRates &rates)
    : m_distance(distance)
    , m_start(rates.effectiveStart())
    , m_accel(rates.accel)
    , m_peak(rates.top)
{
    const double top = rates.top;
    const double rampDistance = (top * top - m_start * m_start) / (2 * m_accel);
    m_reachesTop = 2 * rampDistance <= distance;
    if (m_reachesTop) {
        m_rampMs = (top - m_start) / m_accel;
        m_cruiseMs = (distance - 2 * rampDistance) / top;
    } else {
        m_peak = std::sqrt(m_start * m_start + m_accel * distance);
        m_rampMs = (m_peak - m_start) / m_accel;
    }
}

double Trapezoid::travelledAt(double t) const
{
    const double up = m_start * m_rampMs + m_accel * m_rampMs * m_rampMs / 2;
    if (t <= m_rampMs)
        return std::min(m_distance, m_start * t + m_accel * t * t / 2);
    if (t <= m_rampMs + m_cruiseMs)
        return std::min(m_distance, up + m_peak * (t - m_rampMs));
    const double d = t - m_rampMs - m_cruiseMs;
    return std::min(m_distance, up + m_peak * m_cruiseMs + m_peak * d - m_accel * d * d / 2);
}

} // namespace stepcom
