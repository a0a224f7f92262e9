#include "session/stepmove.h"

#include "motion/motionjudge.h"
#include "motion/travellimits.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"

#include <cmath>

namespace stepcom {

StepMove::StepMove(DeviceSession *session)
    : QObject(session)
    , m_session(session)
{
    connect(session, &DeviceSession::commandFinished, this, &StepMove::onCommand);
    connect(session->motion(), &MotionSupervisor::finished, this, &StepMove::onOutcome);
}

StepMove::~StepMove() = default;

QStringList StepMove::usedKeys(const DeviceSession &session, int motor)
{
    QStringList keys;
    for (const char *local : {"move_distance", "direction"}) {
        if (const Parameter *p =
                session.map().blockParameter(kMotorBlock, motor, QLatin1String(local)))
            keys << p->key;
    }
    return keys;
}

QString StepMove::key(const char *local) const
{
    const Parameter *p =
        m_session->map().blockParameter(kMotorBlock, m_result.request.motor, QLatin1String(local));
    return p ? p->key : QString();
}

QString StepMove::refusal(const StepMoveRequest &r) const
{
    const DeviceSession &s = *m_session;
    const int motors = s.map().blockCount(kMotorBlock);
    if (r.motor < 1 || r.motor > motors)
        return tr("There is no motor %1 (this controller has %2)").arg(r.motor).arg(motors);
    if (!s.map().blockParameter(kMotorBlock, r.motor, QStringLiteral("move")) ||
        usedKeys(s, r.motor).size() != 2 || !TravelLimits::positionParameter(s.map(), r.motor))
        return tr("This register map has no single move for motor %1").arg(r.motor);
    if (!std::isfinite(r.value))
        return tr("Motor %1: the distance or position is not a number").arg(r.motor);
    if (r.kind == StepMoveRequest::Kind::Raw && r.value < 0)
        return tr("Motor %1: a distance cannot be negative").arg(r.motor);
    if (!s.connection()->isConnected())
        return tr("Not connected: nothing was sent");
    if (m_busy)
        return tr("A step is still running: wait for it to end");
    QStringList edited;
    for (const QString &k : usedKeys(s, r.motor)) {
        if (s.parameters()->store()->editedKeys().contains(k))
            edited << s.map().find(k)->label.text(QString());
    }
    if (!edited.isEmpty())
        return tr("Motor %1: the step uses the single-move distance and direction, and they hold "
                  "edits that were not written. Write or revert them first.")
            .arg(r.motor);
    if (s.jog()->state(r.motor) != JogController::State::Idle)
        return tr("Motor %1 is jogging: let go first").arg(r.motor);
    if (s.motion()->active(r.motor))
        return tr("Motor %1 is moving: wait until it ends").arg(r.motor);
    return {};
}

QString StepMove::start(const StepMoveRequest &request)
{
    if (const QString why = refusal(request); !why.isEmpty())
        return why;
    m_busy = true;
    m_result = StepMoveResult{};
    m_result.request = request;
    m_startedPoll = false;
    m_waitingCommand = false;
    m_unsavedBefore = m_session->parameters()->store()->unsavedToFlash();
    const RegisterMap &map = m_session->map();
    // The step's own registers and what the motion judge reads (limits, inputs, the mode):
    // a step is judged on what `command motorN.move --wait` is judged on.
    QStringList keys;
    for (const char *local : {"position", "running", "move_distance", "direction"}) {
        if (const Parameter *p =
                map.blockParameter(kMotorBlock, request.motor, QLatin1String(local)))
            keys << p->key;
    }
    for (const QString &k : MotionJudge::inputKeys(map, key("move"))) {
        if (!keys.contains(k))
            keys << k;
    }
    QList<const Parameter *> params;
    for (const QString &k : std::as_const(keys))
        params << map.find(k);
    Q_EMIT started(request);
    // What the axis and the user's registers hold now, not what the last poll saw.
    m_session->parameters()->read(
        params,
        [self = QPointer<StepMove>(this)](const ReadOutcome &r) {
            if (self)
                self->onRead(r.ok, r.values, r.errors);
        },
        Priority::Command);
    return {};
}

void StepMove::onRead(bool ok, const QHash<QString, qint64> &values, const QStringList &errors)
{
    if (!m_session)
        return;
    if (!ok) {
        finish(tr("Motor %1: could not read the position and the single-move values (%2): "
                  "nothing was moved")
                   .arg(m_result.request.motor)
                   .arg(errors.join(QLatin1String("; "))));
        return;
    }
    m_session->parameters()->store()->setDeviceValues(values);
    const RegisterMap &map = m_session->map();
    const StepMoveRequest &r = m_result.request;
    const Parameter *pos = TravelLimits::positionParameter(map, r.motor);
    const Parameter *dist = map.find(key("move_distance"));
    const Parameter *running = map.blockParameter(kMotorBlock, r.motor, QStringLiteral("running"));
    m_userDistance = values.value(dist->key);
    m_userDirection = values.value(key("direction"));
    if (running && values.value(running->key) != 0) {
        finish(tr("Motor %1 is running: nothing was moved").arg(r.motor));
        return;
    }
    const qint64 posRaw = values.value(pos->key);
    const double here = pos->toEngineering(posRaw);
    double target = here;
    switch (r.kind) {
    case StepMoveRequest::Kind::By:
        target = here + r.value;
        break;
    case StepMoveRequest::Kind::To:
        target = r.value;
        break;
    case StepMoveRequest::Kind::Raw:
        target = here + (r.direction ? -r.value : r.value);
        break;
    }
    m_result.startPosition = here;
    m_result.target = target;
    if (const QString why = m_session->travelLimits().refuseTarget(map, r.motor, here, target);
        !why.isEmpty()) {
        finish(why);
        return;
    }
    // In the position register's counts, so 0.1 steps add up exactly.
    const qint64 targetRaw = std::llround(target * pos->scale);
    if (targetRaw < pos->rawMin || targetRaw > pos->rawMax) {
        finish(tr("Motor %1: %2 %3 is outside the position register's range")
                   .arg(r.motor)
                   .arg(pos->formatRaw(std::clamp(targetRaw, pos->rawMin - 1, pos->rawMax + 1)),
                        pos->unit));
        return;
    }
    const qint64 delta = targetRaw - posRaw;
    const qint64 distanceRaw =
        std::llround(double(std::abs(delta)) / double(pos->scale) * double(dist->scale));
    if (distanceRaw == 0) {
        m_result.arrived = true;
        m_result.restored = true; // nothing was written
        finish(tr("Motor %1 already stands at %2 %3: nothing to move")
                   .arg(r.motor)
                   .arg(pos->formatRaw(posRaw), pos->unit));
        return;
    }
    if (distanceRaw > dist->rawMax) {
        finish(tr("Motor %1: a move of %2 %3 is more than the single move can do (%4 %3)")
                   .arg(r.motor)
                   .arg(dist->formatRaw(distanceRaw), dist->unit, dist->formatRaw(dist->rawMax)));
        return;
    }
    const qint64 direction =
        r.kind == StepMoveRequest::Kind::Raw ? r.direction : (delta > 0 ? 0 : 1);
    // Said before the move, as the jog panel and `command --wait` say it: a limit already ON
    // in the step's direction.
    StatusValues planned = values;
    planned.insert(dist->key, distanceRaw);
    planned.insert(key("direction"), direction);
    m_result.warning = MotionJudge::limitWarning(map, key("move"), planned);
    if (!m_result.warning.isEmpty())
        Q_EMIT warned(m_result.warning);
    QList<ParameterWrite> writes;
    if (distanceRaw != m_userDistance)
        writes.append({dist, distanceRaw});
    if (direction != m_userDirection)
        writes.append({map.find(key("direction")), direction});
    const auto go = [this] {
        if (!m_session->status()->isActive()) {
            m_session->status()->start(); // the supervisor judges the end from the status poll
            m_startedPoll = true;
        }
        m_waitingCommand = true;
        m_session->command(key("move"));
    };
    if (writes.isEmpty()) {
        go();
        return;
    }
    m_session->parameters()->write(
        writes, [self = QPointer<StepMove>(this), go](const WriteOutcome &w) {
            if (!self)
                return;
            if (!w.ok) {
                self->restore(tr("the step's distance and direction could not be written (%1): "
                                 "nothing was moved")
                                  .arg(w.errors.join(QLatin1String("; "))));
                return;
            }
            go();
        });
}

void StepMove::onCommand(const QString &commandKey, bool ok)
{
    if (!m_busy || !m_waitingCommand || commandKey != key("move"))
        return;
    m_waitingCommand = false;
    if (!ok) {
        restore(tr("the single move was not acknowledged: nothing was moved"));
        return;
    }
    m_result.started = true;
    // MotionSupervisor follows it now; onOutcome takes its verdict.
}

void StepMove::onOutcome(const MotionOutcome &outcome)
{
    if (!m_busy || !m_result.started || m_waitingCommand || outcome.start.command != key("move"))
        return;
    m_result.outcome = outcome;
    m_result.arrived = outcome.verdict == MotionOutcome::Verdict::Done;
    restore(m_session->motion()->text(outcome));
}

void StepMove::restore(const QString &why)
{
    if (m_startedPoll) {
        m_session->status()->stop();
        m_startedPoll = false;
    }
    const RegisterMap &map = m_session->map();
    const DeviceSession &s = *m_session;
    QList<ParameterWrite> writes;
    const auto held = [&s](const QString &k) { return s.parameters()->store()->deviceValue(k); };
    if (held(key("move_distance")) != m_userDistance)
        writes.append({map.find(key("move_distance")), m_userDistance});
    if (held(key("direction")) != m_userDirection)
        writes.append({map.find(key("direction")), m_userDirection});
    const Parameter *dist = map.find(key("move_distance"));
    const Parameter *dir = map.find(key("direction"));
    const QString userValues =
        tr("distance %1 %2, direction %3")
            .arg(dist->formatRaw(m_userDistance), dist->unit, dir->displayRaw(m_userDirection));
    if (writes.isEmpty()) {
        m_result.restored = true;
        finish(why);
        return;
    }
    if (!m_session->connection()->isConnected()) {
        finish(tr("%1. The single move's own values (%2) could not be put back: not connected. "
                  "Write them again once the controller answers.")
                   .arg(why, userValues));
        return;
    }
    m_session->parameters()->write(
        writes, [self = QPointer<StepMove>(this), why, userValues](const WriteOutcome &w) {
            if (!self)
                return;
            if (!w.ok) {
                self->finish(tr("%1. The single move's own values (%2) could not be put back: %3")
                                 .arg(why, userValues, w.errors.join(QLatin1String("; "))));
                return;
            }
            self->m_result.restored = true;
            // The registers hold what they held before: the flash state is what it was.
            if (!self->m_unsavedBefore)
                self->m_session->parameters()->store()->setUnsavedToFlash(false);
            self->finish(why);
        });
}

void StepMove::finish(const QString &text)
{
    if (m_startedPoll && m_session) {
        m_session->status()->stop();
        m_startedPoll = false;
    }
    m_busy = false;
    m_waitingCommand = false;
    m_result.text = text;
    if (m_result.restored && m_result.started) {
        if (!m_result.text.endsWith(QLatin1Char('.')))
            m_result.text += QLatin1Char('.');
        m_result.text += QLatin1Char(' ') +
                         tr("The single move's own distance and direction are back (verified).");
    }
    Q_EMIT finished(m_result);
}

} // namespace stepcom
