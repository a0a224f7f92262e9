#pragma once

#include <QMetaObject>
#include <QObject>
#include <QString>

namespace stepcom {

class DeviceSession;
class Parameter;
struct ReadOutcome;

// Gives the one controller at id `from` the id `to` (and, on a serial line, a new baud) and
// proves it: someone answers at `from` without garbled answers (two controllers at one id
// garble each other), nobody answers at `to` yet, the id is written and read back at `to`,
// nobody answers at `from` any more, then the baud is written and read back at the new baud.
// The controller takes a new id or baud at once (manual, 40212/40213), so the link follows it
// after each write's answer. A new id or baud lasts until the power is switched off unless it is
// saved to flash (setSaveToFlash): then the change ends with the save, at the new id and baud.
// stepcomctl assign-id and the id assistant both run this.
class IdChange : public QObject
{
    Q_OBJECT
public:
    enum class Problem {
        None,
        Refused,      // bad arguments or no link: nothing was sent
        Collision,    // garbled answers at `from`: two or more controllers answer there
        NoController, // nobody answers at `from`
        Taken,        // someone answers at `to` already
        NotAtNewId,   // the id write or its read-back at `to` failed
        StillAtOldId, // after the change someone still answers at `from`
        NotAtNewBaud, // the baud write or its read-back at the new baud failed
        NotSaved,     // the controller answers at the new id (and baud), but the save failed
    };
    Q_ENUM(Problem)

    explicit IdChange(DeviceSession *session, QObject *parent = nullptr);
    ~IdChange() override;

    // `baud` 0 (or the line's baud, or a line that is not serial): the baud stays.
    void start(int from, int to, int baud = 0);
    // Save the new id and baud to flash once they are verified (off: they last until power-off).
    void setSaveToFlash(bool save) { m_saveToFlash = save; }
    bool savesToFlash() const { return m_saveToFlash; }
    bool isRunning() const { return m_running; }
    Problem problem() const { return m_problem; }
    // What happened, in words, once finished.
    QString text() const { return m_text; }

Q_SIGNALS:
    // Each step as it begins ("asking id 1", "writing id 4"), for a progress line.
    void progress(const QString &step);
    void finished(bool ok, const QString &text);

private:
    void probeTarget();
    void writeId();
    void checkOldIdSilent();
    void writeBaud();
    void probe(int id, void (IdChange::*then)(const ReadOutcome &, bool garbled));
    void onFromProbed(const ReadOutcome &r, bool garbled);
    void onTargetProbed(const ReadOutcome &r, bool garbled);
    void onOldIdProbed(const ReadOutcome &r, bool garbled);
    // Runs changeLink(id, baud) and calls `then(ok, reason)` once.
    void changeLink(int id, int baud, void (IdChange::*then)(bool ok, const QString &reason));
    void onIdWritten(bool ok, const QString &reason);
    void onBaudWritten(bool ok, const QString &reason);
    void saveThenSucceed();
    void succeed();
    void fail(Problem problem, const QString &text);
    void dropConnections();

    DeviceSession *m_session;
    const Parameter *m_idParam = nullptr;
    int m_from = 0;
    int m_to = 0;
    int m_baud = 0;
    bool m_running = false;
    bool m_saveToFlash = false;
    Problem m_problem = Problem::None;
    QString m_text;
    QMetaObject::Connection m_changed;
    QMetaObject::Connection m_changeFailed;
};

} // namespace stepcom
