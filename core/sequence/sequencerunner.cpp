#include "sequence/sequencerunner.h"

#include "device/deviceclient.h"
#include "map/registermap.h"
#include "motion/referencetracker.h"
#include "sequence/sequencecheck.h"
#include "sequence/sequencemove.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"

namespace stepcom {

SequenceRunner::SequenceRunner(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_move(new SequenceMove(session, this))
{
    m_timer.setSingleShot(true);
    m_stopGrace.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (!m_running || m_ending != Ending::None)
            return;
        if (!m_waitInputKey.isEmpty()) {
            m_waitInputKey.clear();
            end(SequenceResult::Outcome::Timeout,
                tr("%1: the input did not come within %2 s")
                    .arg(m_step ? m_step->describe() : QString())
                    .arg(m_step ? m_step->timeoutMs / 1000.0 : 0.0, 0, 'g', 6));
            return;
        }
        stepDone(); // a dwell
    });
    connect(&m_stopGrace, &QTimer::timeout, this, &SequenceRunner::afterStopped);
    connect(m_move, &SequenceMove::finished, this, &SequenceRunner::onMoved);
    connect(session, &DeviceSession::commandFinished, this, &SequenceRunner::onCommand);
    connect(session->motion(), &MotionSupervisor::finished, this, &SequenceRunner::onMotion);
    connect(session->status(), &SessionStatus::statusCycleFinished, this,
            [this](bool ok, qint64) { onStatusCycle(ok); });
    connect(session, &DeviceSession::emergencyStopRequested, this, [this] {
        if (m_running)
            end(SequenceResult::Outcome::EmergencyStop,
                tr("E-STOP: every motor and output stopped; the run ended"), true);
    });
    connect(session->connection(), &SessionConnection::linkLost, this,
            [this](const QString &reason) {
                if (m_running)
                    end(SequenceResult::Outcome::LinkLost,
                        tr("the link was lost (%1): the run ended; the controller goes on with "
                           "what it was doing")
                            .arg(reason),
                        true);
            });
    const auto restarted = [this](int id) {
        if (m_running && m_session && id == m_session->line()->deviceInView())
            end(SequenceResult::Outcome::Restarted,
                tr("the controller restarted (or may have): its positions and references are "
                   "gone; the run ended"),
                true, true);
    };
    connect(session, &DeviceSession::controllerRestarted, this,
            [restarted](int id, const QStringList &, const RestartWatch::Evidence &) {
                restarted(id);
            });
    connect(session, &DeviceSession::controllerMayHaveRestarted, this,
            [restarted](int id, const RestartWatch::Evidence &) { restarted(id); });
}

SequenceRunner::~SequenceRunner() = default;

QStringList SequenceRunner::check(const Sequence &sequence, int cycles) const
{
    SequenceCheck::Start start;
    const ReferenceTracker *refs = m_session->motion()->references();
    for (int m = 1; m <= m_session->map().blockCount(kMotorBlock); ++m)
        start.axes.insert(m, SequenceCheck::Axis{refs->isReferenced(m), std::nullopt});
    return SequenceCheck::check(sequence, m_session->map(), m_session->travelLimits(), start,
                                cycles);
}

bool SequenceRunner::start(const Sequence &sequence, int cycles)
{
    if (m_running || !m_session || !m_session->connection()->isConnected())
        return false;
    m_sequence = sequence;
    m_cycles = std::max(1, cycles);
    m_running = true;
    m_preparing = true;
    m_paused = false;
    m_singleStep = false;
    m_ending = Ending::None;
    m_result = SequenceResult{};
    m_outputsOn.clear();
    m_userSpeed.clear();
    m_speedSet.clear();
    m_movesRestored = true;
    m_speedsRestored = true;
    m_waitCommand.clear();
    m_waitMotion.clear();
    m_waitInputKey.clear();
    m_step = nullptr;
    m_cycle = 0;
    m_clock.start();
    const RegisterMap &map = m_session->map();
    QList<const Parameter *> params;
    for (int m = 1; m <= map.blockCount(kMotorBlock); ++m) {
        for (const char *local : {"position", "running", "speed"}) {
            if (const Parameter *p = map.blockParameter(kMotorBlock, m, QLatin1String(local)))
                params << p;
        }
    }
    for (const char *key : {"homing.first", "homing.second"}) {
        if (const Parameter *p = map.find(QLatin1String(key)))
            params << p;
    }
    for (int n = 1; const Parameter *p = map.find(QStringLiteral("io.out%1").arg(n)); ++n)
        params << p;
    m_session->parameters()->read(
        params,
        [self = QPointer<SequenceRunner>(this)](const ReadOutcome &r) {
            if (self)
                self->onPrepared(r);
        },
        Priority::Command);
    return true;
}

