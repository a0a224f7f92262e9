#pragma once

#include "motion/travellimits.h"
#include "sequence/sequencestep.h"

#include <QList>
#include <QMap>
#include <QString>

namespace stepcom {

// A machine cycle as a .stepseq file gives it (docs/sequence.md): its named points, its own
// travel limits, what a stop does to the outputs and its steps. Made by SequenceParser, checked
// by SequenceCheck, run by SequenceRunner.
struct Sequence
{
    QString fileName;                        // for messages
    QMap<QString, QMap<int, double>> points; // name → motor → position (axis units)
    TravelLimits limits;                     // the file's, besides StepCom's own
    bool outputsOffOnStop = false;           // on_stop.outputs: "all_off" (default "leave")
    QList<SequenceStep> steps;

    // Every motor a step homes, moves or sets the speed of, in order.
    QList<int> motors() const;
    // Every step, depth first (those inside a repeat after it).
    QList<const SequenceStep *> allSteps() const;
};

} // namespace stepcom
