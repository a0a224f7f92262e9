#pragma once

#include "line/idchange.h"

#include <QList>
#include <QObject>
#include <QString>

namespace stepcom {

class DeviceSession;

// The id assistant for a new line: the technician connects the controllers one at a time; each
// arrives with the factory id 1 at 9600 baud (manual: 40212/40213). For each, next() gives it the
// next free id (and the common baud, if one is set) with IdChange, which proves it answers there
// and no longer at id 1, and puts it on the session's device list; then the assistant waits for
// the next one. Two controllers answering at id 1 garble each other: the assistant stops in
// Collision and says so, and goes on only when next() finds one controller alone. While it
// works the live status is paused (its reads would land on controllers that are being moved);
// finish() leaves the line at the common baud with every controller on the list, and resumes it.
class IdAssigner : public QObject
{
    Q_OBJECT
public:
    enum class State {
        Idle,      // not started
        Waiting,   // connect the next controller alone, then next()
        Working,   // asking, writing, verifying
        Collision, // two or more controllers answered at id 1: refuses to go on
        Failed,    // the last controller did not get its id (text() says why); next() retries
        Finished,  // finish(): the line is at the common baud, the list holds every id given
    };
    Q_ENUM(State)

    static constexpr int kFactoryId = 1;
    static constexpr int kFactoryBaud = 9600;

    explicit IdAssigner(DeviceSession *session, QObject *parent = nullptr);
    ~IdAssigner() override;

    // The first id to give (2 to 255; id 1 is where every new controller arrives).
    void setFirstId(int id);
    int firstId() const { return m_firstId; }
    // The baud every controller gets (serial lines; 0 or 9600: they keep 9600).
    void setCommonBaud(int baud);
    int commonBaud() const { return m_commonBaud; }
    // Save each id (and baud) to flash once verified; off, a controller is back at id 1 and
    // 9600 after its next power-off (IdChange::setSaveToFlash).
    void setSaveToFlash(bool save) { m_change->setSaveToFlash(save); }
    bool savesToFlash() const { return m_change->savesToFlash(); }

    // Starts (or starts again after finish()): needs a connected session. False and text() says
    // why when it cannot. `newLine`: the session's device list starts empty (a list restored
    // from an earlier line on this port would take its ids); else its ids stay taken.
    bool start(bool newLine = true);
    // "The next controller is connected, alone": give it nextId().
    void next();
    // Done adding: the line moves to the common baud, the live status resumes.
    void finish();

    State state() const { return m_state; }
    IdChange::Problem problem() const { return m_change->problem(); }
    // What happened last, or what to do now, in words.
    QString text() const { return m_text; }
    // The ids given in this run, in order.
    QList<int> assigned() const { return m_assigned; }
    // The id the next controller gets: the lowest from firstId() that is neither on the
    // session's list nor given in this run.
    int nextId() const;

Q_SIGNALS:
    void stateChanged(stepcom::IdAssigner::State state);
    void progress(const QString &step);
    // A controller answers at `id` (and the common baud) and is on the device list.
    void deviceAdded(int id);

private:
    void change();
    void onChanged(bool ok, const QString &text);
    void setState(State state, const QString &text);
    void resumeLive();
    // After finish() moved the line: ask each id given, then list them and resume.
    void rollCall(int index, int baud, QList<int> silent);

    DeviceSession *m_session;
    IdChange *m_change;
    int m_firstId = 2;
    int m_commonBaud = 0;
    State m_state = State::Idle;
    QString m_text;
    QList<int> m_assigned;
    int m_target = 0;
    bool m_wasLive = true;
    bool m_paused = false;
};

} // namespace stepcom
