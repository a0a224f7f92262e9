#pragma once

#include <QObject>
#include <QStringList>

namespace stepcom {

class DeviceSession;

// Follows a motion the user started with a command (single move, homing, return to zero) until
// the controller reports every watched motor idle. A poll cycle that was already under way when
// the command was answered may hold the flags from before it, so the verdict waits for two
// idle cycles that started afterwards.
class JogActivity : public QObject
{
    Q_OBJECT
public:
    // `runningKeys`: the motors' running flags (motorN.running) this activity waits for.
    JogActivity(DeviceSession *session, const QStringList &runningKeys, QObject *parent = nullptr);

    // The command was acknowledged: the motion is under way; `what` names it for people.
    void start(const QString &what);
    void clear();
    bool isActive() const { return m_active; }
    QString what() const { return m_what; }
    // The 1-based indexes (into runningKeys) of the motors the last poll saw running.
    QList<int> running() const;

Q_SIGNALS:
    void changed();
    void finished(const QString &what);

private:
    void onCycle(bool ok);

    DeviceSession *m_session;
    QStringList m_keys;
    QString m_what;
    bool m_active = false;
    int m_cycles = 0;
    int m_idleCycles = 0;
};

} // namespace stepcom
