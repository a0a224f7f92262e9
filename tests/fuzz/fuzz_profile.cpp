// Fuzz target: the profile loader (ProfileFile::parse against the built-in map, refusing and
// accepting profiles of other maps), fed arbitrary bytes. Properties: it never crashes or trips
// a sanitizer; a rejected file says why (at least one message, none empty, at most MaxErrors
// plus the "more" line); an accepted profile only holds writable parameters of the map with
// allowed values, names everything else it held (unknown, rejected) and what it lacks, holds
// only travel limits within the position registers (min below max), and survives
// toJson -> parse unchanged -- so "Apply" can never be handed a value the controller
// must not get.

#include "fuzzcheck.h"
#include "map/registermap.h"
#include "profile/profile.h"
#include "profile/profilefile.h"

#include <cstddef>
#include <cstdint>

using namespace stepcom;

namespace {

// The properties of one parse. `otherMaps`: a profile of another map is read with what this
// map knows; then everything the file holds is either a value, or named as unknown or
// rejected, and the settings it lacks are named as missing.
void check(const RegisterMap &map, const QByteArray &bytes, ProfileFile::OtherMaps otherMaps)
{
    const ProfileParseResult result = ProfileFile::parse(bytes, map, otherMaps);
    if (!result.ok()) {
        STEPCOM_FUZZ_CHECK(!result.errors.isEmpty(), QString());
        STEPCOM_FUZZ_CHECK(result.errors.size() <= ProfileFile::MaxErrors + 1,
                           QString::number(result.errors.size()));
        for (const QString &e : result.errors)
            STEPCOM_FUZZ_CHECK(!e.trimmed().isEmpty(), QString());
        return;
    }
    const Profile &p = *result.profile;
    STEPCOM_FUZZ_CHECK(result.errors.isEmpty(), result.errors.join(QLatin1Char('\n')));
    for (auto it = p.values.cbegin(); it != p.values.cend(); ++it) {
        const Parameter *param = map.find(it.key());
        STEPCOM_FUZZ_CHECK(param != nullptr, it.key());
        STEPCOM_FUZZ_CHECK(param->writable(), it.key());
        STEPCOM_FUZZ_CHECK(param->checkRaw(it.value()).isEmpty(), it.key());
    }
    const ProfileVariance &v = p.variance;
    if (otherMaps == ProfileFile::OtherMaps::Refuse || !v.isVariant()) {
        // A profile of this very map fits it exactly: nothing is left out.
        STEPCOM_FUZZ_CHECK(v.isEmpty() && !v.isVariant(), v.describe(map).join(QLatin1Char('\n')));
    }
    for (const ProfileNote &n : v.unknown) {
        const Parameter *param = map.find(n.key);
        STEPCOM_FUZZ_CHECK(!param || !param->writable(), n.key);
        STEPCOM_FUZZ_CHECK(!n.reason.trimmed().isEmpty(), n.key);
    }
    for (const ProfileNote &n : v.rejected) {
        const Parameter *param = map.find(n.key);
        STEPCOM_FUZZ_CHECK(param && param->writable() && !p.values.contains(n.key), n.key);
        STEPCOM_FUZZ_CHECK(!n.reason.trimmed().isEmpty(), n.key);
    }
    for (const QString &key : v.missing) {
        const Parameter *param = map.find(key);
        STEPCOM_FUZZ_CHECK(param && param->writable() && !p.values.contains(key), key);
        STEPCOM_FUZZ_CHECK(v.note(key) == nullptr, key);
    }
    // Saved and read again, nothing changes: neither the values nor what was left out.
    const ProfileParseResult again =
        ProfileFile::parse(ProfileFile::toJson(p, map), map, otherMaps);
    STEPCOM_FUZZ_CHECK(again.ok(), again.errors.join(QLatin1Char('\n')));
    STEPCOM_FUZZ_CHECK(again.profile->values == p.values, QStringLiteral("values changed"));
    STEPCOM_FUZZ_CHECK(again.profile->variance == p.variance, QStringLiteral("variance changed"));
    STEPCOM_FUZZ_CHECK(again.profile->name == p.name && again.profile->notes == p.notes,
                       QStringLiteral("metadata changed"));
    // StepCom's own settings and a backup's origin survive too; accepted limits are usable.
    STEPCOM_FUZZ_CHECK(again.profile->travelLimits == p.travelLimits,
                       QStringLiteral("travel limits changed"));
    STEPCOM_FUZZ_CHECK(again.profile->backupOperation == p.backupOperation &&
                           again.profile->backupDevice == p.backupDevice,
                       QStringLiteral("backup metadata changed"));
    for (auto it = p.travelLimits.axes().cbegin(); it != p.travelLimits.axes().cend(); ++it) {
        const Parameter *position = TravelLimits::positionParameter(map, it.key());
        STEPCOM_FUZZ_CHECK(position && !it->isEmpty(), QString::number(it.key()));
        STEPCOM_FUZZ_CHECK(!it->min || !it->max || *it->min < *it->max, QString::number(it.key()));
        for (const auto &end : {it->min, it->max})
            STEPCOM_FUZZ_CHECK(!end || position->checkRaw(*end).isEmpty(),
                               QString::number(it.key()));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const RegisterMap map = RegisterMap::builtin();
    const QByteArray bytes = fuzz::bytes(data, size);
    check(map, bytes, ProfileFile::OtherMaps::Refuse);
    check(map, bytes, ProfileFile::OtherMaps::Accept);
    // Accepting other maps changes nothing for a profile of this map.
    const ProfileParseResult strict = ProfileFile::parse(bytes, map);
    const ProfileParseResult lenient =
        ProfileFile::parse(bytes, map, ProfileFile::OtherMaps::Accept);
    if (strict.ok()) {
        STEPCOM_FUZZ_CHECK(lenient.ok() && lenient.profile->values == strict.profile->values &&
                               lenient.profile->variance.isEmpty(),
                           QStringLiteral("accepting other maps changed a profile of this map"));
    }
    return 0;
}
