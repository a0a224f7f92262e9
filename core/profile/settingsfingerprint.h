#pragma once

#include <QHash>
#include <QMap>
#include <QString>

namespace stepcom {

class RegisterMap;

// A stable hash of a controller's settings, so two machines can be compared by one line: the
// map's identity, then every read-write setting of the map that the values hold -- except the
// link (device.id, device.baud), which differs from machine to machine by design -- as
// "key=value" lines in key order, the value as the register's exact decimal text ("1.80");
// SHA-256 of that text. The order of the keys in a file never matters; any value does.
// StepCom's own settings (travel limits) are not controller settings and are not included.
class SettingsFingerprint
{
public:
    static QString canonicalText(const RegisterMap &map, const QMap<QString, qint64> &values);
    // The whole SHA-256, lower-case hex.
    static QString hash(const RegisterMap &map, const QMap<QString, qint64> &values);
    // The first 64 bits, in groups: "3f2a-9c1b-77e0-12ab".
    static QString shortHash(const RegisterMap &map, const QMap<QString, qint64> &values);
    // "stepper2/1 · 55 · 3f2a-9c1b-77e0-12ab" (map, settings counted, hash): the line a report
    // shows, the same in every language.
    static QString line(const RegisterMap &map, const QMap<QString, qint64> &values);

    static QMap<QString, qint64> ordered(const QHash<QString, qint64> &values);
};

} // namespace stepcom
