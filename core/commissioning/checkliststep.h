#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QList>
#include <QString>

namespace stepcom {

// One value a step measured or decided, as text (numbers locale-neutral, "99.20"), with its
// unit. Keys are the ones ChecklistStep::measurementLabel knows, or any [a-z0-9_.] key.
struct ChecklistMeasurement
{
    QString key;
    QString value;
    QString unit;
    bool operator==(const ChecklistMeasurement &o) const = default;
};

enum class StepResult { Pending, Passed, Failed, Skipped };

// One run of a step: a step can be repeated; every run is kept, the latest counts.
struct ChecklistAttempt
{
    int number = 1; // 1, 2, … in the order they were run (older ones may have been dropped)
    StepResult result = StepResult::Pending;
    QDateTime time; // UTC
    QString note;
    QList<ChecklistMeasurement> measurements;
    bool operator==(const ChecklistAttempt &o) const = default;
};

// One step of the commissioning checklist: per motor (direction, travel calibration, the limit
// and home inputs, homing, keeping its steps, backlash) or for the machine (homing order,
// interpolation, the run-in of its cycle, save to flash).
struct ChecklistStep
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ChecklistStep)
public:
    enum class Kind {
        Direction,
        Calibration,
        LimitPositive,
        LimitNegative,
        HomeInput,
        Homing,
        KeepsSteps, // the lost-step test and the speed margin (core/proof)
        Backlash,   // the backlash test with a dial gauge
        HomingOrder,
        Interpolation,
        RunIn, // the machine's cycle run N times, then the lost-step check (Sequence page)
        SaveToFlash,
    };

    QString id; // "motor1.direction", "machine.save_to_flash"
    Kind kind = Kind::Direction;
    int motor = 0; // 1.. for a motor's step, 0 for the machine's
    QList<ChecklistAttempt> attempts;

    StepResult result() const
    {
        return attempts.isEmpty() ? StepResult::Pending : attempts.last().result;
    }
    const ChecklistAttempt *latest() const
    {
        return attempts.isEmpty() ? nullptr : &attempts.last();
    }

    // "Motor 1: direction", translated.
    QString title() const;
    // What the technician does in this step, translated (the checklist page shows it).
    QString instruction() const;

    // "direction", "calibration", … : the id's part after the motor or "machine.".
    static QString kindWord(Kind kind);
    static bool isMotorStep(Kind kind);
    // "passed", "failed", "skipped", "pending": the file's words.
    static QString resultWord(StepResult result);
    // Translated: "Passed", "Failed", "Skipped", "Not run".
    static QString resultLabel(StepResult result);
    // The label of a measurement key ("commanded" → "Commanded distance"), or the key itself.
    static QString measurementLabel(const QString &key);

    bool operator==(const ChecklistStep &o) const = default;
};

} // namespace stepcom
