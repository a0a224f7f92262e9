#pragma once

#include "device/deviceclient.h"
#include "profile/profile.h"
#include "profile/profileapplyresult.h"
#include "profile/profilediff.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace stepcom {

class DeviceSession;

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