void SequenceRunner::onPrepared(const ReadOutcome &read)
{
    if (!m_running || !m_preparing || m_ending != Ending::None)
        return;
    m_preparing = false;
    if (!read.ok) {
        end(SequenceResult::Outcome::DeviceError,
            tr("could not read the positions, speeds and homing order (%1): nothing was moved")
                .arg(read.errors.join(QLatin1String("; "))),
            true);
        return;
    }
    m_session->parameters()->store()->setDeviceValues(read.values);
    const RegisterMap &map = m_session->map();
    SequenceCheck::Start start;
    const ReferenceTracker *refs = m_session->motion()->references();
    QStringList running;
    for (int m = 1; m <= map.blockCount(kMotorBlock); ++m) {
        SequenceCheck::Axis axis{refs->isReferenced(m), std::nullopt};
        if (const Parameter *p = map.blockParameter(kMotorBlock, m, QStringLiteral("position"));
            p && read.values.contains(p->key))
            axis.position = p->toEngineering(read.values.value(p->key));
        start.axes.insert(m, axis);
        if (const Parameter *p = map.blockParameter(kMotorBlock, m, QStringLiteral("running"));
            p && read.values.value(p->key) != 0)
            running << tr("motor %1 is running").arg(m);
        if (const Parameter *p = map.blockParameter(kMotorBlock, m, QStringLiteral("speed"));
            p && read.values.contains(p->key))
            m_userSpeed.insert(m, read.values.value(p->key));
    }
    start.homingOrder =
        SequenceCheck::homingOrder(read.values.value(QStringLiteral("homing.first")),
                                   read.values.value(QStringLiteral("homing.second")));
    for (int n = 1; map.find(QStringLiteral("io.out%1").arg(n)); ++n) {
        if (read.values.value(QStringLiteral("io.out%1").arg(n)) != 0)
            m_outputsOn.insert(n);
    }
    m_result.problems =
        running + SequenceCheck::check(m_sequence, map, m_session->travelLimits(), start, m_cycles);
    if (!m_result.problems.isEmpty()) {
        m_result.restored = true;
        end(SequenceResult::Outcome::Refused,
            tr("the run was refused before anything moved: %1")
                .arg(m_result.problems.join(QLatin1String("; "))),
            true);
        return;
    }
    // The supervisor judges moves and homing from the status poll, and a wait reads its input
    // there.
    if (!m_session->status()->isActive()) {
        m_session->status()->start();
        m_startedPoll = true;
    }
    m_stack = {Frame{&m_sequence.steps, 0, 0, m_cycles}};
    m_cycle = 1;
    m_clock.restart();
    m_cycleClock.start();
    Q_EMIT started(m_cycles);
    Q_EMIT cycleStarted(m_cycle);
    next();
}

const SequenceStep *SequenceRunner::nextStep(QList<Frame> &stack, bool announce)
{
    while (!stack.isEmpty()) {
        Frame &f = stack.last();
        if (f.index >= f.steps->size()) {
            ++f.iteration;
            const bool top = stack.size() == 1;
            if (top && announce) {
                const double seconds = m_cycleClock.nsecsElapsed() / 1e9;
                m_result.cycleSeconds << seconds;
                m_result.cyclesDone = f.iteration;
                Q_EMIT cycleFinished(m_cycle, seconds);
            }
            if (f.iteration < f.count) {
                f.index = 0;
                if (top && announce) {
                    ++m_cycle;
                    m_cycleClock.restart();
                    Q_EMIT cycleStarted(m_cycle);
                }
                continue;
            }
            stack.removeLast();
            continue;
        }
        const SequenceStep *step = &f.steps->at(f.index++);
        if (step->kind == SequenceStep::Kind::Repeat) {
            stack << Frame{&step->steps, 0, 0, step->count};
            continue;
        }
        return step;
    }
    return nullptr;
}

QString SequenceRunner::currentStep() const
{
    if (m_step)
        return m_step->path;
    QList<Frame> copy = m_stack;
    const SequenceStep *s = const_cast<SequenceRunner *>(this)->nextStep(copy, false);
    return s ? s->path : QString();
}

void SequenceRunner::next()
{
    if (!m_running || m_ending != Ending::None || m_paused)
        return;
    const SequenceStep *step = nextStep(m_stack, true);
    if (!step) {
        end(SequenceResult::Outcome::Done, tr("%n cycle(s) done", nullptr, m_result.cyclesDone));
        return;
    }
    m_step = step;
    m_stepPath = step->path;
    Q_EMIT stepStarted(m_cycle, step->path, step->describe());
    execute(*step);
}

