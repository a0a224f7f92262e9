#include "sim/model/simswitch.h"

namespace stepcom {

SimSwitch::SimSwitch(int side)
    : m_side(side < 0 ? -1 : 1)
{}

void SimSwitch::configure(double nominalMm, double jitterMm, double hysteresisMm, quint32 seed)
{
    m_nominal = nominalMm;
    m_jitter = jitterMm;
    m_hysteresis = hysteresisMm;
    m_rng.seed(seed);
    m_trip = m_nominal + draw();
    m_drawPending = false;
    m_on = false;
    if (m_hasLast)
        update(m_last);
}

double SimSwitch::draw()
{
    if (m_jitter <= 0)
        return 0;
    return std::uniform_real_distribution<double>(-m_jitter / 2, m_jitter / 2)(m_rng);
}

bool SimSwitch::reached(double c) const
{
    return m_side < 0 ? c <= m_trip : c >= m_trip;
}

bool SimSwitch::released(double c) const
{
    return m_side < 0 ? c > m_trip + m_hysteresis : c < m_trip - m_hysteresis;
}

void SimSwitch::update(double carriageMm)
{
    // Moving towards the switch is a new approach once it has been released.
    const bool approaching = m_hasLast && (carriageMm - m_last) * m_side > 0;
    m_last = carriageMm;
    m_hasLast = true;
    if (m_on) {
        if (released(carriageMm)) {
            m_on = false;
            m_drawPending = true;
        }
        return;
    }
    if (m_drawPending && approaching) {
        m_trip = m_nominal + draw();
        m_drawPending = false;
    }
    if (!m_drawPending && reached(carriageMm))
        m_on = true;
}

} // namespace stepcom
