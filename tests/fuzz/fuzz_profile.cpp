// Fuzz target: the profile loader (ProfileFile::parse against the built-in map), fed arbitrary
// bytes. Properties: it never crashes or trips a sanitizer; a rejected file says why (at least
// one message, none empty, at most MaxErrors plus the "more" line); an accepted profile only
// holds writable parameters of the map with allowed values, and survives toJson -> parse
// unchanged -- so "Apply" can never be handed a value the controller must not get.

#include "fuzzcheck.h"
#include "map/registermap.h"
#include "profile/profile.h"
#include "profile/profilefile.h"

#include <cstddef>
#include <cstdint>

using namespace stepcom;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const RegisterMap map = RegisterMap::builtin();
    const ProfileParseResult result = ProfileFile::parse(fuzz::bytes(data, size), map);
    if (!result.ok()) {
        STEPCOM_FUZZ_CHECK(!result.errors.isEmpty(), QString());
        STEPCOM_FUZZ_CHECK(result.errors.size() <= ProfileFile::MaxErrors + 1,
                           QString::number(result.errors.size()));
        for (const QString &e : result.errors)
            STEPCOM_FUZZ_CHECK(!e.trimmed().isEmpty(), QString());
        return 0;
    }
    const Profile &p = *result.profile;
    STEPCOM_FUZZ_CHECK(result.errors.isEmpty(), result.errors.join(QLatin1Char('\n')));
    for (auto it = p.values.cbegin(); it != p.values.cend(); ++it) {
        const Parameter *param = map.find(it.key());
        STEPCOM_FUZZ_CHECK(param != nullptr, it.key());
        STEPCOM_FUZZ_CHECK(param->writable(), it.key());
        STEPCOM_FUZZ_CHECK(param->checkRaw(it.value()).isEmpty(), it.key());
    }
    const ProfileParseResult again = ProfileFile::parse(ProfileFile::toJson(p, map), map);
    STEPCOM_FUZZ_CHECK(again.ok(), again.errors.join(QLatin1Char('\n')));
    STEPCOM_FUZZ_CHECK(again.profile->values == p.values, QStringLiteral("values changed"));
    STEPCOM_FUZZ_CHECK(again.profile->name == p.name && again.profile->notes == p.notes,
                       QStringLiteral("metadata changed"));
    return 0;
}
