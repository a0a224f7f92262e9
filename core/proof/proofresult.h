#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace stepcom {

// How a proof of an axis ended, the lost-step test's and the others'.
enum class ProofOutcome {
    Done,          // it ran to the end (the verdict says what it found)
    Refused,       // it did not start: nothing moved
    Stopped,       // the user stopped it
    EmergencyStop, // an E-STOP ended it at once
    LinkLost,
    Restarted,
    DeviceError, // a read, a write or a move failed
};
// done, refused, stopped, estop, link_lost, restarted, device_error
QString proofOutcomeWord(ProofOutcome outcome);
// A figure of a proof's JSON: rounded to `decimals`, null when not measured, never "-0".
QJsonValue proofJsonValue(std::optional<double> value, int decimals = 3);
// Two sentences of a proof's message, one after the other as the language writes them; either
// may be empty.
QString proofSentences(const QString &first, const QString &second);

// What the lost-step test found: the count against the home switch before and after moves at
// the test speed, in the axis's distance units (mm on a lead screw).
struct LostStepResult
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::LostStepResult)
public:
    enum class Verdict { Kept, Lost, Unknown };

    int motor = 1;
    int cycles = 0;
    double distance = 0;
    qint64 speedRpm = 0;
    qint64 accel = 0; // the acceleration register the test moves ran at
    // Signed: the carriage behind (−) or ahead (+) of the count after the moves out at the test
    // speed (back slowly), and after the moves back at it (out slowly).
    std::optional<double> lostOut;
    std::optional<double> lostBack;
    double resolution = 0;
    std::optional<double> repeatability; // of the switch, from the references at the start
    double chunk = 0;                    // 4 full steps
    Verdict verdict = Verdict::Unknown;
    ProofOutcome outcome = ProofOutcome::Refused;
    bool restored = false;
    bool simulator = false;             // the device was StepCom's simulator
    std::optional<double> endReference; // where the switch was found last (the count)
    QString text;

    // The worse of the two halves (0 when neither was measured).
    double lost() const;
    // In full steps.
    double lostSteps() const;
    // kept, lost, unknown
    QString verdictWord() const;
    QString verdictText() const;
    QJsonObject toJson() const;
    // A lost-step result worth its name: the test ran to the end with a verdict.
    bool ok() const { return outcome == ProofOutcome::Done && verdict == Verdict::Kept; }
};

} // namespace stepcom
