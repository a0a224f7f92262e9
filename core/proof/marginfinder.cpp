#include "proof/marginfinder.h"

#include "proof/axisproof.h"
#include "proof/proofdrive.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QJsonArray>

#include <cmath>

namespace stepcom {

QJsonObject MarginResult::toJson() const
{
    const QString unit = accel ? QStringLiteral("accel") : QStringLiteral("rpm");
    const auto value = [](const std::optional<qint64> &v) {
        return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null);
    };
    QJsonArray list;
    for (const MarginStep &s : steps) {
        LostStepResult words;
        words.verdict = s.verdict;
        list.append(QJsonObject{{unit, s.value},
                                {QStringLiteral("lost_mm"), proofJsonValue(s.lost)},
                                {QStringLiteral("verdict"), words.verdictWord()}});
    }
    QJsonObject o{{QStringLiteral("motor"), motor},
                  {QStringLiteral("kept_") + unit, value(kept)},
                  {QStringLiteral("stall_") + unit, value(stall)},
                  {QStringLiteral("recommended_") + unit, value(recommended)},
                  {QStringLiteral("steps"), list},
                  {QStringLiteral("outcome"), proofOutcomeWord(outcome)},
                  {QStringLiteral("simulator"), simulator},
                  {QStringLiteral("restored"), restored},
                  {QStringLiteral("message"), text}};
    if (accel)
        o.insert(QStringLiteral("speed_rpm"), speedRpm);
    return o;
}

QList<qint64> MarginFinder::values(qint64 from, qint64 to, qint64 step)
{
    QList<qint64> list;
    if (step < 1 || to < from)
        return list;
    for (qint64 v = from; v < to; v += step)
        list << v;
    list << to;
    return list;
}

