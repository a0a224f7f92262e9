#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

namespace stepcom {

class RegisterMap;

// One value of a profile that this register map cannot take, as the file holds it.
struct ProfileNote
{
    QString key;
    double number = 0;        // the file's number, engineering units
    QString reason;           // why this map cannot take it, naming the key and the value
    QString fileText() const; // the number as written in the file ("1.805", "4500")
    bool operator==(const ProfileNote &o) const = default;
};

// What a profile made with another register map (a firmware variant, a model with more axes)
// holds that this map cannot take as it is. Always empty for a profile of this very map: such
// a file must hold exactly this map's settings, or it is refused.
struct ProfileVariance
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ProfileVariance)
public:
    QString fileMap; // the map the file names, "stepper3/1"; empty for this map's own profiles
    QString thisMap; // "stepper2/1"
    QList<ProfileNote> unknown;  // keys this map has no setting for (by key)
    QList<ProfileNote> rejected; // this map's settings whose value it cannot hold (by key)
    QStringList missing;         // this map's settings the file lacks (map order, no link)

    bool isVariant() const { return !fileMap.isEmpty() && fileMap != thisMap; }
    // Nothing is left out: every value of the file fits, every setting of the map is there.
    bool isEmpty() const { return unknown.isEmpty() && rejected.isEmpty() && missing.isEmpty(); }
    // The notes of `key` (unknown or rejected), or nullptr.
    const ProfileNote *note(const QString &key) const;
    // "the profile was made with register map "stepper3/1"; this map is ...", or empty.
    QString describeMaps() const;
    // One line per value left out, for people, in three groups ("unknown to this map:
    // motor3.speed = 300 (...)", "cannot be applied: motor1.speed: 4500 is out of range
    // (1 .. 3000 rpm)", "not in the profile: line.end_x (End X)"); labels in `locale`.
    QStringList describe(const RegisterMap &map, const QString &locale = QString()) const;
    bool operator==(const ProfileVariance &o) const = default;
};

} // namespace stepcom
