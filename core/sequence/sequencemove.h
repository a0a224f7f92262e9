#pragma once

#include "session/stepmove.h"

#include <QHash>
#include <QList>
#include <QObject>

namespace stepcom {

class DeviceSession;

// One step's move of one or several axes at once, each over StepMove (the move path of a step
// jog and `stepcomctl move`: its read, travel-limit check, single move, MotionSupervisor's
// verdict and the user's distance and direction put back), started together and finished when
// every axis was judged. The caller keeps the status poll running meanwhile, so no axis's
// StepMove stops it under another's move.
class SequenceMove : public QObject
{
    Q_OBJECT
public:
    explicit SequenceMove(DeviceSession *session, QObject *parent = nullptr);

    // Starts every request (one per motor); the first refusal is returned and nothing is started.
    QString start(const QList<StepMoveRequest> &requests);
    bool isBusy() const { return m_pending > 0; }
    // The motors of the move under way.
    QList<int> motors() const;

Q_SIGNALS:
    // Every axis's result, in the order of the requests.
    void finished(const QList<stepcom::StepMoveResult> &results);

private:
    StepMove *stepFor(int motor);
    void onFinished(int motor, const StepMoveResult &result);

    DeviceSession *m_session;
    QHash<int, StepMove *> m_steps; // by motor, made on first use
    QList<int> m_order;
    QHash<int, StepMoveResult> m_results;
    int m_pending = 0;
};

} // namespace stepcom
