#include "profile/profilevariance.h"

#include "map/registermap.h"

#include <QLocale>

namespace stepcom {

QString ProfileNote::fileText() const
{
    // The shortest text that reads back as the same number: what a person typed in the file.
    return QString::number(number, 'g', QLocale::FloatingPointShortest);
}

const ProfileNote *ProfileVariance::note(const QString &key) const
{
    for (const QList<ProfileNote> *list : {&unknown, &rejected}) {
        for (const ProfileNote &n : *list) {
            if (n.key == key)
                return &n;
        }
    }
    return nullptr;
}

QString ProfileVariance::describeMaps() const
{
    if (!isVariant())
        return {};
    return tr("the profile was made with register map \"%1\"; this map is \"%2\": only the "
              "settings both have can be applied")
        .arg(fileMap, thisMap);
}

QStringList ProfileVariance::describe(const RegisterMap &map, const QString &locale) const
{
    QStringList lines;
    for (const ProfileNote &n : unknown)
        lines << tr("unknown to this map: %1 = %2 (%3)").arg(n.key, n.fileText(), n.reason);
    for (const ProfileNote &n : rejected)
        lines << tr("cannot be applied: %1").arg(n.reason);
    for (const QString &key : missing) {
        const Parameter *p = map.find(key);
        lines << tr("not in the profile: %1 (%2)").arg(key, p ? p->label.text(locale) : QString());
    }
    return lines;
}

} // namespace stepcom
