#pragma once

#include "proof/proofresult.h"

#include <QList>
#include <QObject>
#include <QPointer>

namespace stepcom {

class DeviceSession;
class ProofDrive;
struct StepMoveResult;

// What the dial gauge showed on the axis's reversals.
struct BacklashResult
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::BacklashResult)
public:
    int motor = 1;
    int cycles = 0;
    double distance = 0;
    QList<double> readings;         // the gauge after the approach and after each move
    std::optional<double> backlash; // the mean lost motion of the reversals
    std::optional<double> spread;   // the largest reversal's loss minus the smallest
    double resolution = 0;
    ProofOutcome outcome = ProofOutcome::Refused;
    bool restored = false;
    bool simulator = false;
    QString text;

    // Backlash the count cannot see: position from one side.
    bool approachFromOneSide() const { return backlash && *backlash > resolution + 1e-9; }
    // The lost motion of each reversal: D − |Δ reading| from the second move on (the first
    // move goes on in the approach's direction).
    QList<double> losses() const;
    // {"motor", "distance_mm", "cycles", "backlash_mm", "readings", "spread_mm",
    // "approach_from_one_side", "outcome", "restored", ...}
    QJsonObject toJson() const;
};

// The backlash test of one axis with a dial gauge on the carriage (docs/proving.md): a switch
// cannot tell backlash from its own hysteresis, a gauge can. It approaches a point from one
// side (back by D, on by D), then moves on by D and back by D `cycles` times, asking for the
// gauge's reading after the approach and after every move. The moves run at the start
// frequency's speed (or the motor's own, the lower), where nothing stalls; the speed register is
// put back and verified afterwards.
class BacklashTest : public QObject
{
    Q_OBJECT
public:
    struct Options
    {
        int motor = 1;
        double distance = 1; // distance units, each move
        int cycles = 3;
        bool askFirst = false;
    };

    explicit BacklashTest(DeviceSession *session, QObject *parent = nullptr);
    ~BacklashTest() override;

    bool start(const Options &options);
    void proceed();
    // The gauge's reading asked for by readingWanted().
    void giveReading(double value);
    // Stops the motor (or the waiting for a reading) and ends the test: "stopped".
    void stop();
    bool isRunning() const { return m_running; }
    // How many readings the test takes: after the approach and after each move.
    int readingsWanted() const { return 1 + 2 * m_options.cycles; }

Q_SIGNALS:
    void ready(const QString &plan);
    void progress(const QString &text);
    // Read the gauge now: the `index`-th reading (0 after the approach), `text` says where.
    void readingWanted(int index, const QString &text);
    void finished(const stepcom::BacklashResult &result);

private:
    void onSetup(const QString &error);
    void move(double units, const QString &where);
    void onMoved(const StepMoveResult &r, const QString &where);
    void nextMove();
    void end(ProofOutcome outcome, const QString &text);

    QPointer<DeviceSession> m_session;
    ProofDrive *m_drive = nullptr;
    Options m_options;
    BacklashResult m_result;
    qint64 m_slowRpm = 1;
    int m_move = 0; // moves after the approach
    bool m_running = false;
    bool m_waiting = false; // for proceed()
    bool m_wantReading = false;
    bool m_ending = false;
};

} // namespace stepcom
