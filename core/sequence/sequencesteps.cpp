// SequenceRunner's steps: what each kind sends and how it knows it is done.
#include "sequence/sequencemove.h"
#include "sequence/sequencerunner.h"

#include "device/deviceclient.h"
#include "device/parameterstore.h"
#include "map/registermap.h"
#include "motion/motionjudge.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

namespace stepcom {

namespace {

QString outputKey(int n)
{
    return QStringLiteral("io.out%1").arg(n);
}

} // namespace

void SequenceRunner::execute(const SequenceStep &step)
{
    switch (step.kind) {
    case SequenceStep::Kind::Home:
        home(step);
        return;
    case SequenceStep::Kind::MoveTo:
    case SequenceStep::Kind::MoveBy:
        move(step);
        return;
    case SequenceStep::Kind::WaitInput:
        waitInput(step);
        return;
    case SequenceStep::Kind::Output:
    case SequenceStep::Kind::Outputs:
        switchOutputs(step);
        return;
    case SequenceStep::Kind::Dwell:
        m_timer.start(step.dwellMs);
        return;
    case SequenceStep::Kind::Speed:
        setSpeed(step);
        return;
    case SequenceStep::Kind::Repeat:
        break; // nextStep() went inside it
    }
    stepDone();
}

void SequenceRunner::home(const SequenceStep &step)
{
    const RegisterMap &map = m_session->map();
    QList<QString> keys;
    if (step.homeInOrder) {
        if (const Parameter *p = map.find(QStringLiteral("home_all")))
            keys << p->key;
    } else {
        for (int m : step.homeMotors) {
            if (const Parameter *p = map.blockParameter(kMotorBlock, m, QStringLiteral("home")))
                keys << p->key;
        }
    }
    if (keys.size() != 1) {
        end(SequenceResult::Outcome::DeviceError,
            tr("this register map has no homing command for %1").arg(step.describe()));
        return;
    }
    // What the judge reads (the home inputs, limits, the mode), as StepMove and `command
    // --wait` read it: a homing is judged on what the controller holds now.
    const QString key = keys.first();
    QList<const Parameter *> params;
    for (const QString &k : MotionJudge::inputKeys(map, key))
        params << map.find(k);
    m_session->parameters()->read(
        params,
        [self = QPointer<SequenceRunner>(this), key](const ReadOutcome &r) {
            if (!self || !self->m_running || self->m_ending != Ending::None)
                return;
            if (!r.ok) {
                self->end(SequenceResult::Outcome::DeviceError,
                          tr("could not read what the homing is judged on (%1): nothing was moved")
                              .arg(r.errors.join(QLatin1String("; "))));
                return;
            }
            self->m_session->parameters()->store()->setDeviceValues(r.values);
            self->m_waitCommand = key;
            self->m_waitMotion = key;
            self->m_session->command(key);
        },
        Priority::Command);
}

void SequenceRunner::move(const SequenceStep &step)
{
    QList<StepMoveRequest> requests;
    for (auto it = step.axes.begin(); it != step.axes.end(); ++it) {
        StepMoveRequest r;
        r.kind = step.kind == SequenceStep::Kind::MoveTo ? StepMoveRequest::Kind::To
                                                         : StepMoveRequest::Kind::By;
        r.motor = it.key();
        r.value = it.value();
        requests << r;
    }
    if (const QString why = m_move->start(requests); !why.isEmpty())
        end(SequenceResult::Outcome::DeviceError, why);
}

void SequenceRunner::waitInput(const SequenceStep &step)
{
    m_waitInputKey = QStringLiteral("io.in%1").arg(step.number);
    m_waitInputOn = step.on;
    if (step.timeoutMs > 0)
        m_timer.start(step.timeoutMs);
    // Judged on the next status cycles: the value held now may be from before this step.
}

void SequenceRunner::switchOutputs(const SequenceStep &step)
{
    const RegisterMap &map = m_session->map();
    const QString key =
        step.kind == SequenceStep::Kind::Output
            ? QStringLiteral("output%1_%2")
                  .arg(step.number)
                  .arg(step.on ? QStringLiteral("on") : QStringLiteral("off"))
            : (step.on ? QStringLiteral("outputs_all_on") : QStringLiteral("outputs_all_off"));
    if (!map.find(key)) {
        end(SequenceResult::Outcome::DeviceError,
            tr("this register map has no command %1").arg(key));
        return;
    }
    m_waitCommand = key;
    m_session->command(key);
}

void SequenceRunner::setSpeed(const SequenceStep &step)
{
    const RegisterMap &map = m_session->map();
    QList<ParameterWrite> writes;
    QHash<int, qint64> raws;
    for (auto it = step.axes.begin(); it != step.axes.end(); ++it) {
        const Parameter *p = map.blockParameter(kMotorBlock, it.key(), QStringLiteral("speed"));
        QString why;
        const auto raw = p ? p->fromEngineering(it.value(), &why) : std::nullopt;
        if (!raw) {
            end(SequenceResult::Outcome::DeviceError, why);
            return;
        }
        writes.append({p, *raw});
        raws.insert(it.key(), *raw);
    }
    // Marked before the write: a write cut short may have reached the controller.
    for (auto it = raws.begin(); it != raws.end(); ++it)
        m_speedSet.insert(it.key(), it.value());
    m_session->parameters()->write(
        writes, [self = QPointer<SequenceRunner>(this)](const WriteOutcome &w) {
            if (!self || !self->m_running || self->m_ending != Ending::None)
                return;
            if (!w.ok) {
                self->end(SequenceResult::Outcome::DeviceError,
                          tr("the speed could not be written and verified (%1)")
                              .arg(w.errors.join(QLatin1String("; "))));
                return;
            }
            self->stepDone();
        });
}

void SequenceRunner::onCommand(const QString &key, bool ok)
{
    if (!m_running || key != m_waitCommand)
        return;
    m_waitCommand.clear();
    if (m_ending == Ending::Soft) {
        restoreSpeeds(); // the outputs on_stop asked for
        return;
    }
    if (m_ending != Ending::None)
        return;
    if (!ok) {
        m_waitMotion.clear();
        end(SequenceResult::Outcome::DeviceError,
            tr("the controller did not acknowledge %1: the run ended").arg(key));
        return;
    }
    if (!m_step || !m_waitMotion.isEmpty())
        return; // a homing: its verdict follows
    QList<int> outputs;
    if (m_step->kind == SequenceStep::Kind::Output)
        outputs << m_step->number;
    else
        for (int n = 1; m_session->map().find(outputKey(n)); ++n)
            outputs << n;
    verifyOutputs(outputs, m_step->on);
}

void SequenceRunner::verifyOutputs(const QList<int> &outputs, bool on)
{
    QList<const Parameter *> params;
    for (int n : outputs)
        params << m_session->map().find(outputKey(n));
    m_session->parameters()->read(
        params,
        [self = QPointer<SequenceRunner>(this), outputs, on](const ReadOutcome &r) {
            if (!self || !self->m_running || self->m_ending != Ending::None)
                return;
            if (!r.ok) {
                self->end(SequenceResult::Outcome::DeviceError,
                          tr("the outputs could not be read back (%1)")
                              .arg(r.errors.join(QLatin1String("; "))));
                return;
            }
            self->m_session->parameters()->store()->setDeviceValues(r.values);
            for (int n : outputs) {
                if ((r.values.value(outputKey(n)) != 0) != on) {
                    self->end(SequenceResult::Outcome::DeviceError,
                              (on ? tr("output %1 still reads OFF after its command")
                                  : tr("output %1 still reads ON after its command"))
                                  .arg(n));
                    return;
                }
                if (on)
                    self->m_outputsOn.insert(n);
                else
                    self->m_outputsOn.remove(n);
            }
            self->stepDone();
        },
        Priority::Command);
}

void SequenceRunner::onMotion(const MotionOutcome &outcome)
{
    if (!m_running || m_waitMotion.isEmpty() || outcome.start.command != m_waitMotion)
        return;
    m_waitMotion.clear();
    if (m_ending == Ending::Soft) {
        afterStopped();
        return;
    }
    if (m_ending != Ending::None)
        return;
    if (outcome.ok()) {
        stepDone();
        return;
    }
    motionFailed(&outcome, m_session->motion()->text(outcome));
}

void SequenceRunner::onMoved(const QList<StepMoveResult> &results)
{
    if (!m_running)
        return;
    m_movesRestored = std::all_of(results.begin(), results.end(),
                                  [](const StepMoveResult &r) { return r.restored; });
    if (m_ending == Ending::Soft) {
        afterStopped();
        return;
    }
    if (m_ending != Ending::None)
        return;
    for (const StepMoveResult &r : results) {
        if (r.arrived)
            continue;
        if (r.outcome) {
            const MotionOutcome outcome = *r.outcome;
            motionFailed(&outcome, r.text);
        } else {
            end(SequenceResult::Outcome::DeviceError, r.text);
        }
        return;
    }
    stepDone();
}

void SequenceRunner::motionFailed(const MotionOutcome *outcome, const QString &text)
{
    using Outcome = SequenceResult::Outcome;
    switch (outcome->cause) {
    case MotionCause::EmergencyStop:
        end(Outcome::EmergencyStop, text, true);
        return;
    case MotionCause::LinkLost:
        end(Outcome::LinkLost, text, true);
        return;
    case MotionCause::Restarted:
    case MotionCause::Silent:
        end(Outcome::Restarted, text, true, true);
        return;
    case MotionCause::Stop:
        end(Outcome::Stopped, text);
        return;
    case MotionCause::None:
        break;
    }
    if (outcome->causeWord() == QLatin1String("limit")) {
        end(Outcome::Limit, text);
        return;
    }
    if (m_outputsOn.isEmpty()) {
        end(Outcome::Stopped, text);
        return;
    }
    // Nothing this session sent stopped it: an E-STOP from elsewhere also switches the outputs
    // off, which the controller shows.
    checkOutputs([this, text](bool allOn) {
        if (allOn)
            end(SequenceResult::Outcome::Stopped, text);
        else
            end(SequenceResult::Outcome::EmergencyStop,
                tr("%1; the outputs the run had switched on read OFF: an E-STOP (or all "
                   "outputs off) from elsewhere")
                    .arg(text),
                true, true);
    });
}

void SequenceRunner::checkOutputs(std::function<void(bool allOn)> done)
{
    if (m_checkingOutputs)
        return;
    m_checkingOutputs = true;
    QList<const Parameter *> params;
    const QList<int> outputs = m_outputsOn.values();
    for (int n : outputs)
        params << m_session->map().find(outputKey(n));
    m_session->parameters()->read(
        params,
        [self = QPointer<SequenceRunner>(this), outputs, done](const ReadOutcome &r) {
            if (!self)
                return;
            self->m_checkingOutputs = false;
            if (!self->m_running || self->m_ending == Ending::AtOnce)
                return;
            bool allOn = true;
            if (r.ok) {
                self->m_session->parameters()->store()->setDeviceValues(r.values);
                for (int n : outputs)
                    allOn = allOn && r.values.value(outputKey(n)) != 0;
            }
            done(allOn);
        },
        Priority::Command);
}

void SequenceRunner::onStatusCycle(bool ok)
{
    if (!m_running || m_preparing || m_ending != Ending::None || !ok)
        return;
    const ParameterStore *store = m_session->parameters()->store();
    if (!m_waitInputKey.isEmpty()) {
        if (const auto v = store->deviceValue(m_waitInputKey); v && (*v != 0) == m_waitInputOn) {
            m_waitInputKey.clear();
            m_timer.stop();
            stepDone();
            return;
        }
    }
    // Between moves: an output the run switched on reading OFF is an E-STOP's sign.
    if (m_move->isBusy() || !m_waitMotion.isEmpty() || !m_waitCommand.isEmpty())
        return;
    for (int n : std::as_const(m_outputsOn)) {
        if (store->deviceValue(outputKey(n)).value_or(1) == 0) {
            checkOutputs([this](bool allOn) {
                if (!allOn && m_ending == Ending::None)
                    end(SequenceResult::Outcome::EmergencyStop,
                        tr("the outputs the run had switched on read OFF: an E-STOP (or all "
                           "outputs off) from elsewhere"),
                        true, true);
            });
            return;
        }
    }
}

} // namespace stepcom
