#pragma once

#include "commissioning/checkliststep.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QList>

namespace stepcom {

class RegisterMap;

// The commissioning checklist of one machine: per motor direction, travel calibration, the
// positive and negative limit and home inputs, homing; then the machine's homing order,
// interpolation test and save to flash with read-back. Each step is pending until a result is
// recorded; recording again repeats it (every attempt is kept, the latest counts). A value
// class: the checklist page records, then saves it with ChecklistFile beside the profile, so an
// interrupted checklist resumes at nextPending().
class Checklist
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::Checklist)
public:
    static constexpr int MaxAttempts = 20; // per step; older attempts are dropped
    static constexpr int MaxMeasurements = 24;
    static constexpr int MaxNoteChars = 2000;
    static constexpr int MaxValueChars = 200;

    enum class Verdict {
        NotStarted,      // nothing recorded
        InProgress,      // some steps not run, none failed
        Failed,          // at least one step's latest result is a failure
        PassedWithSkips, // every step run, none failed, some skipped
        Passed,          // every step passed
    };

    Checklist() = default;
    // Every step for `map`'s motors (its "motor" block count), all pending.
    static Checklist forMap(const RegisterMap &map);
    // "motor2.limit_negative", "machine.interpolation".
    static QString stepId(ChecklistStep::Kind kind, int motor = 0);

    QString mapIdentity() const { return m_mapIdentity; }
    int motorCount() const { return m_motors; }
    QString machine;             // the machine's name (the profile's, usually)
    QString settingsFingerprint; // of the settings the checklist last ran against (optional)

    const QList<ChecklistStep> &steps() const { return m_steps; }
    const ChecklistStep *step(const QString &id) const;
    // The first step without a result, where a resumed checklist goes on; nullptr when none.
    const ChecklistStep *nextPending() const;

    // Records one attempt of a step (Passed, Failed or Skipped) at `time` (UTC). Empty on
    // success; otherwise why not, and nothing changes: an unknown step, Pending as a result, a
    // note or value too long, too many or bad measurements.
    QString record(const QString &id, StepResult result,
                   const QList<ChecklistMeasurement> &measurements = {},
                   const QString &note = QString(),
                   const QDateTime &time = QDateTime::currentDateTimeUtc());
    // Used by the file reader: the attempts as stored, checked the same way.
    QString restore(const QString &id, const QList<ChecklistAttempt> &attempts);

    int count(StepResult result) const;
    Verdict verdict() const;
    // "7 of 15 steps passed, 1 failed, 2 skipped, 5 not run", translated.
    QString summary() const;
    static QString verdictText(Verdict verdict);
    // The time of the last attempt of any step (invalid when nothing was recorded).
    QDateTime lastRecorded() const;

    // A measurement's key: 1-40 characters of a-z, 0-9, '_' and '.'.
    static bool validKey(const QString &key);

    bool operator==(const Checklist &o) const = default;

private:
    QString checkAttempt(const ChecklistStep &step, const ChecklistAttempt &a) const;

    QString m_mapIdentity;
    int m_motors = 0;
    QList<ChecklistStep> m_steps;
};

} // namespace stepcom
