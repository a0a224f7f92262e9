#pragma once

#include "proof/proofresult.h"

#include <QList>
#include <QObject>
#include <QPointer>

#include <optional>

namespace stepcom {

class AxisProof;
class DeviceSession;
class ProofDrive;

// One speed (or acceleration) of a margin search and what the lost-step test found there.
struct MarginStep
{
    qint64 value = 0;
    std::optional<double> lost;
    LostStepResult::Verdict verdict = LostStepResult::Verdict::Unknown;
};

// Where the axis stops keeping its steps, and the value to run at.
struct MarginResult
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::MarginResult)
public:
    // The share of the highest value that kept its steps practitioners run at (70-80 %).
    static constexpr double kRecommendedShare = 0.75;

    int motor = 1;
    bool accel = false;          // the acceleration register was searched, at speedRpm
    qint64 speedRpm = 0;         // the speed the acceleration was searched at
    std::optional<qint64> kept;  // the highest value that kept its steps
    std::optional<qint64> stall; // the first that lost them; unset: none did
    std::optional<qint64> recommended;
    QList<MarginStep> steps;
    ProofOutcome outcome = ProofOutcome::Refused;
    bool restored = false;
    bool simulator = false;
    QString text;

    // {"motor", "kept_rpm", "stall_rpm", "recommended_rpm", "steps": [{"rpm", "lost_mm",
    // "verdict"}], ...}; with the acceleration "kept_accel" ... and "speed_rpm".
    QJsonObject toJson() const;
};

// The margin search of one axis (docs/proving.md): the lost-step test (AxisProof) at each value
// from `from` up to `to`, lowest first, since resonance can lose steps below a speed that keeps
// them; it stops at the first loss. Every value is tested on its way up, the switch referenced
// once at the start and then from where the last test found it. The recommendation is 75 % of
// the highest value kept; nothing of it is written here.
class MarginFinder : public QObject
{
    Q_OBJECT
public:
    // About this many steps between the current value and the register's top by default.
    static constexpr int kDefaultSteps = 10;

    struct Options
    {
        int motor = 1;
        bool accel = false;         // search the acceleration register at the motor's own speed
        std::optional<qint64> from; // unset: the motor's own value
        std::optional<qint64> to;   // unset: the register's top (the acceleration: 10 × from)
        std::optional<qint64> step; // unset: (to − from) / kDefaultSteps, rounded up
        int cycles = 2;
        double distance = 10;
        bool askFirst = false;
    };

    explicit MarginFinder(DeviceSession *session, QObject *parent = nullptr);
    ~MarginFinder() override;

    bool start(const Options &options);
    void proceed();
    void stop();
    bool isRunning() const { return m_running; }
    // The values a search from `from` to `to` in `step` tests: `to` always among them.
    static QList<qint64> values(qint64 from, qint64 to, qint64 step);

Q_SIGNALS:
    void ready(const QString &plan);
    void progress(const QString &text);
    void stepDone(const stepcom::MarginStep &step);
    void finished(const stepcom::MarginResult &result);

private:
    void onSetup(const QString &error);
    QString check();
    void next();
    void onTested(const LostStepResult &r);
    void end(ProofOutcome outcome, const QString &text);

    QPointer<DeviceSession> m_session;
    ProofDrive *m_drive = nullptr;
    AxisProof *m_proof = nullptr;
    Options m_options;
    MarginResult m_result;
    QList<qint64> m_values;
    int m_index = 0;
    std::optional<double> m_base;
    double m_repeatability = 0;
    bool m_running = false;
    bool m_waiting = false;
    bool m_stopped = false;
};

} // namespace stepcom
