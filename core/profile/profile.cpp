#include "profile/profile.h"

#include "map/registermap.h"

namespace stepcom {

bool Profile::isLinkSetting(const QString &key)
{
    return key == QLatin1String("device.id") || key == QLatin1String("device.baud");
}

QList<const Parameter *> Profile::profileParameters(const RegisterMap &map, bool withLink)
{
    QList<const Parameter *> out;
    for (const Parameter &p : map.parameters()) {
        if (p.writable() && (withLink || !isLinkSetting(p.key)))
            out << &p;
    }
    return out;
}

Profile Profile::fromValues(const RegisterMap &map, const QHash<QString, qint64> &raw,
                            bool withLink)
{
    Profile profile;
    profile.mapId = map.id();
    profile.mapVersion = map.version();
    profile.created = QDateTime::currentDateTimeUtc();
    profile.created.setTime(QTime(profile.created.time().hour(), profile.created.time().minute(),
                                  profile.created.time().second()));
    profile.stepcomVersion = QStringLiteral(STEPCOM_VERSION);
    for (const Parameter *p : profileParameters(map, withLink)) {
        const auto it = raw.constFind(p->key);
        if (it != raw.cend())
            profile.values.insert(p->key, *it);
    }
    if (const auto id = raw.constFind(QStringLiteral("device.id")); id != raw.cend())
        profile.deviceId = int(*id);
    if (const auto baud = raw.constFind(QStringLiteral("device.baud")); baud != raw.cend())
        profile.baud = int(*baud);
    return profile;
}

} // namespace stepcom
