#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <deque>
#include <functional>
#include <vector>

namespace stepcom {

// A queue of steps run one after the other from the event loop, without nested event loops:
// "do this", "wait until that holds", "wait so long". A step may plan further steps; they run
// right after it, before the rest of the queue (so a step can expand into a sub-script).
class Script : public QObject
{
    Q_OBJECT
public:
    using Action = std::function<void()>;
    using Condition = std::function<bool()>;

    explicit Script(QObject *parent = nullptr);

    void then(Action action);
    // Continue once `condition` holds; fail the whole script naming `what` after `timeoutMs`.
    void waitFor(const QString &what, Condition condition, int timeoutMs = 15000);
    void sleep(int ms);

    void start();
    // Stop with an error: the remaining steps are dropped, finished(false, why) follows.
    void fail(const QString &why);
    bool isFailed() const { return m_failed; }

Q_SIGNALS:
    void finished(bool ok, const QString &error);

private:
    struct Step
    {
        enum class Kind { Run, WaitFor, Sleep } kind = Kind::Run;
        Action action;
        Condition condition;
        QString what;
        int ms = 0;
    };

    void add(Step step);
    void scheduleNext(int ms = 0);
    void runNext();
    void poll();

    std::deque<Step> m_queue;
    std::vector<Step> m_planned; // steps added by the step now running
    bool m_inStep = false;
    bool m_failed = false;
    bool m_done = false;
    Step m_waiting;
    QElapsedTimer m_waitClock;
    QTimer m_poll;
};

} // namespace stepcom
