#pragma once

#include <QHash>
#include <QList>
#include <QObject>
#include <QStringList>

namespace stepcom {

class RegisterMap;

// Sees that a controller may have restarted (its 24 V switched off and on: a daily event while
// a machine is commissioned) from what it answers, per device of the line: it answers again
// after a silence, or its positions went back to 0. Each axis is judged on its own: one that
// stood still (not running, no command that moves or zeroes it) and reads 0 proves a restart
// whatever the other axes did; one that was moving may have ended at 0. It only suspects: the
// session reads everything again and compares with what it held before it says what happened.
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
        Reset,       // back at 0, and an axis that stood still went there: restarted
        AfterMotion, // back at 0 after a silence, but only axes that moved or were commanded
                     // went there: they may have ended there, or it restarted -- not known
    };
    Q_ENUM(Zeros)

    // What the judgement was made from, said with it (motors by number, 1..).
    struct Evidence
    {
        qint64 silentMs = 0;       // how long it did not answer; 0: it answered throughout
        QList<int> zeroed;         // read 0 now, not 0 before
        QList<int> stoodStill;     // not running before, and no command to move or zero it
        QList<int> moving;         // running before, or commanded to move or zero
        QHash<int, qint64> before; // raw positions at the last answer before
        bool conclusive() const;   // an axis that stood still went to 0
    };

    explicit RestartWatch(const RegisterMap &map, QObject *parent = nullptr);

    // A status read of `device` ended at `nowMs`: `values` (raw, by key) when it was answered.
    void statusRead(int device, bool ok, const QHash<QString, qint64> &values, qint64 nowMs);
    // A command went to `device` after which positions of `motors` (empty: every motor) may
    // rightly be 0 (a move, homing, zeroing, return to zero): the next samples' zeros are its.
    void commandSent(int device, qint64 nowMs, const QList<int> &motors = {});
    // The link is gone (or another line): nothing known of any device.
    void forget();

    // The coils after which positions at 0 are no sign of a restart.
    bool movesOrZeroes(const QString &coilKey) const;
    // The motors a coil of `map` moves or zeroes: its own motor, or every one (empty).
    static QList<int> motorsOf(const RegisterMap &map, const QString &coilKey);

    // "motor 1 stood still at -1234.56 mm and reads 0.00 mm; motor 2 was moving and reads
    // 0.00 mm", in the installed language, after `first` (the silence) when given.
    static QString describe(const Evidence &evidence, const RegisterMap &map,
                            const QString &first = {});

Q_SIGNALS:
    // `why`: in words, "it answers again after 3.2 s without an answer"; `zeros`: what its
    // positions say; `evidence`: what was seen, axis by axis.
    void suspected(int device, const QString &why, stepcom::RestartWatch::Zeros zeros,
                   const stepcom::RestartWatch::Evidence &evidence);

private:
    struct Axis
    {
        qint64 position = 0;
        bool running = false;
        qint64 commandedAtMs = -1; // the last command that may move or zero it
        qint64 runningAtMs = -1;   // last seen running
    };
    struct Device
    {
        qint64 answeredAtMs = -1; // the last answered read
        qint64 sampledAtMs = -1;  // the last sample with every position
        bool failed = false;      // a read went unanswered since
        QHash<int, Axis> axes;    // by motor, known once sampled
    };
    // Whether `axis` stood still through the last sample at `sampledAtMs` until `nowMs`.
    static bool stoodStill(const Axis &axis, qint64 sampledAtMs, qint64 nowMs);

    QHash<int, QString> m_positionKeys; // by motor
    QHash<int, QString> m_runningKeys;
    QHash<int, Device> m_devices;
};

} // namespace stepcom
