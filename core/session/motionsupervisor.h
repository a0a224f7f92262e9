#pragma once

#include "motion/motionoutcome.h"
#include "motion/motionwatch.h"

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
// It follows every controller of the line at once (by device id): a homing on device 2 is still
// judged from the background poll while device 3 is in view. The calls without an id and the
// signals `started` and `finished` are about the device in view.
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
    // Every motion followed on `device` (any device of the line).
    QList<MotionStart> activeOn(int device) const;
    // Motors of the followed motion of `kind` that the last poll saw running.
    QList<int> running(MotionKind kind) const;
    // The last outcome that moved `motor` / of `kind`.
    std::optional<MotionOutcome> lastOutcome(int motor) const;
    std::optional<MotionOutcome> lastOutcome(MotionKind kind) const;
    // The outcome in the installed language.
    QString text(const MotionOutcome &outcome) const;
    // Before sending `command`: a warning when it drives an axis into a limit already ON.
    QString startWarning(const QString &command) const;

    // The session: `device` acknowledged `key` (it was in view when the command was given).
    void commandAcknowledged(int device, const QString &key);
    // Controller `device` restarted: every motion followed there ended with it, its references
    // are gone.
    void restarted(int device) { interrupted(device, MotionCause::Restarted); }
    // `device` did not answer for a while as it moved and stands at 0 now: it may have
    // restarted or finished; every motion followed there ended unknown, its references too.
    void silent(int device) { interrupted(device, MotionCause::Silent); }
    // The session: fresh status of `device` is in (the live poll or the background poll).
    void statusRead(int device, bool ok);
    int view() const { return m_view; }

Q_SIGNALS:
    void started(const stepcom::MotionStart &start);
    void finished(const stepcom::MotionOutcome &outcome);
    // Every outcome, of any device of the line.
    void deviceFinished(int device, const stepcom::MotionOutcome &outcome);
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
    // What is followed and was judged on one controller.
    struct Device
    {
        QList<Followed> followed;
        QHash<int, MotionOutcome> byMotor;
        QHash<int, MotionOutcome> byKind;
    };

    StatusValues snapshot(int device) const;
    const Device &inView() const;
    void onDispatched(const Request &request);
    void onDisconnected();
    void interrupted(int device, MotionCause cause);
    void setView(int device);
    void readEndThenJudge(int device, quint64 id);
    void conclude(int device, quint64 id, const StatusValues &end);
    static int indexOf(const Device &d, quint64 id);

    DeviceSession *m_session;
    ModbusLink *m_link;
    ReferenceTracker *m_references;
    QHash<quint16, QString> m_coils; // coil address -> key
    QHash<int, Device> m_devices;    // by device id
    int m_view = 1;
    quint64 m_nextId = 1;
};

} // namespace stepcom
