#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace stepcom {

// How a run of a sequence ended (SequenceRunner::finished).
struct SequenceResult
{
    enum class Outcome {
        Done,          // every cycle ran to its end
        Timeout,       // a wait_input's input did not come in time
        Stopped,       // a move or homing ended short (a stop from elsewhere, no home input)
        EmergencyStop, // an E-STOP: this session's, or seen (the outputs went off with the axes)
        Limit,         // a limit input stopped a move
        LinkLost,
        Restarted,   // the controller restarted (or may have): a run never goes on after one
        Interrupted, // stop() (Ctrl-C, the Stop button)
        DeviceError, // a command or a write the controller did not take or verify
        Refused,     // the check before the run found problems (`problems`): nothing moved
    };

    Outcome outcome = Outcome::Done;
    int cyclesDone = 0;
    QString step;               // the step it ended at ("steps[1].steps[0]"), empty when done
    QString text;               // what happened, in the installed language
    double elapsedSeconds = 0;  // from the first step to the end
    QList<double> cycleSeconds; // each whole cycle's time, in order
    bool restored = false;      // the user's speeds and single-move values are back, verified
    QStringList problems;       // Refused: what the check found

    bool ok() const { return outcome == Outcome::Done; }
    // done, timeout, stopped, estop, limit, link-lost, restarted, interrupted, device-error,
    // refused: stable words for scripts.
    static QString word(Outcome outcome);
    QString word() const { return word(outcome); }
    // The cycle times' min, median and max (0 without a whole cycle).
    double minCycle() const;
    double medianCycle() const;
    double maxCycle() const;
};

} // namespace stepcom
