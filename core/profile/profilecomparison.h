#pragma once

#include "profile/profilediff.h"

#include <optional>

namespace stepcom {

// A key of two profiles that this register map cannot take (unknown to it, or a value out of
// its range in one of them): compared as the files hold it, in engineering units.
struct ProfileForeignRow
{
    QString key;
    std::optional<double> a; // nullopt: file A does not hold it
    std::optional<double> b;
    QString reason; // why this map cannot take it (from the first file that says so)
    bool differs() const { return a != b; }
};

// Two profile files side by side against one register map, no controller needed: the same
// rows as ProfileDiff's "device versus profile", with file A in place of the device.
class ProfileComparison
{
public:
    static ProfileComparison compare(const RegisterMap &map, const Profile &a, const Profile &b);

    // Every setting of the map, in map order (link settings included): `device` holds file A's
    // value, `profile` file B's. A value one file holds beyond the map's range is a foreign row.
    QList<ProfileDifference> rows;
    QList<ProfileForeignRow> foreign; // by key

    QList<ProfileDifference> differing() const; // both hold it, the values differ
    QList<ProfileDifference> same() const;      // both hold it, the same value
    QList<ProfileDifference> onlyInA() const;   // A holds it, B lacks it
    QList<ProfileDifference> onlyInB() const;
    QList<ProfileForeignRow> foreignDiffering() const;
    // Every value of one file is in the other, equal: nothing to tell apart.
    bool identical() const;

private:
    bool isForeign(const QString &key) const;
};

} // namespace stepcom
