#include "profile/profilecomparison.h"

#include "map/registermap.h"

namespace stepcom {

namespace {

// The profile's value of `key` in engineering units: a valid one, or one this map cannot take.
std::optional<double> fileNumber(const RegisterMap &map, const Profile &p, const QString &key)
{
    if (const auto it = p.values.constFind(key); it != p.values.cend()) {
        if (const Parameter *param = map.find(key))
            return param->toEngineering(*it);
    }
    if (const ProfileNote *n = p.variance.note(key))
        return n->number;
    return std::nullopt;
}

} // namespace

ProfileComparison ProfileComparison::compare(const RegisterMap &map, const Profile &a,
                                             const Profile &b)
{
    ProfileComparison c;
    QHash<QString, qint64> left;
    for (auto it = a.values.cbegin(); it != a.values.cend(); ++it)
        left.insert(it.key(), it.value());
    c.rows = ProfileDiff::compare(map, b, left);

    QMap<QString, QString> reasons; // by key: the foreign rows, sorted
    for (const Profile *p : {&a, &b}) {
        for (const QList<ProfileNote> *notes : {&p->variance.unknown, &p->variance.rejected}) {
            for (const ProfileNote &n : *notes) {
                if (!reasons.contains(n.key))
                    reasons.insert(n.key, n.reason);
            }
        }
    }
    for (auto it = reasons.cbegin(); it != reasons.cend(); ++it)
        c.foreign.append(
            {it.key(), fileNumber(map, a, it.key()), fileNumber(map, b, it.key()), it.value()});
    return c;
}

bool ProfileComparison::isForeign(const QString &key) const
{
    return std::any_of(foreign.cbegin(), foreign.cend(),
                       [&](const ProfileForeignRow &f) { return f.key == key; });
}

QList<ProfileDifference> ProfileComparison::differing() const
{
    return ProfileDiff::differences(rows);
}

QList<ProfileDifference> ProfileComparison::same() const
{
    QList<ProfileDifference> out;
    for (const ProfileDifference &r : rows) {
        if (r.device && r.profile && r.device == r.profile)
            out << r;
    }
    return out;
}

QList<ProfileDifference> ProfileComparison::onlyInA() const
{
    QList<ProfileDifference> out;
    for (const ProfileDifference &r : rows) {
        if (r.device && !r.profile && !isForeign(r.parameter->key))
            out << r;
    }
    return out;
}

QList<ProfileDifference> ProfileComparison::onlyInB() const
{
    QList<ProfileDifference> out;
    for (const ProfileDifference &r : rows) {
        if (!r.device && r.profile && !isForeign(r.parameter->key))
            out << r;
    }
    return out;
}

QList<ProfileForeignRow> ProfileComparison::foreignDiffering() const
{
    QList<ProfileForeignRow> out;
    for (const ProfileForeignRow &f : foreign) {
        if (f.differs())
            out << f;
    }
    return out;
}

bool ProfileComparison::identical() const
{
    return differing().isEmpty() && onlyInA().isEmpty() && onlyInB().isEmpty() &&
           foreignDiffering().isEmpty();
}

} // namespace stepcom
