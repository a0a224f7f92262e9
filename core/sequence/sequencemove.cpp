#include "sequence/sequencemove.h"

namespace stepcom {

SequenceMove::SequenceMove(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{}

StepMove *SequenceMove::stepFor(int motor)
{
    if (StepMove *s = m_steps.value(motor))
        return s;
    auto *s = new StepMove(m_session);
    s->setParent(this);
    connect(s, &StepMove::finished, this,
            [this, motor](const StepMoveResult &r) { onFinished(motor, r); });
    m_steps.insert(motor, s);
    return s;
}

QList<int> SequenceMove::motors() const
{
    return isBusy() ? m_order : QList<int>();
}

QString SequenceMove::start(const QList<StepMoveRequest> &requests)
{
    if (isBusy())
        return tr("A move is still running: wait for it to end");
    for (const StepMoveRequest &r : requests) {
        if (const QString why = stepFor(r.motor)->refusal(r); !why.isEmpty())
            return why;
    }
    m_order.clear();
    m_results.clear();
    m_pending = int(requests.size());
    for (const StepMoveRequest &r : requests)
        m_order << r.motor;
    for (const StepMoveRequest &r : requests) {
        if (const QString why = stepFor(r.motor)->start(r); !why.isEmpty()) {
            StepMoveResult failed;
            failed.request = r;
            failed.restored = true; // nothing was written
            failed.text = why;
            onFinished(r.motor, failed);
        }
    }
    return {};
}

void SequenceMove::onFinished(int motor, const StepMoveResult &result)
{
    if (m_pending == 0 || !m_order.contains(motor) || m_results.contains(motor))
        return;
    m_results.insert(motor, result);
    if (--m_pending > 0)
        return;
    QList<StepMoveResult> all;
    for (int m : std::as_const(m_order))
        all << m_results.value(m);
    Q_EMIT finished(all);
}

} // namespace stepcom
