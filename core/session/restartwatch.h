#pragma once

#include <QHash>
#include <QObject>
#include <QStringList>

namespace stepcom {

class RegisterMap;

// Sees that a controller may have restarted (its 24 V switched off and on: a daily event while
// a machine is commissioned) from what it answers, per device of the line: it answers again
// after a silence, or its positions went back to 0 with no motion and no command that moves or
// zeroes them. It only suspects: the session reads everything again and compares with what it
// held before it says the controller restarted.
class RestartWatch : public QObject
{
    Q_OBJECT
public:
    // No answer for this long (from the last answer to the next, with unanswered reads in
    // between), then answering: the controller may have been off.
    static constexpr qint64 kSilenceMs = 1000;
    // Zeros this soon after a command that moves or zeroes, or after a motor was last seen
    // running, are theirs: a status read under way when a command went out may still show the
    // values from before it, and homing stops on the home input before it zeroes the position.
    static constexpr qint64 kCommandWindowMs = 1500;

    // What the positions say, next to a silence.
    enum class Zeros {
        Kept,        // not all back at 0 (or not known)
        Reset,       // back at 0 with no motion and no command that explains it: restarted
        AfterMotion, // back at 0 after a silence in which an axis moved or was commanded: it
                     // may have ended there, or restarted -- not known from the positions
    };
    Q_ENUM(Zeros)

    explicit RestartWatch(const RegisterMap &map, QObject *parent = nullptr);

    // A status read of `device` ended at `nowMs`: `values` (raw, by key) when it was answered.
    void statusRead(int device, bool ok, const QHash<QString, qint64> &values, qint64 nowMs);
    // A command went to `device` after which positions may rightly be 0 (a move, homing,
    // zeroing, return to zero): the next samples' zeros are its.
    void commandSent(int device, qint64 nowMs);
    // The link is gone (or another line): nothing known of any device.
    void forget();

    // The coils after which positions at 0 are no sign of a restart.
    bool movesOrZeroes(const QString &coilKey) const;

Q_SIGNALS:
    // `why`: in words, "it answers again after 3.2 s without an answer"; `zeros`: what its
    // positions say.
    void suspected(int device, const QString &why, stepcom::RestartWatch::Zeros zeros);

private:
    struct Device
    {
        qint64 answeredAtMs = -1; // the last answered read
        bool failed = false;      // a read went unanswered since
        bool known = false;       // a sample was taken since the last command or silence
        bool anyNonZero = false;
        bool running = false;
        bool commanded = false; // since the last sample
        qint64 commandedAtMs = -1;
        qint64 runningAtMs = -1; // last seen running
    };

    QStringList m_positionKeys;
    QStringList m_runningKeys;
    QHash<int, Device> m_devices;
};

} // namespace stepcom
