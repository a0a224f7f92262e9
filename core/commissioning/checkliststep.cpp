#include "commissioning/checkliststep.h"

#include <QHash>

namespace stepcom {

QString ChecklistStep::kindWord(Kind kind)
{
    switch (kind) {
    case Kind::Direction:
        return QStringLiteral("direction");
    case Kind::Calibration:
        return QStringLiteral("calibration");
    case Kind::LimitPositive:
        return QStringLiteral("limit_positive");
    case Kind::LimitNegative:
        return QStringLiteral("limit_negative");
    case Kind::HomeInput:
        return QStringLiteral("home_input");
    case Kind::Homing:
        return QStringLiteral("homing");
    case Kind::KeepsSteps:
        return QStringLiteral("keeps_steps");
    case Kind::Backlash:
        return QStringLiteral("backlash");
    case Kind::HomingOrder:
        return QStringLiteral("homing_order");
    case Kind::Interpolation:
        return QStringLiteral("interpolation");
    case Kind::RunIn:
        return QStringLiteral("run_in");
    case Kind::SaveToFlash:
        return QStringLiteral("save_to_flash");
    }
    return {};
}

bool ChecklistStep::isMotorStep(Kind kind)
{
    return kind != Kind::HomingOrder && kind != Kind::Interpolation && kind != Kind::RunIn &&
           kind != Kind::SaveToFlash;
}

QString ChecklistStep::resultWord(StepResult result)
{
    switch (result) {
    case StepResult::Pending:
        return QStringLiteral("pending");
    case StepResult::Passed:
        return QStringLiteral("passed");
    case StepResult::Failed:
        return QStringLiteral("failed");
    case StepResult::Skipped:
        return QStringLiteral("skipped");
    }
    return {};
}

QString ChecklistStep::resultLabel(StepResult result)
{
    switch (result) {
    case StepResult::Pending:
        return tr("Not run");
    case StepResult::Passed:
        return tr("Passed");
    case StepResult::Failed:
        return tr("Failed");
    case StepResult::Skipped:
        return tr("Skipped");
    }
    return {};
}

QString ChecklistStep::title() const
{
    QString what;
    switch (kind) {
    case Kind::Direction:
        what = tr("direction");
        break;
    case Kind::Calibration:
        what = tr("travel calibration");
        break;
    case Kind::LimitPositive:
        what = tr("positive limit input");
        break;
    case Kind::LimitNegative:
        what = tr("negative limit input");
        break;
    case Kind::HomeInput:
        what = tr("home input");
        break;
    case Kind::Homing:
        what = tr("homing");
        break;
    case Kind::KeepsSteps:
        what = tr("keeps its steps");
        break;
    case Kind::Backlash:
        what = tr("backlash");
        break;
    case Kind::HomingOrder:
        return tr("Machine: homing order");
    case Kind::Interpolation:
        return tr("Machine: interpolation test");
    case Kind::RunIn:
        return tr("Machine: run-in of its cycle");
    case Kind::SaveToFlash:
        return tr("Machine: save to flash and read back");
    }
    return tr("Motor %1: %2").arg(motor).arg(what);
}

QString ChecklistStep::instruction() const
{
    switch (kind) {
    case Kind::Direction:
        return tr("Move motor %1 a small step forward. Did the axis move toward + ? No offers to "
                  "flip its direction register.")
            .arg(motor);
    case Kind::Calibration:
        return tr("Move motor %1 by a distance you choose, measure what the axis really moved "
                  "and type it in: StepCom proposes the corrected pitch (pitch × measured ÷ "
                  "commanded).")
            .arg(motor);
    case Kind::LimitPositive:
        return tr("Press the positive limit switch of motor %1 by hand: StepCom watches the "
                  "inputs and compares the one that changed with the configuration.")
            .arg(motor);
    case Kind::LimitNegative:
        return tr("Press the negative limit switch of motor %1 by hand: StepCom watches the "
                  "inputs and compares the one that changed with the configuration.")
            .arg(motor);
    case Kind::HomeInput:
        return tr("Press the home switch of motor %1 by hand (often the negative limit's "
                  "switch): StepCom compares the input that changed with the configuration.")
            .arg(motor);
    case Kind::Homing:
        return tr("Home motor %1 and check that it ended on its home switch, referenced.")
            .arg(motor);
    case Kind::KeepsSteps:
        return tr("Prove that motor %1 keeps its steps at its own speed and acceleration: the "
                  "count against the home switch before and after moves out fast and back "
                  "slowly, and the other way. Then find the margin: the test at each speed on "
                  "the way up, to the first loss.")
            .arg(motor);
    case Kind::Backlash:
        return tr("Put a dial gauge on motor %1's carriage. StepCom approaches a point from one "
                  "side, then moves on and back; type what the gauge shows after each move.")
            .arg(motor);
    case Kind::HomingOrder:
        return tr("Home the machine in the configured order and check that every axis in the "
                  "order ended referenced.");
    case Kind::Interpolation:
        return tr("Run the configured arc or line and check that the axes ended at its end "
                  "point.");
    case Kind::RunIn:
        return tr("Run the machine's cycle on the Sequence page for a number of cycles, with the "
                  "lost-step check at the end. The run-in's result is recorded here: cycles, "
                  "cycle time and whether every axis kept its steps.");
    case Kind::SaveToFlash:
        return tr("Save the parameters to flash, read them back and compare them with what "
                  "was written.");
    }
    return {};
}

QString ChecklistStep::measurementLabel(const QString &key)
{
    static const QHash<QString, const char *> labels{
        {QStringLiteral("commanded"), QT_TR_NOOP("Commanded distance")},
        {QStringLiteral("measured"), QT_TR_NOOP("Measured distance")},
        {QStringLiteral("pitch_before"), QT_TR_NOOP("Pitch before")},
        {QStringLiteral("pitch_after"), QT_TR_NOOP("Pitch after")},
        {QStringLiteral("moved_toward_plus"), QT_TR_NOOP("Moved toward +")},
        {QStringLiteral("direction_before"), QT_TR_NOOP("Direction before")},
        {QStringLiteral("direction_after"), QT_TR_NOOP("Direction after")},
        {QStringLiteral("input_configured"), QT_TR_NOOP("Input configured")},
        {QStringLiteral("input_answered"), QT_TR_NOOP("Input that answered")},
        {QStringLiteral("fix"), QT_TR_NOOP("Fix written")},
        {QStringLiteral("position_end"), QT_TR_NOOP("End position")},
        {QStringLiteral("expected_end"), QT_TR_NOOP("Expected end")},
        {QStringLiteral("order"), QT_TR_NOOP("Homing order")},
        {QStringLiteral("readback"), QT_TR_NOOP("Read back")},
        {QStringLiteral("verdict"), QT_TR_NOOP("Verdict")},
        {QStringLiteral("speed_rpm"), QT_TR_NOOP("Tested at speed")},
        {QStringLiteral("accel"), QT_TR_NOOP("Tested at acceleration")},
        {QStringLiteral("cycles"), QT_TR_NOOP("Cycles")},
        {QStringLiteral("distance"), QT_TR_NOOP("Distance of each move")},
        {QStringLiteral("lost_out"), QT_TR_NOOP("Lost after the moves out")},
        {QStringLiteral("lost_back"), QT_TR_NOOP("Lost after the moves back")},
        {QStringLiteral("repeatability"), QT_TR_NOOP("Switch repeatability")},
        {QStringLiteral("kept_rpm"), QT_TR_NOOP("Highest speed kept")},
        {QStringLiteral("stall_rpm"), QT_TR_NOOP("First speed lost")},
        {QStringLiteral("recommended_rpm"), QT_TR_NOOP("Recommended speed")},
        {QStringLiteral("kept_accel"), QT_TR_NOOP("Highest acceleration kept")},
        {QStringLiteral("stall_accel"), QT_TR_NOOP("First acceleration lost")},
        {QStringLiteral("recommended_accel"), QT_TR_NOOP("Recommended acceleration")},
        {QStringLiteral("backlash"), QT_TR_NOOP("Backlash")},
        {QStringLiteral("spread"), QT_TR_NOOP("Spread")},
        {QStringLiteral("readings"), QT_TR_NOOP("Gauge readings")},
        {QStringLiteral("simulator"), QT_TR_NOOP("Taken on")},
        {QStringLiteral("sequence"), QT_TR_NOOP("Sequence")},
        {QStringLiteral("outcome"), QT_TR_NOOP("Outcome")},
        {QStringLiteral("cycles_done"), QT_TR_NOOP("Cycles done")},
        {QStringLiteral("cycle_min"), QT_TR_NOOP("Shortest cycle")},
        {QStringLiteral("cycle_median"), QT_TR_NOOP("Median cycle")},
        {QStringLiteral("cycle_max"), QT_TR_NOOP("Longest cycle")},
        {QStringLiteral("check_steps"), QT_TR_NOOP("Lost-step check")},
    };
    const auto it = labels.constFind(key);
    return it == labels.cend() ? key : tr(*it);
}

} // namespace stepcom
