#pragma once

#include "proof/proofresult.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

namespace stepcom {

class DeviceSession;
class ProofDrive;
class SwitchReference;
struct StepMoveResult;

// The lost-step test of one axis (docs/proving.md): the count where the home switch comes ON
// (SwitchReference) twice at the start, which measures the switch's repeatability, then two
// halves of `cycles` back-and-forth moves of `distance`: out at the test speed and back slowly,
// then out slowly and back at the test speed, each followed by a reference. A stall loses in the
// direction of the move, so moves of both directions at the test speed would hide each other's
// loss; the halves keep them apart. The slow moves and the references run at the start
// frequency's speed (or a quarter of the test speed, the lower), where nothing stalls. The
// verdict comes from the counts alone: kept within the switch's repeatability and the
// resolution, lost past it, unknown when the switch does not repeat to 4 full steps.
// The speed and acceleration registers it wrote are put back and verified, however it ends.
class AxisProof : public QObject
{
    Q_OBJECT
public:
    // Where the switch was found by a test just before, and how well it repeated: the margin
    // finder's next speed starts from there instead of referencing twice again.
    struct Baseline
    {
        double position = 0;
        double repeatability = 0;
    };
    struct Options
    {
        int motor = 1;
        int cycles = 3;
        double distance = 10;           // distance units, each move
        std::optional<qint64> speedRpm; // unset: the motor's own speed register
        std::optional<qint64> accel;    // unset: the motor's own acceleration register
        double search = 250;            // how far the first approach may go toward the switch
        bool askFirst = false;          // ready(plan) and wait for proceed()
        std::optional<Baseline> baseline;
    };
    // The clearance kept from the switch by the moves, so a loss shows at the reference rather
    // than as a move stopped on the switch.
    static constexpr double kClearance = 0.5;

    explicit AxisProof(DeviceSession *session, QObject *parent = nullptr);
    ~AxisProof() override;

    // False (nothing sent) when a test is running; else `finished` follows once.
    bool start(const Options &options);
    // After ready(): the moves begin.
    void proceed();
    // Stops the motor at once; the registers are put back and `finished` says "stopped".
    void stop();
    bool isRunning() const { return m_running; }

Q_SIGNALS:
    // The values are read and the test fits: what it will do, for the user to confirm.
    void ready(const QString &plan);
    void progress(const QString &text);
    // A half is measured: `out` the moves out at the test speed.
    void halfDone(bool out, double lost);
    void finished(const stepcom::LostStepResult &result);

private:
    void onSetup(const QString &error);
    QString check();
    QString planText() const;
    void reference(std::function<void(double)> found);
    void startHalf(bool out);
    void cycleMove();
    void onMoved(const StepMoveResult &r);
    void endHalf();
    // The verdict from what was measured; `outcome` says how it ended.
    void end(ProofOutcome outcome, const QString &text);
    void endOnHalt();

    QPointer<DeviceSession> m_session;
    ProofDrive *m_drive = nullptr;
    SwitchReference *m_reference = nullptr;
    Options m_options;
    LostStepResult m_result;
    bool m_running = false;
    bool m_waiting = false; // for proceed()
    bool m_ending = false;
    qint64 m_slowRpm = 1;
    std::optional<double> m_lastFound;
    double m_base = 0;
    bool m_out = true;
    int m_move = 0; // of the half's moves, 0 .. 2 × cycles
};

} // namespace stepcom
