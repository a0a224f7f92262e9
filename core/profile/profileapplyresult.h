#pragma once

#include "map/parameter.h"

#include <QCoreApplication>
#include <QList>
#include <QStringList>

#include <optional>

namespace stepcom {

// What became of one key of a profile applied to one controller.
struct AppliedKey
{
    enum class State {
        Unchanged,  // the controller already held the profile's value: not written
        Verified,   // written and read back equal
        Written,    // acknowledged, but it read back other (readBack) or could not be read
        Refused,    // not written: `refusal` says why
        NotWritten, // never sent (an earlier step failed, an E-STOP, the backup failed)
        NotKnown,   // sent without a good answer, or the controller restarted after it
        Lost,       // verified, then the controller held its old value again: it restarted
    };
    enum class Refusal { None, OutOfRange, Controller, Questioned };
    QString key;
    const Parameter *parameter = nullptr;
    State state = State::NotWritten;
    Refusal refusal = Refusal::None;
    qint64 wanted = 0;
    std::optional<qint64> before;   // what the controller held before (nullopt: not known)
    std::optional<qint64> readBack; // Written, Lost: what it read back (nullopt: nothing)
    QString reason;                 // Refused, NotWritten, NotKnown, Lost: why, in words
};

// How one apply ended, per key, for every front-end to show (none works it out itself).
struct ProfileApplyResult
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ProfileApplyResult)
public:
    enum class End {
        Done,      // every step ran (keys may still be refused or unverified)
        Failed,    // nothing to act on: the read failed or the backup was refused
        Stopped,   // an E-STOP stopped it between steps
        LinkLost,  // the link went away during it
        Restarted, // the controller restarted during it
    };
    int id = 0;
    End end = End::Done;
    QList<AppliedKey> keys;
    QString error;           // Failed, Stopped, LinkLost, Restarted: why, in words
    QStringList writeErrors; // what the write said went wrong
    bool flashAsked = false;
    std::optional<bool> savedToFlash; // nullopt: not tried, or its answer did not come
    QString flashError;

    QStringList keysIn(AppliedKey::State state) const;
    const AppliedKey *key(const QString &key) const;
    // Every key asked for verified or already held, and saved to flash when that was asked.
    bool ok() const;
    // "motor1.speed: wrote 450 rpm, the controller holds 300 rpm" and the like, one per key
    // that is neither verified nor unchanged.
    QStringList problems() const;
    // One key in words, named `name` (its key when empty).
    static QString describe(const AppliedKey &k, const QString &name = QString());
};

} // namespace stepcom
