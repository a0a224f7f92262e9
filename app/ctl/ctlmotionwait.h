#pragma once

#include "motion/motionoutcome.h"

#include <QObject>
#include <QTextStream>
#include <QTimer>

#include <memory>

namespace stepcom {

class DeviceSession;
class MotionWatch;
class RestartWatch;
struct Parameter;

// `stepcomctl command NAME --wait` (a row of the command table), over stepcomctl's one-shot
// session: reads what the controller holds, sends the motion command,
// reads the positions, running flags and inputs until the axes are idle, and prints the
// outcome in the window's words (MotionJudge), or as JSON. Exit 0 only when "done" or
// "referenced"; 1 when it stopped elsewhere, was interrupted, the controller restarted or the
// link was lost.
class CtlMotionWait : public QObject
{
    Q_OBJECT
public:
    // What it says goes to `out` and `err`: the runner's, kept for --json's object.
    CtlMotionWait(DeviceSession *session, const Parameter &command, bool json, QTextStream &out,
                  QTextStream &err, QObject *parent = nullptr);
    ~CtlMotionWait() override;
    void start();

Q_SIGNALS:
    void finished(int exitCode);

private:
    void sample();
    void conclude(MotionCause cause);
    void fail(const QString &message);

    DeviceSession *m_session;
    const Parameter &m_command;
    bool m_json;
    StatusValues m_values;
    std::unique_ptr<MotionWatch> m_watch;
    RestartWatch *m_restarts; // a restart ends the wait: the positions after it mean nothing
    QTimer m_timer;
    qint64 m_answeredAtMs = 0; // the controller's last answer (epoch ms)
    bool m_done = false;
    QTextStream &m_out;
    QTextStream &m_err;
};

} // namespace stepcom
