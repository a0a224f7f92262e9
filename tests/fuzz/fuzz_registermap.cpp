// Fuzz target: the register map loader (RegisterMap::fromJson), fed arbitrary bytes.
// Properties: it never crashes or trips a sanitizer; a rejected map says why (at least one
// non-empty message) and an accepted one has none; whatever it accepts is consistent enough
// for the rest of StepCom to use blindly (keys and addresses index back to their parameter,
// ranges are ordered, every bound is allowed, formats, parses back and survives the wire).

#include "fuzzcheck.h"
#include "map/registermap.h"

#include <QStringList>

#include <cstddef>
#include <cstdint>

using namespace stepcom;

namespace {

void checkHolding(const RegisterMap &map, const Parameter &p)
{
    STEPCOM_FUZZ_CHECK(p.words == 1 || p.words == 2, p.key);
    STEPCOM_FUZZ_CHECK(p.scale == 1 || p.scale == 10 || p.scale == 100 || p.scale == 1000, p.key);
    STEPCOM_FUZZ_CHECK(p.rawMin <= p.rawMax, p.key);
    for (int w = 0; w < p.words; ++w) {
        const Parameter *at = map.holdingAt(quint16(p.address + w));
        STEPCOM_FUZZ_CHECK(at && at->key == p.key, p.key);
    }
    (void)p.registerName();
    (void)p.rangeText();
    if (!p.values.isEmpty()) {
        for (const EnumValue &v : p.values) {
            STEPCOM_FUZZ_CHECK(p.checkRaw(v.value).isEmpty(), p.key);
            STEPCOM_FUZZ_CHECK(p.decode(p.encode(v.value).constData()) == v.value, p.key);
            (void)p.displayRaw(v.value, QStringLiteral("zh_CN"));
        }
        return;
    }
    for (const qint64 raw : {p.rawMin, p.rawMax}) {
        STEPCOM_FUZZ_CHECK(p.checkRaw(raw).isEmpty(), p.key);
        STEPCOM_FUZZ_CHECK(p.decode(p.encode(raw).constData()) == raw,
                           p.key + QLatin1Char(' ') + QString::number(raw));
        const QString text = p.formatRaw(raw);
        QString error;
        const std::optional<qint64> back = p.parse(text, &error);
        STEPCOM_FUZZ_CHECK(back && *back == raw, p.key + QLatin1Char(' ') + text + error);
        (void)p.displayRaw(raw);
        (void)p.fromEngineering(p.toEngineering(raw), &error);
    }
    STEPCOM_FUZZ_CHECK(!p.checkRaw(p.rawMin - 1).isEmpty(), p.key);
    STEPCOM_FUZZ_CHECK(!p.checkRaw(p.rawMax + 1).isEmpty(), p.key);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    // The real map is built in (also in the standalone fuzz build, for the profile target).
    static const bool builtinLoads = RegisterMap::builtin().isValid();
    STEPCOM_FUZZ_CHECK(builtinLoads, QStringLiteral("the built-in map does not load"));
    QStringList errors;
    const std::optional<RegisterMap> map = RegisterMap::fromJson(fuzz::bytes(data, size), &errors);
    for (const QString &e : std::as_const(errors))
        STEPCOM_FUZZ_CHECK(!e.trimmed().isEmpty(), QStringLiteral("an empty error message"));
    if (!map) {
        STEPCOM_FUZZ_CHECK(!errors.isEmpty(), QStringLiteral("rejected without a reason"));
        return 0;
    }
    STEPCOM_FUZZ_CHECK(errors.isEmpty(), errors.join(QLatin1Char('\n')));
    STEPCOM_FUZZ_CHECK(map->isValid(), map->identity());
    STEPCOM_FUZZ_CHECK(map->maxRegistersPerRequest() >= 2 && map->maxRegistersPerRequest() <= 123,
                       map->identity());
    for (const Parameter &p : map->parameters()) {
        const Parameter *byKey = map->find(p.key);
        STEPCOM_FUZZ_CHECK(byKey && byKey->address == p.address && byKey->kind == p.kind, p.key);
        STEPCOM_FUZZ_CHECK(map->group(p.group) != nullptr, p.key);
        STEPCOM_FUZZ_CHECK(
            !p.label.text().isEmpty() && !p.label.text(QStringLiteral("zh_CN")).isEmpty(), p.key);
        if (!p.block.isEmpty()) {
            STEPCOM_FUZZ_CHECK(p.instance >= 1 && p.instance <= map->blockCount(p.block), p.key);
            const Parameter *inBlock = map->blockParameter(p.block, p.instance, p.localKey);
            STEPCOM_FUZZ_CHECK(inBlock && inBlock->key == p.key, p.key);
        }
        if (p.isHolding()) {
            checkHolding(*map, p);
        } else {
            const Parameter *at = map->coilAt(p.address);
            STEPCOM_FUZZ_CHECK(at && at->key == p.key, p.key);
        }
    }
    for (const ParameterGroup &g : map->groups())
        (void)map->inGroup(g.id);
    STEPCOM_FUZZ_CHECK(map->holdings().size() + map->coils().size() == map->parameters().size(),
                       map->identity());
    return 0;
}
