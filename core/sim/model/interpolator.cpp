#include "sim/model/interpolator.h"

#include "sim/model/simaxis.h"

#include "motion/motorderived.h"

#include <cmath>

namespace stepcom {

void Interpolator::start(Kind kind, const InterpolationPath &path, double speedRpm, SimAxis &x,
                         SimAxis &y)
{
    m_kind = kind;
    m_path = path;
    m_speedRpm = speedRpm;
    m_startX = motorderived::wholePulses(path.start().x, x.settings().stepsPerUnit());
    m_startY = motorderived::wholePulses(path.start().y, y.settings().stepsPerUnit());
    x.startMove(m_startX);
    y.startMove(m_startY);
    m_phase = Phase::Approach;
    tick(x, y); // both may already be at the start
}

void Interpolator::stop(SimAxis &x, SimAxis &y)
{
    if (m_phase == Phase::Idle)
        return;
    m_phase = Phase::Idle;
    x.stop();
    y.stop();
}

void Interpolator::beginPath(SimAxis &x, SimAxis &y)
{
    const AxisSettings &s = x.settings();
    // Path rates follow motor 1: its pulse rates expressed in distance units per millisecond.
    const double unitsPerStep = 1.0 / s.stepsPerUnit();
    m_mover.setRates(
        RampRates::fromHz(s.startHz, s.hzForRpm(m_speedRpm), s.accelHzPerMs).scaled(unitsPerStep));
    m_mover.stop();
    m_mover.setPosition(0);
    x.startPath();
    y.startPath();
    m_phase = Phase::Path;
    m_last = m_path.start();
    m_mover.moveTo(m_path.length());
}

void Interpolator::tick(SimAxis &x, SimAxis &y)
{
    switch (m_phase) {
    case Phase::Idle:
        return;
    case Phase::Approach:
        if (x.isRunning() || y.isRunning())
            return;
        // Both stopped: at the start point the path begins, anywhere else they were stopped.
        if (std::abs(x.exactSteps() - m_startX) < 0.5 && std::abs(y.exactSteps() - m_startY) < 0.5)
            beginPath(x, y);
        else
            m_phase = Phase::Idle;
        if (m_phase != Phase::Path)
            return;
        break;
    case Phase::Path:
        break;
    }
    if (x.activity() != SimAxis::Activity::Path || y.activity() != SimAxis::Activity::Path) {
        stop(x, y); // one axis was stopped (limit, stop command): the other stops with it
        return;
    }
    m_mover.tick();
    const double sx = x.settings().stepsPerUnit();
    const double sy = y.settings().stepsPerUnit();
    if (!m_mover.isMoving()) {
        // The end point, in whole steps.
        x.setPathSteps(motorderived::wholePulses(m_path.end().x, sx));
        y.setPathSteps(motorderived::wholePulses(m_path.end().y, sy));
        m_phase = Phase::Idle;
        x.stop();
        y.stop();
        return;
    }
    const InterpolationPath::Point p = m_path.pointAt(m_mover.position());
    // The pulse rates from the unrounded path, so whole pulses do not make them jitter.
    const double rateX = (p.x - m_last.x) * sx * 1000.0;
    const double rateY = (p.y - m_last.y) * sy * 1000.0;
    m_last = p;
    // The controller sends whole pulses: the counters stay integers along the way.
    x.setPathSteps(motorderived::wholePulses(p.x, sx), rateX);
    y.setPathSteps(motorderived::wholePulses(p.y, sy), rateY);
}

} // namespace stepcom
