#pragma once

#include "profile/profile.h"
#include "profile/profileapply.h"
#include "profile/profilediff.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace stepcom {

class DeviceSession;

// One device's part in a profile applied to several: what it held, what differed, what the
// user chose, and how it ended.
struct RolloutDevice
{
    enum class State { Pending, Compared, Written, Skipped, Failed };
    int id = 0;
    QString name;
    State state = State::Pending;
    QHash<QString, qint64> before;        // every profile value as read before writing
    QList<ProfileDifference> differences; // rows that differ (link settings left out)
    QStringList chosen;                   // keys to write (all differing ones at first)
    QStringList verified;                 // written, read back and equal
    QString reason;                       // skipped or failed: why
    ProfileApplyResult result;            // what its ProfileApply came to, per key
};

// Applies one profile to several controllers of the line, one after the other, each through
// its own ProfileApply: compare() reads each and lists what differs (nothing is written); after
// the user confirmed, apply() lets each back up its settings (the session's risk guard), write
// its chosen differences and verify them. Each device ends written (every chosen value
// verified), skipped (nothing
// chosen, or nothing differed) or failed (with why); a failure on one does not stop the
// others, an E-STOP stops all that is left. device.id and device.baud are never applied here:
// one id for several devices would make them collide.
class ProfileRollout : public QObject
{
    Q_OBJECT
public:
    ProfileRollout(DeviceSession *session, const Profile &profile, QObject *parent = nullptr);

    const Profile &profile() const { return m_profile; }

    // Reads every id in `ids` (names: what the device list calls them) and compares.
    void compare(const QList<int> &ids, const QHash<int, QString> &names = {});
    // The keys to write to `id` (of its differences); the rest of them are left as they are.
    void choose(int id, const QStringList &keys);
    // Writes what is chosen; only after compare() has finished.
    void apply();
    bool isBusy() const { return m_busy; }
    bool isApplied() const { return m_applied; }
    bool isCompared() const { return m_compared; }
    const QList<RolloutDevice> &devices() const { return m_devices; }
    const RolloutDevice *device(int id) const;
    // How many chosen values go to how many devices.
    int chosenValues() const;
    int chosenDevices() const;
    // One line per device: "id 2 (Y axis): written and verified, 3 value(s)", translated.
    static QString describe(const RolloutDevice &d);
    // The worst of the devices: true when none failed.
    bool allOk() const;

Q_SIGNALS:
    void compared();
    void deviceFinished(int id);
    void finished(bool ok);

private:
    void compareNext();
    void applyNext();
    void applied(const ProfileApplyResult &result);
    void end(RolloutDevice &d, RolloutDevice::State state, const QString &reason);
    void stopAll(); // E-STOP: nothing more goes out
    ProfileApply *applyOf(int id);

    QPointer<DeviceSession> m_session;
    Profile m_profile;
    QList<RolloutDevice> m_devices;
    QHash<int, ProfileApply *> m_applies; // one per device, from its comparison on
    int m_index = 0;
    bool m_busy = false;
    bool m_compared = false;
    bool m_applied = false;
    bool m_stopped = false;
    quint64 m_generation = 0; // an answer after an E-STOP is dropped
};

} // namespace stepcom
