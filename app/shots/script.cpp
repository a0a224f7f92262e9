#include "script.h"

namespace stepcom {

Script::Script(QObject *parent)
    : QObject(parent)
{
    m_poll.setInterval(20);
    connect(&m_poll, &QTimer::timeout, this, &Script::poll);
}

void Script::add(Step step)
{
    if (m_inStep)
        m_planned.push_back(std::move(step));
    else
        m_queue.push_back(std::move(step));
}

void Script::then(Action action)
{
    Step s;
    s.action = std::move(action);
    add(std::move(s));
}

void Script::waitFor(const QString &what, Condition condition, int timeoutMs)
{
    Step s;
    s.kind = Step::Kind::WaitFor;
    s.condition = std::move(condition);
    s.what = what;
    s.ms = timeoutMs;
    add(std::move(s));
}

void Script::sleep(int ms)
{
    Step s;
    s.kind = Step::Kind::Sleep;
    s.ms = ms;
    add(std::move(s));
}

void Script::start()
{
    scheduleNext();
}

void Script::fail(const QString &why)
{
    if (m_failed || m_done)
        return;
    m_failed = true;
    m_done = true;
    m_poll.stop();
    m_queue.clear();
    m_planned.clear();
    Q_EMIT finished(false, why);
}

void Script::scheduleNext(int ms)
{
    QTimer::singleShot(ms, this, &Script::runNext);
}

void Script::runNext()
{
    if (m_done)
        return;
    if (m_queue.empty()) {
        m_done = true;
        Q_EMIT finished(true, QString());
        return;
    }
    Step step = std::move(m_queue.front());
    m_queue.pop_front();
    switch (step.kind) {
    case Step::Kind::Run:
        m_inStep = true;
        step.action();
        m_inStep = false;
        // What the step planned runs next, in the order it was planned.
        for (auto it = m_planned.rbegin(); it != m_planned.rend(); ++it)
            m_queue.push_front(std::move(*it));
        m_planned.clear();
        scheduleNext();
        break;
    case Step::Kind::Sleep:
        scheduleNext(step.ms);
        break;
    case Step::Kind::WaitFor:
        m_waiting = std::move(step);
        m_waitClock.start();
        m_poll.start();
        poll();
        break;
    }
}

void Script::poll()
{
    if (m_done) {
        m_poll.stop();
        return;
    }
    if (m_waiting.condition()) {
        m_poll.stop();
        scheduleNext();
    } else if (m_waitClock.elapsed() > m_waiting.ms) {
        m_poll.stop();
        fail(QStringLiteral("timed out after %1 ms waiting for: %2")
                 .arg(m_waiting.ms)
                 .arg(m_waiting.what));
    }
}

} // namespace stepcom
