#pragma once

#include "device/deviceclient.h"
#include "profile/profile.h"
#include "profile/profilediff.h"

#include <QCoreApplication>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <optional>

namespace stepcom {

class DeviceSession;

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
    QString error;          // Failed, Stopped, LinkLost, Restarted: why, in words
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

// Applies a profile to one controller, the step that can crash an axis on the next machine.
// One class for the compare dialog, ProfileRollout and stepcomctl apply: read what the
// controller holds, compare with the profile, back up through the session's risk guard
// (Risk::Apply), write the chosen keys that differ, verify them by read-back and, when asked,
// save to flash (through the guard, Risk::SaveToFlash). An E-STOP stops it between steps; a
// lost link or a restart ends it with each key known written or said not known.
class ProfileApply : public QObject
{
    Q_OBJECT
public:
    enum class Step { Reading, BackingUp, Writing, ReadingBack, SavingToFlash };
    Q_ENUM(Step)

    // `id`: the controller of the line (0: the device in view when made).
    ProfileApply(DeviceSession *session, const Profile &profile, int id = 0,
                 QObject *parent = nullptr);

    int id() const { return m_id; }
    const Profile &profile() const { return m_profile; }
    // device.id and device.baud may be written (the device in view only; the link follows).
    void setIncludeLink(bool include) { m_includeLink = include; }
    // Save to flash after the writes (the device in view only).
    void setSaveToFlash(bool save) { m_saveToFlash = save; }
    // Keys the review (WriteReview) questions are refused instead of written.
    void setRefuseQuestioned(bool refuse) { m_refuseQuestioned = refuse; }

    // Reads what the controller holds and compares; `compared` follows. Writes nothing.
    void compare();
    bool isCompared() const { return m_compared; }
    const QHash<QString, qint64> &before() const { return m_before; }
    const QStringList &readErrors() const { return m_readErrors; }
    const QStringList &unsupported() const { return m_unsupported; }
    // The differing rows (link settings only with setIncludeLink).
    const QList<ProfileDifference> &differences() const { return m_differences; }
    QList<ProfileDifference> leftOutLinkSettings() const;
    QStringList differingKeys() const;
    // What the window's write dialog asks about writing `keys` (WriteReview), on what was read.
    QStringList questions(const QStringList &keys) const;

    // Writes `keys` of the profile (reading and comparing first unless compare() just did);
    // `finished` follows once.
    void apply(const QStringList &keys);
    bool isBusy() const { return m_busy; }
    const ProfileApplyResult &result() const { return m_result; }

Q_SIGNALS:
    void compared(bool ok);
    void progress(stepcom::ProfileApply::Step step);
    void finished(const stepcom::ProfileApplyResult &result);

private:
    void read(std::function<void()> next);
    void plan();
    void backUp();
    void write();
    void written(const WriteOutcome &outcome);
    void readBack();
    void saveToFlash();
    void end(ProfileApplyResult::End end, const QString &error = QString());
    // A step may start: false (and the apply ended) after an E-STOP or a lost link.
    bool mayGoOn();
    // Says the step; false when whoever heard it ended the apply (an E-STOP).
    bool announce(Step step);
    bool isInView() const;
    AppliedKey *keyOf(const QString &key);
    QList<ParameterWrite> pendingWrites() const;

    QPointer<DeviceSession> m_session;
    Profile m_profile;
    int m_id = 0;
    bool m_includeLink = false;
    bool m_saveToFlash = false;
    bool m_refuseQuestioned = false;
    bool m_compared = false;
    bool m_busy = false;
    bool m_stopped = false;
    bool m_restarted = false;
    QString m_lost; // why the link went away during the apply
    QHash<QString, qint64> m_before;
    QStringList m_readErrors;
    QStringList m_unsupported;
    QList<ProfileDifference> m_differences;
    QStringList m_keys;
    ProfileApplyResult m_result;
    quint64 m_generation = 0; // an answer after the apply ended is dropped
};

} // namespace stepcom