void SequenceRunner::stepDone()
{
    const SequenceStep *step = m_step;
    m_step = nullptr;
    if (step)
        Q_EMIT stepFinished(m_cycle, step->path, step->describe());
    if (!m_running || m_ending != Ending::None)
        return;
    if (m_pauseAfterStep || m_singleStep) {
        m_singleStep = false;
        const QString following = currentStep();
        if (!following.isEmpty()) {
            m_paused = true;
            Q_EMIT paused(following);
            return;
        }
    }
    // Queued: a loop of instant steps never deepens the stack.
    QMetaObject::invokeMethod(this, &SequenceRunner::next, Qt::QueuedConnection);
}

void SequenceRunner::singleStep()
{
    if (!m_paused)
        return;
    m_paused = false;
    m_singleStep = true;
    next();
}

void SequenceRunner::resume()
{
    if (!m_paused)
        return;
    m_paused = false;
    next();
}

void SequenceRunner::stop()
{
    if (m_running)
        end(SequenceResult::Outcome::Interrupted, tr("stopped: the run was interrupted"));
}

void SequenceRunner::sendStops()
{
    for (int m = 1; m <= m_session->map().blockCount(kMotorBlock); ++m) {
        if (const Parameter *p =
                m_session->map().blockParameter(kMotorBlock, m, QStringLiteral("stop")))
            m_session->command(p->key);
    }
}

void SequenceRunner::end(SequenceResult::Outcome outcome, const QString &text, bool atOnce,
                         bool sendStop)
{
    if (!m_running || m_ending == Ending::AtOnce || (m_ending == Ending::Soft && !atOnce))
        return;
    if (m_ending == Ending::None) {
        m_result.outcome = outcome;
        m_result.text = text;
        m_result.step = outcome == SequenceResult::Outcome::Done ? QString() : m_stepPath;
    }
    m_timer.stop();
    m_waitInputKey.clear();
    m_waitCommand.clear();
    m_paused = false;
    if (atOnce) {
        m_ending = Ending::AtOnce;
        if (sendStop && m_session && m_session->connection()->isConnected())
            sendStops();
        complete();
        return;
    }
    m_ending = Ending::Soft;
    if (outcome == SequenceResult::Outcome::Done) {
        restoreSpeeds();
        return;
    }
    sendStops();
    if (m_move->isBusy() || !m_waitMotion.isEmpty()) {
        m_stopGrace.start(3000); // the stopped motion's verdict, or on without it
        return;
    }
    afterStopped();
}

void SequenceRunner::afterStopped()
{
    if (!m_running || m_ending != Ending::Soft)
        return;
    m_stopGrace.stop();
    m_waitMotion.clear();
    if (m_sequence.outputsOffOnStop) {
        if (const Parameter *p = m_session->map().find(QStringLiteral("outputs_all_off"))) {
            m_waitCommand = p->key;
            m_session->command(p->key);
            return; // onCommand goes on
        }
    }
    restoreSpeeds();
}

void SequenceRunner::restoreSpeeds()
{
    if (!m_running)
        return;
    const RegisterMap &map = m_session->map();
    QList<ParameterWrite> writes;
    for (auto it = m_speedSet.begin(); it != m_speedSet.end(); ++it) {
        const Parameter *p = map.blockParameter(kMotorBlock, it.key(), QStringLiteral("speed"));
        if (p && m_userSpeed.contains(it.key()) && it.value() != m_userSpeed.value(it.key()))
            writes.append({p, m_userSpeed.value(it.key())});
    }
    if (writes.isEmpty() || !m_session->connection()->isConnected()) {
        m_speedsRestored = writes.isEmpty();
        complete();
        return;
    }
    m_session->parameters()->write(writes,
                                   [self = QPointer<SequenceRunner>(this)](const WriteOutcome &w) {
                                       if (!self)
                                           return;
                                       self->m_speedsRestored = w.ok;
                                       if (w.ok)
                                           self->m_speedSet.clear();
                                       self->complete();
                                   });
}

void SequenceRunner::complete()
{
    if (!m_running)
        return;
    if (m_startedPoll && m_session) {
        m_session->status()->stop();
        m_startedPoll = false;
    }
    m_running = false;
    m_preparing = false;
    m_stopGrace.stop();
    m_result.elapsedSeconds = m_clock.nsecsElapsed() / 1e9;
    if (m_result.outcome != SequenceResult::Outcome::Refused) {
        // Cut short at once: what a speed step or a move left set is not known to be back.
        const bool speeds = m_ending == Ending::AtOnce ? m_speedSet.isEmpty() : m_speedsRestored;
        m_result.restored = speeds && m_movesRestored && !m_move->isBusy();
        if (!m_result.restored)
            m_result.text += QLatin1String(". ") +
                             tr("The motors' own speed or single-move values may not be back: "
                                "read them before the next run");
    }
    m_waitCommand.clear();
    m_waitMotion.clear();
    m_step = nullptr;
    Q_EMIT finished(m_result);
}

} // namespace stepcom
