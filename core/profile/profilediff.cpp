#include "profile/profilediff.h"

#include "map/registermap.h"

#include <QCoreApplication>

namespace stepcom {

QList<ProfileDifference> ProfileDiff::compare(const RegisterMap &map, const Profile &profile,
                                              const QHash<QString, qint64> &device)
{
    QList<ProfileDifference> rows;
    for (const Parameter *p : Profile::profileParameters(map, true)) {
        ProfileDifference row;
        row.parameter = p;
        row.linkSetting = Profile::isLinkSetting(p->key);
        if (const auto it = device.constFind(p->key); it != device.cend())
            row.device = *it;
        if (const auto it = profile.values.constFind(p->key); it != profile.values.cend())
            row.profile = *it;
        rows << row;
    }
    return rows;
}

QList<ProfileDifference> ProfileDiff::differences(const QList<ProfileDifference> &rows)
{
    QList<ProfileDifference> out;
    for (const ProfileDifference &r : rows) {
        if (r.differs())
            out << r;
    }
    return out;
}

QList<ParameterWrite> ProfileDiff::writesFor(const RegisterMap &map, const Profile &profile,
                                             const QStringList &keys, bool includeLink,
                                             QStringList *errors)
{
    QList<ParameterWrite> writes;
    for (const QString &key : keys) {
        if (!map.find(key) || !profile.values.contains(key)) {
            if (errors)
                errors->append(QCoreApplication::translate("stepcom::ProfileDiff",
                                                           "%1: the profile holds no value")
                                   .arg(key));
        }
    }
    for (const Parameter *p : Profile::profileParameters(map, includeLink)) {
        const auto it = profile.values.constFind(p->key);
        if (keys.contains(p->key) && it != profile.values.cend())
            writes.append({p, *it});
    }
    return writes;
}

QString ProfileDiff::describe(const ProfileDifference &row)
{
    const Parameter &p = *row.parameter;
    const QString device = row.device
                               ? p.displayRaw(*row.device)
                               : QCoreApplication::translate("stepcom::ProfileDiff", "(unknown)");
    const QString profile =
        row.profile ? p.displayRaw(*row.profile)
                    : QCoreApplication::translate("stepcom::ProfileDiff", "(not in the profile)");
    return QStringLiteral("%1: %2 -> %3").arg(p.key, device, profile);
}

} // namespace stepcom
