#pragma once

#include "device/motionoutcome.h"
#include "device/motionwatch.h"

#include <QHash>
#include <QObject>

#include <optional>

namespace stepcom {

class DeviceSession;
class ModbusLink;
class ReferenceTracker;
struct Request;

// Follows every motion command the session sends (single move, homing, homing in order, return
// to data zero, arc, line) until its axes are idle, reads where they ended and says what it came
// to (MotionJudge): "done" only at the end point, "referenced" only on the home input at 0.
// Stops, E-STOPs and link losses seen in between are remembered as the cause, and they take the
// axes' reference away. Front-ends show the state; the words are made when they are shown.
class MotionSupervisor : public QObject
{
    Q_OBJECT
public:
    // `link` is the session's own: every stop goes through it, whoever sent it.
    MotionSupervisor(DeviceSession *session, ModbusLink *link);
    ~MotionSupervisor() override;

    ReferenceTracker *references() const { return m_references; }
    // The motion being followed that moves `motor` / of `kind`, if any.
    std::optional<MotionStart> active(int motor) const;
    std::optional<MotionStart> active(MotionKind kind) const;
    // Motors of the followed motion of `kind` that the last poll saw running.
    QList<int> running(MotionKind kind) const;
    // The last outcome that moved `motor` / of `kind`.
    std::optional<MotionOutcome> lastOutcome(int motor) const;
    std::optional<MotionOutcome> lastOutcome(MotionKind kind) const;
    // The outcome in the installed language.
    QString text(const MotionOutcome &outcome) const;
    // Before sending `command`: a warning when it drives an axis into a limit already ON.
    QString startWarning(const QString &command) const;

Q_SIGNALS:
    void started(const stepcom::MotionStart &start);
    void finished(const stepcom::MotionOutcome &outcome);
    // An E-STOP went out: every held control (jog buttons, keys, starts) lets go at once.
    void emergencyStopSent();
    // Something shown may have changed: a motion started, progressed or ended.
    void changed();

private:
    struct Followed
    {
        quint64 id = 0;
        MotionWatch watch;
        bool judging = false;
    };

    StatusValues snapshot() const;
    void onCommandFinished(const QString &key, bool ok);
    void onDispatched(const Request &request);
    void onCycle(bool ok);
    void onDisconnected();
    void readEndThenJudge(quint64 id);
    void conclude(quint64 id, const StatusValues &end);
    int indexOf(quint64 id) const;

    DeviceSession *m_session;
    ReferenceTracker *m_references;
    QHash<quint16, QString> m_coils; // coil address -> key
    QList<Followed> m_followed;
    quint64 m_nextId = 1;
    QHash<int, MotionOutcome> m_byMotor;
    QHash<int, MotionOutcome> m_byKind;
};

} // namespace stepcom
