#include "motion/motionwatch.h"

#include "map/registermap.h"

namespace stepcom {

namespace {

int rank(MotionCause c)
{
    switch (c) {
    case MotionCause::None:
        return 0;
    case MotionCause::Stop:
        return 1;
    case MotionCause::EmergencyStop:
        return 2;
    case MotionCause::LinkLost:
        return 3;
    case MotionCause::Silent:
        return 4;
    case MotionCause::Restarted:
        return 5;
    }
    return 0;
}

} // namespace

MotionWatch::MotionWatch(const RegisterMap &map, MotionStart start, int skipSamples)
    : m_start(std::move(start))
    , m_skip(skipSamples)
{
    for (int n : m_start.motors) {
        const Parameter *p =
            map.blockParameter(QStringLiteral("motor"), n, QStringLiteral("running"));
        m_runningKeys << (p ? p->key : QString());
    }
}

void MotionWatch::interrupt(MotionCause cause)
{
    if (rank(cause) > rank(m_cause))
        m_cause = cause;
}

QList<int> MotionWatch::running() const
{
    QList<int> on;
    for (int i = 0; i < m_runningKeys.size(); ++i) {
        if (m_last.value(m_runningKeys.at(i), 0) != 0)
            on << m_start.motors.at(i);
    }
    return on;
}

bool MotionWatch::sample(const StatusValues &values)
{
    if (m_over)
        return true;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        m_last.insert(it.key(), it.value());
    if (m_skip > 0) {
        --m_skip;
        return false;
    }
    bool known = true;
    for (const QString &k : std::as_const(m_runningKeys))
        known = known && m_last.contains(k);
    m_idle = known && running().isEmpty() ? m_idle + 1 : 0;
    m_over = m_idle >= 2;
    return m_over;
}

} // namespace stepcom
