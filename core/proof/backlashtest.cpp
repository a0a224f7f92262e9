#include "proof/backlashtest.h"

#include "motion/travellimits.h"
#include "proof/proofdrive.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace stepcom {

QList<double> BacklashResult::losses() const
{
    QList<double> list;
    for (int i = 2; i < readings.size(); ++i)
        list << distance - std::abs(readings.at(i) - readings.at(i - 1));
    return list;
}

QJsonObject BacklashResult::toJson() const
{
    QJsonArray shown;
    for (double r : readings)
        shown.append(r);
    return {{QStringLiteral("motor"), motor},
            {QStringLiteral("distance_mm"), distance},
            {QStringLiteral("cycles"), cycles},
            {QStringLiteral("backlash_mm"), proofJsonValue(backlash)},
            {QStringLiteral("readings"), shown},
            {QStringLiteral("spread_mm"), proofJsonValue(spread)},
            {QStringLiteral("resolution_mm"), resolution},
            {QStringLiteral("approach_from_one_side"), approachFromOneSide()},
            {QStringLiteral("outcome"), proofOutcomeWord(outcome)},
            {QStringLiteral("simulator"), simulator},
            {QStringLiteral("restored"), restored},
            {QStringLiteral("message"), text}};
}

BacklashTest::BacklashTest(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{}

BacklashTest::~BacklashTest() = default;

bool BacklashTest::start(const Options &options)
{
    if (m_running || !m_session)
        return false;
    m_options = options;
    m_result = BacklashResult{};
    m_result.motor = options.motor;
    m_result.cycles = options.cycles;
    m_result.distance = options.distance;
    m_move = 0;
    m_running = true;
    m_waiting = m_wantReading = m_ending = false;
    ProofDrive::renew(m_drive, m_session, options.motor, this);
    if (const QString why = m_drive->refusal(); !why.isEmpty()) {
        end(ProofOutcome::Refused, why);
        return true;
    }
    m_result.simulator = m_session->connection()->isSimulator();
    m_drive->readSetup([this](const QString &error) { onSetup(error); });
    return true;
}

void BacklashTest::onSetup(const QString &error)
{
    if (!error.isEmpty())
        return end(ProofOutcome::DeviceError, error);
    const ProofSetup &s = m_drive->setup();
    m_result.resolution = s.resolution();
    m_slowRpm =
        std::max<qint64>(1, qint64(std::floor(std::min(s.rpmOfHz(s.startHz), double(s.speedRpm)))));
    const QString unit = m_drive->parameter("position")->unit;
    if (m_options.cycles < 1 || m_options.cycles > 100)
        return end(ProofOutcome::Refused,
                   tr("cycles must be 1 to 100, not %1").arg(m_options.cycles));
    const Parameter *distance = m_drive->parameter("move_distance");
    if (!(m_options.distance > 0) ||
        (distance && std::llround(m_options.distance * distance->scale) > distance->rawMax))
        return end(ProofOutcome::Refused,
                   tr("the distance must be above 0 and within the single move's range, not %1")
                       .arg(m_options.distance));
    for (double target : {s.position - m_options.distance, s.position + m_options.distance}) {
        if (const QString why = m_session->travelLimits().refuseTarget(
                m_session->map(), m_options.motor, s.position, target);
            !why.isEmpty())
            return end(ProofOutcome::Refused, tr("The test moves %1 %2 either way: %3")
                                                  .arg(m_options.distance, 0, 'f', 2)
                                                  .arg(unit, why));
    }
    const QString plan =
        tr("Motor %1: the backlash test with a dial gauge on the carriage").arg(m_options.motor) +
        QLatin1Char('\n') +
        tr("  back %1 %2 and on %1 %2 (the approach), then %3 time(s) on %1 %2 and back %1 %2, "
           "at %4 rpm; the gauge is read %5 times")
            .arg(m_options.distance, 0, 'f', 2)
            .arg(unit)
            .arg(m_options.cycles)
            .arg(m_slowRpm)
            .arg(readingsWanted()) +
        QLatin1Char('\n') + tr("  afterwards: speed %1 rpm put back and verified").arg(s.speedRpm) +
        QLatin1Char('\n');
    if (m_options.askFirst) {
        m_waiting = true;
        Q_EMIT ready(plan);
        return;
    }
    proceed();
}

void BacklashTest::proceed()
{
    if (!m_running || m_ending)
        return;
    m_waiting = false;
    m_drive->setSpeed(m_slowRpm, std::nullopt, [this](const QString &error) {
        if (m_drive->halt() != ProofDrive::Halt::None)
            return end(ProofOutcome::Stopped, m_drive->haltText());
        if (!error.isEmpty())
            return end(ProofOutcome::DeviceError, error);
        Q_EMIT progress(tr("Motor %1: the approach").arg(m_options.motor));
        m_drive->moveBy(-m_options.distance, [this](const StepMoveResult &r) {
            if (m_drive->halt() != ProofDrive::Halt::None || !r.arrived)
                return onMoved(r, QString());
            move(m_options.distance, tr("after the approach"));
        });
    });
}

void BacklashTest::move(double units, const QString &where)
{
    m_drive->moveBy(units, [this, where](const StepMoveResult &r) { onMoved(r, where); });
}

void BacklashTest::onMoved(const StepMoveResult &r, const QString &where)
{
    using H = ProofDrive::Halt;
    switch (m_drive->halt()) {
    case H::None:
        break;
    case H::Stopped:
        return end(ProofOutcome::Stopped, m_drive->haltText());
    case H::EmergencyStop:
        return end(ProofOutcome::EmergencyStop, m_drive->haltText());
    case H::LinkLost:
        return end(ProofOutcome::LinkLost, m_drive->haltText());
    case H::Restarted:
        return end(ProofOutcome::Restarted, m_drive->haltText());
    }
    if (!r.arrived)
        return end(ProofOutcome::DeviceError, r.text);
    m_wantReading = true;
    Q_EMIT readingWanted(int(m_result.readings.size()), where);
}

void BacklashTest::giveReading(double value)
{
    if (!m_wantReading || m_ending)
        return;
    m_wantReading = false;
    m_result.readings << value;
    nextMove();
}

void BacklashTest::nextMove()
{
    if (m_result.readings.size() >= readingsWanted()) {
        const QList<double> losses = m_result.losses();
        double sum = 0;
        for (double l : losses)
            sum += l;
        m_result.backlash = sum / losses.size();
        const auto [lo, hi] = std::minmax_element(losses.begin(), losses.end());
        m_result.spread = *hi - *lo;
        const QString unit = m_drive->parameter("position")->unit;
        QString text = tr("Motor %1: backlash %2 %3 (spread %4 %3 over %5 reversals)")
                           .arg(m_options.motor)
                           .arg(*m_result.backlash, 0, 'f', 3)
                           .arg(unit)
                           .arg(*m_result.spread, 0, 'f', 3)
                           .arg(losses.size());
        if (m_result.approachFromOneSide())
            text = proofSentences(
                text, tr("It is more than the count's resolution: position the axis from one side "
                         "(approach every point in the same direction)"));
        return end(ProofOutcome::Done, text);
    }
    const bool on = m_move % 2 == 0;
    ++m_move;
    Q_EMIT progress(
        tr("Motor %1: move %2 of %3").arg(m_options.motor).arg(m_move).arg(2 * m_options.cycles));
    move(on ? m_options.distance : -m_options.distance,
         on ? tr("after moving on by %1").arg(m_options.distance)
            : tr("after moving back by %1").arg(m_options.distance));
}

void BacklashTest::stop()
{
    if (!m_running || m_ending)
        return;
    if (m_waiting || m_wantReading) {
        m_waiting = m_wantReading = false;
        m_drive->stop();
        return end(ProofOutcome::Stopped, tr("Stopped: no more readings"));
    }
    m_drive->stop(); // the move under way ends, and the test with it
}

void BacklashTest::end(ProofOutcome outcome, const QString &text)
{
    if (m_ending)
        return;
    m_ending = true;
    m_result.outcome = outcome;
    if (outcome == ProofOutcome::Refused || !m_drive) {
        m_result.restored = true;
        m_result.text = text;
        m_running = false;
        Q_EMIT finished(m_result);
        return;
    }
    m_drive->restore([this, text](bool restored, const QString &restoreText) {
        m_result.restored = restored;
        m_result.text = proofSentences(text, restoreText);
        m_running = false;
        Q_EMIT finished(m_result);
    });
}

} // namespace stepcom
