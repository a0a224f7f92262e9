#pragma once

#include "device/writeplanner.h"
#include "profile/profile.h"

#include <QHash>
#include <QList>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;

// One row of "device versus profile".
struct ProfileDifference
{
    const Parameter *parameter = nullptr;
    std::optional<qint64> device;  // nullopt: not known (not read, not connected)
    std::optional<qint64> profile; // nullopt: the profile does not hold it (link settings)
    bool linkSetting = false;      // device.id / device.baud: applied only when chosen
    // Only known values differ: a value not read (not connected) is unknown, not different.
    bool differs() const { return profile.has_value() && device.has_value() && device != profile; }
};

// Compares a profile with what a controller holds and turns a choice of rows into writes.
// Pure functions: the CLI and the window share them.
class ProfileDiff
{
public:
    // One row per profile parameter (every read-write register, device.id and device.baud
    // included), in map order.
    static QList<ProfileDifference> compare(const RegisterMap &map, const Profile &profile,
                                            const QHash<QString, qint64> &device);
    static QList<ProfileDifference> differences(const QList<ProfileDifference> &rows);
    // The writes for the chosen keys, in map order. Keys the profile does not hold are errors;
    // device.id and device.baud are skipped unless `includeLink`.
    static QList<ParameterWrite> writesFor(const RegisterMap &map, const Profile &profile,
                                           const QStringList &keys, bool includeLink,
                                           QStringList *errors);
    // "motor1.speed: 300 rpm -> 450 rpm" (device value first).
    static QString describe(const ProfileDifference &row);
};

} // namespace stepcom
