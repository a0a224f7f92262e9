#pragma once

#include <QCoreApplication>
#include <QList>
#include <QMap>
#include <QString>

namespace stepcom {

// One step of a machine cycle (a .stepseq file, docs/sequence.md), as parsed: what it does and
// where it stands in the file ("steps[1].steps[0]"), so every message can name it.
struct SequenceStep
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::SequenceStep)
public:
    enum class Kind {
        Home,      // homeMotors, or the controller's homing order (homeInOrder)
        MoveTo,    // axes: absolute positions (from `point` when it names one)
        MoveBy,    // axes: relative distances
        WaitInput, // number, on, timeoutMs
        Output,    // number, on (the controller switches output 1 alone)
        Outputs,   // on: all on / all off
        Dwell,     // dwellMs
        Repeat,    // count × steps
        Speed,     // axes: rpm for the moves after it
    };

    Kind kind = Kind::Dwell;
    QString path;
    bool homeInOrder = false;
    QList<int> homeMotors;
    QString point;          // move_to by name; empty for an inline position
    QMap<int, double> axes; // by motor: mm (moves) or rpm (speed)
    int number = 0;
    bool on = false;
    int timeoutMs = 0; // 0: waits until the run is stopped
    int dwellMs = 0;
    int count = 1;
    QList<SequenceStep> steps;

    // "move to load (motor 1 → 30.00 mm)", in the installed language.
    QString describe() const;
    // "home", "move_to", ... : the file's word for the kind.
    static QString kindWord(Kind kind);
};

} // namespace stepcom
