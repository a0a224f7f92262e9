#pragma once

#include "profile/backupstore.h"
#include "session/devicesession.h"

#include <QCoreApplication>

#include <functional>

namespace stepcom {

// A backup of the controller's settings through a session, before a risky operation: the
// settings the store holds from the device, or, when some are not known (a one-shot session,
// a read that failed), a read of them first; a device of the line not in view is always read.
// The window's risk guard and stepcomctl's use it.
class SessionBackup
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::SessionBackup)
public:
    static BackupStore::Operation operation(DeviceSession::Risk risk);
    // The settings to back up: every profile setting, the link included.
    static QList<const Parameter *> settings(const RegisterMap &map);
    // Saves the backup of controller `id` (the device in view or another of the line) and
    // hands over what came of it (Saved::error says why not).
    static void save(DeviceSession *session, const BackupStore &store, DeviceSession::Risk risk,
                     int id, std::function<void(const BackupStore::Saved &)> done);
};

} // namespace stepcom
