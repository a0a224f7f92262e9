#pragma once

#include "sequence/sequence.h"

#include <QCoreApplication>

namespace stepcom {

class RegisterMap;

// What a run of a sequence will do, said before anyone is asked to start it: the points, the
// file's limits, what a stop does to the outputs, the cycles and the lost-step check after
// them. `stepcomctl run` prints it and the Sequence page shows it in its question, so both say
// the same.
class SequencePlan
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::SequencePlan)
public:
    // The motors a move of the sequence drives: the axes the lost-step check proves afterwards.
    static QList<int> movedMotors(const Sequence &sequence);
    // One line each, ending in a newline.
    static QString describe(const Sequence &sequence, const RegisterMap &map, int cycles,
                            bool checkSteps);
    // "motor1 30.00 mm, motor2 0.00 mm".
    static QString axesText(const RegisterMap &map, const QMap<int, double> &axes);
};

} // namespace stepcom
