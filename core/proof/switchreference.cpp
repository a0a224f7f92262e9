#include "proof/switchreference.h"

#include "map/registermap.h"
#include "proof/proofdrive.h"
#include "session/devicesession.h"

#include <cmath>

namespace stepcom {

SwitchReference::SwitchReference(ProofDrive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
{}

void SwitchReference::find(std::optional<double> hint, std::function<void(const Result &)> done)
{
    m_result = Result{};
    m_done = std::move(done);
    m_phase = Phase::Search;
    m_travelled = 0;
    m_count = 0;
    m_fromHint = false;
    if (!hint) {
        step();
        return;
    }
    // Half a creep's reach before where it was: a healthy axis finds it again within a few
    // creeps; a loss moved it, and the coarse approach or the back-off finds it then.
    m_drive->readHome(
        [this, at = *hint + kHintClearance](const QString &error, bool on, double pos) {
            if (!error.isEmpty())
                return fail(error);
            if (on) {
                m_phase = Phase::BackOff;
                return move(kBackOff);
            }
            m_phase = Phase::Creep;
            m_fromHint = true;
            if (std::abs(at - pos) < m_drive->setup().positionResolution)
                return step();
            move(at - pos);
            m_count = 0; // the creep's own moves are counted from here
        });
}

void SwitchReference::step()
{
    m_drive->readHome([this](const QString &error, bool on, double position) {
        if (!error.isEmpty())
            return fail(error);
        onInput(on, position);
    });
}

void SwitchReference::onInput(bool on, double position)
{
    const ProofSetup &s = m_drive->setup();
    const auto next = [this](Phase phase) {
        m_phase = phase;
        m_travelled = 0;
        m_count = 0;
    };
    switch (m_phase) {
    case Phase::Search: {
        if (on) {
            next(Phase::BackOff);
            return move(kBackOff);
        }
        const Parameter *pos = m_drive->parameter("position");
        double reach = m_search - m_travelled;
        if (const auto min = m_drive->session()->travelLimits().axis(s.motor).min)
            reach = std::min(reach, position - pos->toEngineering(*min));
        if (reach < s.positionResolution / 2)
            return fail(tr("the home switch (IN%1) did not come ON within %2 %3 toward it")
                            .arg(s.homeInput)
                            .arg(m_travelled, 0, 'f', 2)
                            .arg(pos->unit));
        if (s.limitNegative == s.homeInput) {
            // The switch is the negative limit too: the controller stops the move on it.
            m_travelled = m_search - reach;
            return move(-reach);
        }
        return move(-std::min(kSearchStep, reach));
    }
    case Phase::BackOff:
        if (!on) {
            next(Phase::Creep);
            m_fromHint = false;
            return move(-s.positionResolution);
        }
        if (m_count >= kMaxBackOffs)
            return fail(tr("the home switch (IN%1) stayed ON %2 %3 away from it")
                            .arg(s.homeInput)
                            .arg(kMaxBackOffs * kBackOff, 0, 'f', 2)
                            .arg(m_drive->parameter("position")->unit));
        return move(kBackOff);
    case Phase::Creep:
        if (on) {
            m_result.found = true;
            m_result.position = position;
            return std::exchange(m_done, {})(m_result);
        }
        if (m_fromHint && m_count >= kHintCreeps) {
            // Not where it was: the carriage moved against the count, so search as at first.
            m_fromHint = false;
            next(Phase::Search);
            return step();
        }
        if (m_count >= kMaxCreeps)
            return fail(tr("the home switch (IN%1) did not come ON again within %2 creep moves")
                            .arg(s.homeInput)
                            .arg(kMaxCreeps));
        return move(-s.positionResolution);
    }
}

void SwitchReference::move(double units)
{
    ++m_count;
    ++m_result.moves;
    if (units < 0)
        m_travelled += -units;
    m_drive->moveBy(units, [this](const StepMoveResult &r) { onMoved(r); });
}

void SwitchReference::onMoved(const StepMoveResult &r)
{
    if (m_drive->halt() != ProofDrive::Halt::None)
        return fail(m_drive->haltText());
    if (!r.arrived) {
        // A move toward the switch that the switch itself stopped (it is the limit input) is
        // what the search wants; anything else ends the reference.
        const AxisEnd *end = r.outcome ? r.outcome->axis(r.request.motor) : nullptr;
        const bool stoppedBySwitch = end && end->limitNegativeOn && r.request.value < 0 &&
                                     r.outcome->cause == MotionCause::None;
        if (!stoppedBySwitch)
            return fail(r.text);
    }
    step();
}

void SwitchReference::fail(const QString &error)
{
    m_result.found = false;
    m_result.error = error;
    if (auto done = std::exchange(m_done, {}))
        done(m_result);
}

} // namespace stepcom