MarginFinder::MarginFinder(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{}

MarginFinder::~MarginFinder() = default;

bool MarginFinder::start(const Options &options)
{
    if (m_running || !m_session)
        return false;
    m_options = options;
    m_result = MarginResult{};
    m_result.motor = options.motor;
    m_result.accel = options.accel;
    m_index = 0;
    m_base.reset();
    m_running = true;
    m_waiting = false;
    m_stopped = false;
    ProofDrive::renew(m_drive, m_session, options.motor, this);
    if (const QString why = m_drive->refusal(); !why.isEmpty()) {
        end(ProofOutcome::Refused, why);
        return true;
    }
    m_result.simulator = m_session->connection()->isSimulator();
    m_drive->readSetup([this](const QString &error) { onSetup(error); });
    return true;
}

void MarginFinder::onSetup(const QString &error)
{
    if (!error.isEmpty())
        return end(ProofOutcome::DeviceError, error);
    if (const QString why = check(); !why.isEmpty())
        return end(ProofOutcome::Refused, why);
    const Parameter *p = m_drive->parameter(m_options.accel ? "accel_frequency" : "speed");
    QStringList shown;
    for (qint64 v : std::as_const(m_values))
        shown << QString::number(v);
    const QString plan =
        (m_options.accel
             ? tr("Motor %1: the acceleration margin at %2 rpm: the lost-step test (%3 cycle(s) "
                  "of %4 %5 each way) at each acceleration %6 %7, stopping at the first loss")
                   .arg(m_options.motor)
                   .arg(m_result.speedRpm)
             : tr("Motor %1: the speed margin: the lost-step test (%3 cycle(s) of %4 %5 each "
                  "way) at each speed %6 %7, stopping at the first loss")
                   .arg(m_options.motor))
            .arg(m_options.cycles)
            .arg(m_options.distance, 0, 'f', 2)
            .arg(m_drive->parameter("position")->unit, shown.join(QLatin1String(", ")), p->unit) +
        QLatin1Char('\n') +
        tr("  each test references on the home switch (IN%1) and moves up to %2 %3 past it")
            .arg(m_drive->setup().homeInput)
            .arg(AxisProof::kClearance + m_options.distance, 0, 'f', 2)
            .arg(m_drive->parameter("position")->unit) +
        QLatin1Char('\n') +
        tr("  afterwards: speed %1 rpm and acceleration %2 put back and verified; nothing of the "
           "recommendation is written")
            .arg(m_drive->setup().speedRpm)
            .arg(m_drive->setup().accelRaw) +
        QLatin1Char('\n');
    if (m_options.askFirst) {
        m_waiting = true;
        Q_EMIT ready(plan);
        return;
    }
    proceed();
}

QString MarginFinder::check()
{
    const ProofSetup &s = m_drive->setup();
    const Parameter *p = m_drive->parameter(m_options.accel ? "accel_frequency" : "speed");
    m_result.speedRpm = s.speedRpm;
    const qint64 own = m_options.accel ? s.accelRaw : s.speedRpm;
    const qint64 from = m_options.from.value_or(own);
    const qint64 top =
        m_options.accel ? std::min(p->rawMax, std::max<qint64>(from, 1) * 10) : p->rawMax;
    const qint64 to = m_options.to.value_or(std::max(top, from));
    for (qint64 v : {from, to}) {
        if (const QString why = p->checkRaw(v); !why.isEmpty())
            return tr("Motor %1: %2 %3: %4").arg(m_options.motor).arg(v).arg(p->unit, why);
    }
    if (to < from)
        return tr("the search must go up: from %1 is above to %2").arg(from).arg(to);
    const qint64 step = m_options.step.value_or(
        std::max<qint64>(1, (to - from + kDefaultSteps - 1) / kDefaultSteps));
    if (step < 1)
        return tr("the step must be at least 1, not %1").arg(step);
    m_values = values(from, to, step);
    if (m_values.size() > 100)
        return tr("%1 values to test: take a larger step (at most 100)").arg(m_values.size());
    return m_drive->homeInputRefusal();
}

void MarginFinder::proceed()
{
    if (!m_running || m_proof)
        return;
    m_waiting = false;
    m_proof = new AxisProof(m_session, this);
    connect(m_proof, &AxisProof::progress, this, &MarginFinder::progress);
    connect(m_proof, &AxisProof::finished, this, &MarginFinder::onTested);
    next();
}

void MarginFinder::next()
{
    const qint64 value = m_values.at(m_index);
    const Parameter *p = m_drive->parameter(m_options.accel ? "accel_frequency" : "speed");
    Q_EMIT progress(tr("Motor %1: testing %2 %3 (%4 of %5)")
                        .arg(m_options.motor)
                        .arg(value)
                        .arg(p->unit)
                        .arg(m_index + 1)
                        .arg(m_values.size()));
    AxisProof::Options o;
    o.motor = m_options.motor;
    o.cycles = m_options.cycles;
    o.distance = m_options.distance;
    (m_options.accel ? o.accel : o.speedRpm) = value;
    if (m_base)
        o.baseline = AxisProof::Baseline{*m_base, m_repeatability};
    m_proof->start(o);
}

void MarginFinder::onTested(const LostStepResult &r)
{
    using V = LostStepResult::Verdict;
    MarginStep step;
    step.value = m_values.at(m_index);
    if (r.lostOut || r.lostBack)
        step.lost = r.lost();
    step.verdict = r.verdict;
    m_result.restored = r.restored;
    if (r.outcome == ProofOutcome::Done || step.verdict == V::Lost) {
        m_result.steps << step;
        Q_EMIT stepDone(step);
    }
    if (r.verdict == V::Lost) {
        m_result.stall = step.value;
        return end(ProofOutcome::Done, QString());
    }
    if (r.outcome != ProofOutcome::Done)
        return end(m_stopped ? ProofOutcome::Stopped : r.outcome, r.text);
    if (r.verdict == V::Unknown)
        return end(ProofOutcome::Done, r.text);
    m_result.kept = step.value;
    m_base = r.endReference;
    m_repeatability = r.repeatability.value_or(0);
    if (++m_index >= m_values.size())
        return end(ProofOutcome::Done, QString());
    next();
}

void MarginFinder::stop()
{
    if (!m_running)
        return;
    m_stopped = true;
    if (m_proof && m_proof->isRunning()) {
        m_proof->stop();
        return;
    }
    end(ProofOutcome::Stopped, tr("Stopped before anything moved"));
}

void MarginFinder::end(ProofOutcome outcome, const QString &text)
{
    if (!m_running)
        return;
    m_running = false;
    m_result.outcome = outcome;
    if (outcome == ProofOutcome::Refused || m_result.steps.isEmpty())
        m_result.restored = outcome == ProofOutcome::Refused || m_result.restored;
    if (m_result.kept)
        m_result.recommended = qint64(std::floor(*m_result.kept * MarginResult::kRecommendedShare));
    const QString unit =
        m_options.accel ? m_drive->parameter("accel_frequency")->unit : QStringLiteral("rpm");
    QString said = text;
    if (outcome == ProofOutcome::Done && text.isEmpty()) {
        if (m_result.kept && m_result.stall)
            said = tr("Motor %1 kept its steps up to %2 %3 and lost them at %4 %3: run at %5 %3 "
                      "or less")
                       .arg(m_options.motor)
                       .arg(*m_result.kept)
                       .arg(unit)
                       .arg(*m_result.stall)
                       .arg(*m_result.recommended);
        else if (m_result.kept)
            said = tr("Motor %1 kept its steps at every value up to %2 %3: run at %4 %3 or less")
                       .arg(m_options.motor)
                       .arg(*m_result.kept)
                       .arg(unit)
                       .arg(*m_result.recommended);
        else
            said = tr("Motor %1 lost steps already at %2 %3, the lowest value tested")
                       .arg(m_options.motor)
                       .arg(m_result.stall.value_or(0))
                       .arg(unit);
    }
    m_result.text = said;
    Q_EMIT finished(m_result);
}

} // namespace stepcom
