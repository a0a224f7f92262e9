#pragma once

#include "sequence/sequence.h"

#include <QCoreApplication>
#include <QHash>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;
class TravelLimits;

// Walks a sequence's positions through its steps, loops and cycles included, before anything
// moves: every move_to and move_by is checked against the file's limits and StepCom's software
// travel limits, and a move_to needs its axis referenced (homed earlier in the run, or already
// referenced for the session). A loop that leaves the axes as it found them is walked once.
class SequenceCheck
{
public:
    Q_DECLARE_TR_FUNCTIONS(stepcom::SequenceCheck)
public:
    struct Axis
    {
        bool referenced = false;
        std::optional<double> position; // axis units; not known yet: relative moves unchecked
        bool operator==(const Axis &o) const = default;
    };
    struct Start
    {
        QHash<int, Axis> axes; // by motor
        // The motors `home: "order"` homes (40177, 40178), when read; not known: every motor.
        std::optional<QList<int>> homingOrder;
    };

    // Every problem of running `sequence` `cycles` times from `start`, each naming the file and
    // the step ("FILE: steps[1].steps[0]: ..."); empty when it may run.
    static QStringList check(const Sequence &sequence, const RegisterMap &map,
                             const TravelLimits &travel, const Start &start, int cycles);
    // The motors of `start` homed by the homing order registers' raw values (0 none, 1, 2).
    static QList<int> homingOrder(qint64 first, qint64 second);
};

} // namespace stepcom
