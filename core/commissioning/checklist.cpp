#include "commissioning/checklist.h"

#include "map/registermap.h"

#include <algorithm>

namespace stepcom {

Checklist Checklist::forMap(const RegisterMap &map)
{
    using StepKind = ChecklistStep::Kind;
    Checklist c;
    c.m_mapIdentity = map.identity();
    c.m_motors = map.blockCount(QStringLiteral("motor"));
    for (int motor = 1; motor <= c.m_motors; ++motor) {
        for (StepKind k : {StepKind::Direction, StepKind::Calibration, StepKind::LimitPositive,
                           StepKind::LimitNegative, StepKind::HomeInput, StepKind::Homing,
                           StepKind::KeepsSteps, StepKind::Backlash})
            c.m_steps.append({stepId(k, motor), k, motor, {}});
    }
    for (StepKind k :
         {StepKind::HomingOrder, StepKind::Interpolation, StepKind::RunIn, StepKind::SaveToFlash})
        c.m_steps.append({stepId(k), k, 0, {}});
    return c;
}

QString Checklist::stepId(ChecklistStep::Kind kind, int motor)
{
    const QString word = ChecklistStep::kindWord(kind);
    return ChecklistStep::isMotorStep(kind) ? QStringLiteral("motor%1.%2").arg(motor).arg(word)
                                            : QStringLiteral("machine.") + word;
}

const ChecklistStep *Checklist::step(const QString &id) const
{
    const auto it = std::find_if(m_steps.cbegin(), m_steps.cend(),
                                 [&](const ChecklistStep &s) { return s.id == id; });
    return it == m_steps.cend() ? nullptr : &*it;
}

const ChecklistStep *Checklist::nextPending() const
{
    const auto it = std::find_if(m_steps.cbegin(), m_steps.cend(), [](const ChecklistStep &s) {
        return s.result() == StepResult::Pending;
    });
    return it == m_steps.cend() ? nullptr : &*it;
}

bool Checklist::validKey(const QString &key)
{
    if (key.isEmpty() || key.size() > 40)
        return false;
    return std::all_of(key.cbegin(), key.cend(), [](QChar c) {
        return (c >= QLatin1Char('a') && c <= QLatin1Char('z')) ||
               (c >= QLatin1Char('0') && c <= QLatin1Char('9')) || c == QLatin1Char('_') ||
               c == QLatin1Char('.');
    });
}

QString Checklist::checkAttempt(const ChecklistStep &step, const ChecklistAttempt &a) const
{
    if (a.result == StepResult::Pending)
        return tr("%1: a result is passed, failed or skipped, not pending").arg(step.id);
    if (!a.time.isValid())
        return tr("%1: the attempt has no valid time").arg(step.id);
    if (a.note.size() > MaxNoteChars)
        return tr("%1: the note has %2 characters (at most %3)")
            .arg(step.id)
            .arg(a.note.size())
            .arg(MaxNoteChars);
    if (a.measurements.size() > MaxMeasurements)
        return tr("%1: %2 measurements (at most %3)")
            .arg(step.id)
            .arg(a.measurements.size())
            .arg(MaxMeasurements);
    for (const ChecklistMeasurement &m : a.measurements) {
        if (!validKey(m.key))
            return tr("%1: \"%2\" is not a measurement key (1-40 of a-z, 0-9, _ and .)")
                .arg(step.id, m.key.left(60));
        if (m.value.size() > MaxValueChars || m.unit.size() > 16)
            return tr("%1: the measurement \"%2\" is too long").arg(step.id, m.key);
    }
    return {};
}

QString Checklist::record(const QString &id, StepResult result,
                          const QList<ChecklistMeasurement> &measurements, const QString &note,
                          const QDateTime &time)
{
    const auto it = std::find_if(m_steps.begin(), m_steps.end(),
                                 [&](const ChecklistStep &s) { return s.id == id; });
    if (it == m_steps.end())
        return tr("\"%1\" is not a step of this checklist").arg(id.left(60));
    ChecklistAttempt a;
    a.number = it->attempts.isEmpty() ? 1 : it->attempts.last().number + 1;
    a.result = result;
    a.time = time.toUTC();
    a.note = note;
    a.measurements = measurements;
    if (const QString why = checkAttempt(*it, a); !why.isEmpty())
        return why;
    it->attempts.append(a);
    while (it->attempts.size() > MaxAttempts)
        it->attempts.removeFirst();
    return {};
}

QString Checklist::restore(const QString &id, const QList<ChecklistAttempt> &attempts)
{
    const auto it = std::find_if(m_steps.begin(), m_steps.end(),
                                 [&](const ChecklistStep &s) { return s.id == id; });
    if (it == m_steps.end())
        return tr("\"%1\" is not a step of this checklist (%2 motor(s))")
            .arg(id.left(60))
            .arg(m_motors);
    if (attempts.size() > MaxAttempts)
        return tr("%1: %2 attempts (at most %3)").arg(id).arg(attempts.size()).arg(MaxAttempts);
    int last = 0;
    for (const ChecklistAttempt &a : attempts) {
        if (const QString why = checkAttempt(*it, a); !why.isEmpty())
            return why;
        if (a.number <= last)
            return tr("%1: the attempts must be numbered upwards (found %2 after %3)")
                .arg(id)
                .arg(a.number)
                .arg(last);
        last = a.number;
    }
    it->attempts = attempts;
    return {};
}

int Checklist::count(StepResult result) const
{
    return int(std::count_if(m_steps.cbegin(), m_steps.cend(),
                             [&](const ChecklistStep &s) { return s.result() == result; }));
}

Checklist::Verdict Checklist::verdict() const
{
    if (count(StepResult::Failed) > 0)
        return Verdict::Failed;
    const int pending = count(StepResult::Pending);
    if (pending == m_steps.size())
        return Verdict::NotStarted;
    if (pending > 0)
        return Verdict::InProgress;
    return count(StepResult::Skipped) > 0 ? Verdict::PassedWithSkips : Verdict::Passed;
}

QString Checklist::verdictText(Verdict verdict)
{
    switch (verdict) {
    case Verdict::NotStarted:
        return tr("Not started");
    case Verdict::InProgress:
        return tr("In progress: not every step was run");
    case Verdict::Failed:
        return tr("Failed: at least one step failed");
    case Verdict::PassedWithSkips:
        return tr("Passed, with skipped steps");
    case Verdict::Passed:
        return tr("Passed: every step passed");
    }
    return {};
}

QString Checklist::summary() const
{
    return tr("%1 of %2 steps passed, %3 failed, %4 skipped, %5 not run")
        .arg(count(StepResult::Passed))
        .arg(m_steps.size())
        .arg(count(StepResult::Failed))
        .arg(count(StepResult::Skipped))
        .arg(count(StepResult::Pending));
}

QDateTime Checklist::lastRecorded() const
{
    QDateTime last;
    for (const ChecklistStep &s : m_steps) {
        for (const ChecklistAttempt &a : s.attempts) {
            if (!last.isValid() || a.time > last)
                last = a.time;
        }
    }
    return last;
}

} // namespace stepcom
