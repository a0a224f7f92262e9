#pragma once

#include "motion/motionoutcome.h"
#include "sequence/sequence.h"
#include "sequence/sequenceresult.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>

#include <functional>

namespace stepcom {

class DeviceSession;
class SequenceMove;
struct ReadOutcome;
struct StepMoveResult;

// Runs a machine cycle (a Sequence) on the session's device in view, step after step, for a
// number of cycles (docs/sequence.md). Before the first step it reads the positions, the homing
// order and the speeds, and checks the whole run again (SequenceCheck) with them: refused, it
// moves nothing. Moves go through SequenceMove (StepMove per axis), homing through the session's
// command and MotionSupervisor's verdict, outputs are read back after their command, a wait
// reads the input from the status poll the runner keeps running. A stop, a limit or a timeout
// ends the run with the motors stopped, the outputs as on_stop says and the user's speeds put
// back; an E-STOP, a link loss or a restart end it at once, nothing sent after them but a stop.
// The window's Sequence page and `stepcomctl run` drive it.
class SequenceRunner : public QObject
{
    Q_OBJECT
public:
    explicit SequenceRunner(DeviceSession *session, QObject *parent = nullptr);
    ~SequenceRunner() override;

    // What the file cannot do with what the session knows now (references, StepCom's travel
    // limits), without a frame sent; empty when it may start.
    QStringList check(const Sequence &sequence, int cycles) const;
    // Reads, checks again and runs `cycles` times; `finished` follows once. False (and nothing
    // sent) when it cannot start: not connected, already running.
    bool start(const Sequence &sequence, int cycles);
    // Ends the run (Interrupted): motors stopped at once, outputs as on_stop says, speeds back.
    void stop();

    // Pause after each step until resume() or singleStep().
    void setPauseAfterStep(bool pause) { m_pauseAfterStep = pause; }
    bool pauseAfterStep() const { return m_pauseAfterStep; }
    // While paused: run the next step, then pause again.
    void singleStep();
    // While paused: go on (pausing again after the next step only with pauseAfterStep).
    void resume();

    bool isRunning() const { return m_running; }
    bool isPaused() const { return m_paused; }
    int cycle() const { return m_cycle; } // 1.. while running
    QString currentStep() const;          // the path of the step running or next

Q_SIGNALS:
    // The reads and the check are done: the first step starts now.
    void started(int cycles);
    void cycleStarted(int cycle);
    void cycleFinished(int cycle, double seconds);
    // `path`: the step in the file ("steps[1].steps[0]"); `text`: what it does, in words.
    void stepStarted(int cycle, const QString &path, const QString &text);
    void stepFinished(int cycle, const QString &path, const QString &text);
    // Paused before the step at `nextPath`.
    void paused(const QString &nextPath);
    void finished(const stepcom::SequenceResult &result);

private:
    struct Frame
    {
        const QList<SequenceStep> *steps = nullptr;
        int index = 0;
        int iteration = 0;
        int count = 1;
    };
    enum class Ending { None, Soft, AtOnce };

    // -- the run (sequencerunner.cpp) --
    void onPrepared(const ReadOutcome &read);
    void next();
    // Advances `stack` to the next step to run (a repeat's steps inside it); null at the end.
    // `announce`: the run's own stack, whose cycles ending are said and timed.
    const SequenceStep *nextStep(QList<Frame> &stack, bool announce);
    void stepDone();
    // Ends the run: Soft stops the motors, sets the outputs as on_stop says and puts the speeds
    // back first; AtOnce sends at most a stop (`sendStop`) and ends.
    void end(SequenceResult::Outcome outcome, const QString &text, bool atOnce = false,
             bool sendStop = false);
    void afterStopped();
    void restoreSpeeds();
    void complete();
    void sendStops();
    // -- the steps (sequencesteps.cpp) --
    void execute(const SequenceStep &step);
    void home(const SequenceStep &step);
    void move(const SequenceStep &step);
    void waitInput(const SequenceStep &step);
    void switchOutputs(const SequenceStep &step);
    void setSpeed(const SequenceStep &step);
    void onCommand(const QString &key, bool ok);
    void onMotion(const MotionOutcome &outcome);
    void onMoved(const QList<StepMoveResult> &results);
    void onStatusCycle(bool ok);
    // A motion ended without arriving: what stopped it, the outputs read for an E-STOP's sign.
    void motionFailed(const MotionOutcome *outcome, const QString &text);
    // The outputs the run switched on read OFF now: an E-STOP (or an all-off) from elsewhere.
    void checkOutputs(std::function<void(bool allOn)> done);
    void verifyOutputs(const QList<int> &outputs, bool on);

    QPointer<DeviceSession> m_session;
    SequenceMove *m_move;
    Sequence m_sequence;
    int m_cycles = 1;
    QList<Frame> m_stack;
    const SequenceStep *m_step = nullptr;
    QString m_stepPath;
    bool m_running = false;
    bool m_preparing = false;
    bool m_paused = false;
    bool m_pauseAfterStep = false;
    bool m_singleStep = false;
    Ending m_ending = Ending::None;
    bool m_startedPoll = false;
    QString m_waitCommand;  // the coil whose answer the step waits for
    QString m_waitMotion;   // the motion command whose verdict it waits for
    QString m_waitInputKey; // wait_input: the input's key
    bool m_waitInputOn = true;
    bool m_checkingOutputs = false;
    bool m_speedsRestored = true;
    QTimer m_timer;                 // dwell, wait_input's timeout
    QTimer m_stopGrace;             // a stopped motion gets this long to be judged
    QSet<int> m_outputsOn;          // what the run switched on (and verified)
    QHash<int, qint64> m_userSpeed; // by motor, as read before the run
    QHash<int, qint64> m_speedSet;  // what a speed step wrote
    bool m_movesRestored = true;
    int m_cycle = 0;
    QElapsedTimer m_clock;
    QElapsedTimer m_cycleClock;
    SequenceResult m_result;
    QList<QMetaObject::Connection> m_connections;
};

} // namespace stepcom
