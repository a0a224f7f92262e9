#include "proof/axisproof.h"

#include "motion/travellimits.h"
#include "proof/proofdrive.h"
#include "proof/switchreference.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <cmath>

namespace stepcom {

AxisProof::AxisProof(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{}

AxisProof::~AxisProof() = default;

bool AxisProof::start(const Options &options)
{
    if (m_running || !m_session)
        return false;
    m_options = options;
    m_result = LostStepResult{};
    m_result.motor = options.motor;
    m_result.cycles = options.cycles;
    m_result.distance = options.distance;
    m_running = true;
    m_waiting = false;
    m_ending = false;
    m_lastFound.reset();
    ProofDrive::renew(m_drive, m_session, options.motor, this);
    m_reference = new SwitchReference(m_drive, m_drive);
    if (const QString why = m_drive->refusal(); !why.isEmpty()) {
        m_result.restored = true;
        m_running = false;
        m_result.text = why;
        Q_EMIT finished(m_result);
        return true;
    }
    m_result.simulator = m_session->connection()->isSimulator();
    Q_EMIT progress(tr("Motor %1: reading its values").arg(options.motor));
    m_drive->readSetup([this](const QString &error) { onSetup(error); });
    return true;
}

void AxisProof::onSetup(const QString &error)
{
    if (!error.isEmpty())
        return end(m_drive->halt() != ProofDrive::Halt::None ? ProofOutcome::LinkLost
                                                             : ProofOutcome::DeviceError,
                   error);
    const ProofSetup &s = m_drive->setup();
    m_result.speedRpm = m_options.speedRpm.value_or(s.speedRpm);
    m_result.accel = m_options.accel.value_or(s.accelRaw);
    m_result.resolution = s.resolution();
    m_result.chunk = s.chunk();
    // Slow enough to start without a ramp and never to stall: the start frequency's speed, or a
    // quarter of the test speed when that is lower.
    const double slow = std::min(s.rpmOfHz(s.startHz), m_result.speedRpm / 4.0);
    m_slowRpm = std::max<qint64>(1, qint64(std::floor(slow)));
    if (const QString why = check(); !why.isEmpty())
        return end(ProofOutcome::Refused, why);
    if (m_options.askFirst) {
        m_waiting = true;
        Q_EMIT ready(planText());
        return;
    }
    proceed();
}

QString AxisProof::check()
{
    const ProofSetup &s = m_drive->setup();
    const int motor = m_options.motor;
    const Parameter *position = m_drive->parameter("position");
    if (const QString why = m_drive->homeInputRefusal(); !why.isEmpty())
        return why;
    if (m_options.cycles < 1 || m_options.cycles > 1000)
        return tr("cycles must be 1 to 1000, not %1").arg(m_options.cycles);
    const Parameter *distance = m_drive->parameter("move_distance");
    if (!(m_options.distance > 0) ||
        (distance && std::llround(m_options.distance * distance->scale) > distance->rawMax))
        return tr("the distance must be above 0 and within the single move's range, not %1")
            .arg(m_options.distance);
    if (const QString why = m_drive->parameter("speed")->checkRaw(m_result.speedRpm);
        !why.isEmpty())
        return tr("Motor %1: the test speed %2 rpm: %3").arg(motor).arg(m_result.speedRpm).arg(why);
    if (const QString why = m_drive->parameter("accel_frequency")->checkRaw(m_result.accel);
        !why.isEmpty())
        return tr("Motor %1: the test acceleration %2: %3").arg(motor).arg(m_result.accel).arg(why);
    const TravelLimits &limits = m_session->travelLimits();
    const double top = s.position + kClearance + m_options.distance;
    if (const QString why = limits.refuseTarget(m_session->map(), motor, s.position, top);
        !why.isEmpty())
        return tr("The test needs the travel from the home switch to %1 %2 past it: %3")
            .arg(kClearance + m_options.distance, 0, 'f', 2)
            .arg(position->unit, why);
    if (const auto min = limits.axis(motor).min) {
        const double room = s.position - position->toEngineering(*min);
        if (!m_options.baseline && room <= 0)
            return tr("Motor %1 stands at its lower travel limit: the home switch beyond it "
                      "cannot be searched for")
                .arg(motor);
        m_options.search = std::min(m_options.search, room);
    }
    m_reference->setSearch(m_options.search);
    return {};
}

QString AxisProof::planText() const
{
    const ProofSetup &s = m_drive->setup();
    const QString unit = m_drive->parameter("position")->unit;
    const QString accelUnit = m_drive->parameter("accel_frequency")->unit;
    QString text = tr("Motor %1: the lost-step test").arg(m_options.motor) + QLatin1Char('\n');
    text += tr("  reference: the home switch on IN%1, approached in the negative direction "
               "(up to %2 %3) at %4 rpm, %5")
                .arg(s.homeInput)
                .arg(m_options.search, 0, 'f', 2)
                .arg(unit)
                .arg(m_slowRpm)
                .arg(m_options.baseline ? tr("from where the last test found it")
                                        : tr("twice, to measure its repeatability")) +
            QLatin1Char('\n');
    text += tr("  then %1 cycle(s) of %2 %3 out at %4 rpm (acceleration %5 %6) and back at %7 "
               "rpm, a reference, the same out at %7 rpm and back at %4 rpm, a reference")
                .arg(m_options.cycles)
                .arg(m_options.distance, 0, 'f', 2)
                .arg(unit)
                .arg(m_result.speedRpm)
                .arg(m_result.accel)
                .arg(accelUnit)
                .arg(m_slowRpm) +
            QLatin1Char('\n');
    text += tr("  travel: from the home switch to %1 %2 past it")
                .arg(kClearance + m_options.distance, 0, 'f', 2)
                .arg(unit) +
            QLatin1Char('\n');
    text += tr("  afterwards: speed %1 rpm and acceleration %2 %3 put back and verified")
                .arg(s.speedRpm)
                .arg(s.accelRaw)
                .arg(accelUnit) +
            QLatin1Char('\n');
    return text;
}

void AxisProof::proceed()
{
    if (!m_running || m_ending)
        return;
    m_waiting = false;
    connect(m_drive, &ProofDrive::halted, this, [this] {
        if (m_waiting)
            endOnHalt();
    });
    m_drive->setSpeed(m_slowRpm, std::nullopt, [this](const QString &error) {
        if (m_drive->halt() != ProofDrive::Halt::None)
            return endOnHalt();
        if (!error.isEmpty())
            return end(ProofOutcome::DeviceError, error);
        if (const auto &b = m_options.baseline) {
            m_lastFound = b->position;
            m_base = b->position;
            m_result.repeatability = b->repeatability;
            return startHalf(true);
        }
        Q_EMIT progress(tr("Motor %1: reference 1 of 2 on the home switch").arg(m_options.motor));
        reference([this](double first) {
            Q_EMIT progress(
                tr("Motor %1: reference 2 of 2 on the home switch").arg(m_options.motor));
            reference([this, first](double second) {
                m_result.repeatability = std::abs(second - first);
                m_base = second;
                startHalf(true);
            });
        });
    });
}

void AxisProof::reference(std::function<void(double)> found)
{
    m_reference->find(m_lastFound, [this, found](const SwitchReference::Result &r) {
        if (m_drive->halt() != ProofDrive::Halt::None)
            return endOnHalt();
        if (!r.found)
            return end(ProofOutcome::DeviceError,
                       tr("Motor %1: the reference on the home switch failed: %2")
                           .arg(m_options.motor)
                           .arg(r.error));
        m_lastFound = r.position;
        m_result.endReference = r.position;
        found(r.position);
    });
}

void AxisProof::startHalf(bool out)
{
    m_out = out;
    m_move = 0;
    Q_EMIT progress(out ? tr("Motor %1: %2 cycle(s) out at %3 rpm, back at %4 rpm")
                              .arg(m_options.motor)
                              .arg(m_options.cycles)
                              .arg(m_result.speedRpm)
                              .arg(m_slowRpm)
                        : tr("Motor %1: %2 cycle(s) out at %3 rpm, back at %4 rpm")
                              .arg(m_options.motor)
                              .arg(m_options.cycles)
                              .arg(m_slowRpm)
                              .arg(m_result.speedRpm));
    m_drive->setSpeed(m_slowRpm, m_result.accel, [this](const QString &error) {
        if (m_drive->halt() != ProofDrive::Halt::None)
            return endOnHalt();
        if (!error.isEmpty())
            return end(ProofOutcome::DeviceError, error);
        m_drive->moveBy(kClearance, [this](const StepMoveResult &r) {
            if (m_drive->halt() != ProofDrive::Halt::None)
                return endOnHalt();
            if (!r.arrived)
                return end(ProofOutcome::DeviceError, r.text);
            cycleMove();
        });
    });
}

void AxisProof::cycleMove()
{
    if (m_move >= 2 * m_options.cycles)
        return endHalf();
    const bool away = m_move % 2 == 0;
    const bool fast = away == m_out;
    m_drive->setSpeed(fast ? m_result.speedRpm : m_slowRpm, m_result.accel,
                      [this, away](const QString &error) {
                          if (m_drive->halt() != ProofDrive::Halt::None)
                              return endOnHalt();
                          if (!error.isEmpty())
                              return end(ProofOutcome::DeviceError, error);
                          m_drive->moveBy(away ? m_options.distance : -m_options.distance,
                                          [this](const StepMoveResult &r) { onMoved(r); });
                      });
}

void AxisProof::onMoved(const StepMoveResult &r)
{
    if (m_drive->halt() != ProofDrive::Halt::None)
        return endOnHalt();
    if (!r.arrived) {
        // A move back that ran onto the switch (the negative limit) lost more than the
        // clearance: the reference says how much.
        const AxisEnd *end = r.outcome ? r.outcome->axis(r.request.motor) : nullptr;
        if (end && end->limitNegativeOn && r.request.value < 0 &&
            r.outcome->cause == MotionCause::None)
            return endHalf();
        return this->end(ProofOutcome::DeviceError, r.text);
    }
    ++m_move;
    cycleMove();
}

void AxisProof::endHalf()
{
    Q_EMIT progress(tr("Motor %1: reference on the home switch").arg(m_options.motor));
    m_drive->setSpeed(m_slowRpm, m_result.accel, [this](const QString &error) {
        if (m_drive->halt() != ProofDrive::Halt::None)
            return endOnHalt();
        if (!error.isEmpty())
            return end(ProofOutcome::DeviceError, error);
        reference([this](double found) {
            // Where the switch now comes ON, in the count: higher when the carriage fell
            // behind the count.
            const double lost = m_base - found;
            (m_out ? m_result.lostOut : m_result.lostBack) = lost;
            Q_EMIT halfDone(m_out, lost);
            m_base = found;
            if (m_out)
                return startHalf(false);
            end(ProofOutcome::Done, QString());
        });
    });
}

void AxisProof::endOnHalt()
{
    using H = ProofDrive::Halt;
    const H halt = m_drive->halt();
    const ProofOutcome outcome = halt == H::EmergencyStop ? ProofOutcome::EmergencyStop
                                 : halt == H::LinkLost    ? ProofOutcome::LinkLost
                                 : halt == H::Restarted   ? ProofOutcome::Restarted
                                                          : ProofOutcome::Stopped;
    end(outcome, m_drive->haltText());
}

void AxisProof::stop()
{
    if (!m_running || m_ending)
        return;
    if (m_waiting) {
        m_waiting = false;
        end(ProofOutcome::Stopped, tr("Stopped before anything moved"));
        return;
    }
    m_drive->stop(); // the move under way ends and its continuation ends the test
}

void AxisProof::end(ProofOutcome outcome, const QString &text)
{
    if (m_ending)
        return;
    m_ending = true;
    m_waiting = false;
    m_result.outcome = outcome;
    const double tolerance = m_result.repeatability.value_or(0) + m_result.resolution;
    const auto lostHalf = [tolerance](const std::optional<double> &v) {
        return v && std::abs(*v) > tolerance + 1e-9;
    };
    using V = LostStepResult::Verdict;
    if (!m_result.repeatability || tolerance >= m_result.chunk)
        m_result.verdict = V::Unknown;
    else if (lostHalf(m_result.lostOut) || lostHalf(m_result.lostBack))
        m_result.verdict = V::Lost; // a loss measured is real, however the test ended
    else if (outcome == ProofOutcome::Done)
        m_result.verdict = V::Kept;
    else
        m_result.verdict = V::Unknown;
    QString said = text;
    if (outcome == ProofOutcome::Done) {
        const QString unit = m_drive->parameter("position")->unit;
        said = tr("Motor %1 %2 at %3 rpm: %4 %5 off after the moves out, %6 %5 after the moves "
                  "back (switch repeatability %7 %5, 4 full steps %8 %5)")
                   .arg(m_options.motor)
                   .arg(m_result.verdictText())
                   .arg(m_result.speedRpm)
                   .arg(m_result.lostOut.value_or(0), 0, 'f', 3)
                   .arg(unit)
                   .arg(m_result.lostBack.value_or(0), 0, 'f', 3)
                   .arg(m_result.repeatability.value_or(0), 0, 'f', 3)
                   .arg(m_result.chunk, 0, 'f', 3);
        if (m_result.verdict == V::Unknown)
            said = proofSentences(
                said, tr("The switch did not repeat well enough to tell a loss of 4 full steps."));
    }
    if (outcome == ProofOutcome::Refused) {
        // Nothing was moved or written.
        m_result.restored = true;
        m_result.text = said;
        m_running = false;
        Q_EMIT finished(m_result);
        return;
    }
    m_drive->restore([this, said](bool restored, const QString &restoreText) {
        m_result.restored = restored;
        m_result.text = proofSentences(said, restoreText);
        m_running = false;
        Q_EMIT finished(m_result);
    });
}

} // namespace stepcom
