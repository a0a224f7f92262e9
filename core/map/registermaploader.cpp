#include "map/registermaploader.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>

namespace stepcom {

namespace {

const QString kFormat = QStringLiteral("stepcom-register-map");

// Beyond 2^53 a double no longer holds every whole number, and beyond 2^63 converting it to an
// integer is undefined; no number in a map comes anywhere near.
constexpr double kLargestWhole = 9007199254740992.0; // 2^53

bool isWholeNumber(const QJsonValue &v)
{
    if (!v.isDouble())
        return false;
    const double d = v.toDouble();
    return std::fabs(d) <= kLargestWhole && d == std::trunc(d);
}

// A number from the map times its scale as a raw value, saturated far beyond any register's
// width (so 1e300 is "does not fit", never an undefined conversion).
qint64 scaledRaw(const QJsonValue &v, int scale)
{
    const double d = v.toDouble() * scale;
    if (!(std::fabs(d) <= kLargestWhole)) // NaN included
        return d < 0 ? -qint64(kLargestWhole) : qint64(kLargestWhole);
    return qint64(std::llround(d));
}

QString hex(quint16 a)
{
    return QStringLiteral("0x") +
           QString::number(a, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

} // namespace

std::optional<RegisterMap> RegisterMapLoader::load(const QByteArray &json, QStringList *errors)
{
    QStringList local;
    RegisterMapLoader loader(errors ? errors : &local);
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // Line and column help far more than a byte offset when editing by hand.
        const QByteArray head = json.left(parseError.offset);
        const int line = int(head.count('\n')) + 1;
        const int column = int(parseError.offset - (head.lastIndexOf('\n') + 1)) + 1;
        loader.error({}, {},
                     QStringLiteral("invalid JSON at line %1, column %2: %3")
                         .arg(line)
                         .arg(column)
                         .arg(parseError.errorString()));
        return std::nullopt;
    }
    if (!doc.isObject()) {
        loader.error({}, {}, QStringLiteral("the map must be a JSON object"));
        return std::nullopt;
    }
    if (!loader.loadTop(doc.object()))
        return std::nullopt;
    loader.index();
    if (loader.m_errorCount > 0)
        return std::nullopt;
    return loader.m_map;
}

void RegisterMapLoader::error(const QString &where, const QString &field, const QString &message)
{
    ++m_errorCount;
    QString prefix = where;
    if (!field.isEmpty())
        prefix += (prefix.isEmpty() ? QString() : QStringLiteral(", ")) +
                  QStringLiteral("field '%1'").arg(field);
    *m_errors << (prefix.isEmpty() ? message : prefix + QStringLiteral(": ") + message);
}

void RegisterMapLoader::unknownFields(const QJsonObject &o, const QStringList &allowed,
                                      const QString &where)
{
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!allowed.contains(it.key()))
            error(where, it.key(), QStringLiteral("unknown field"));
    }
}

std::optional<LocalizedText> RegisterMapLoader::text(const QJsonObject &o, const QString &field,
                                                     const QString &where, bool required, int n)
{
    const QJsonValue v = o.value(field);
    if (v.isUndefined()) {
        if (required)
            error(where, field, QStringLiteral("missing"));
        return std::nullopt;
    }
    if (!v.isObject()) {
        error(where, field, QStringLiteral("must be an object with \"en\" and \"zh_CN\""));
        return std::nullopt;
    }
    const QJsonObject t = v.toObject();
    unknownFields(t, {QStringLiteral("en"), QStringLiteral("zh_CN")}, where);
    LocalizedText out;
    out.en = t.value(QStringLiteral("en")).toString();
    out.zh = t.value(QStringLiteral("zh_CN")).toString();
    if (out.en.trimmed().isEmpty())
        error(where, field, QStringLiteral("the English text is missing"));
    if (out.zh.trimmed().isEmpty())
        error(where, field, QStringLiteral("the Chinese (zh_CN) text is missing"));
    const QString number = QString::number(n);
    out.en.replace(QLatin1String("{n}"), number);
    out.zh.replace(QLatin1String("{n}"), number);
    return out;
}

bool RegisterMapLoader::loadTop(const QJsonObject &top)
{
    unknownFields(top,
                  {QStringLiteral("format"), QStringLiteral("schema"), QStringLiteral("id"),
                   QStringLiteral("version"), QStringLiteral("name"), QStringLiteral("limits"),
                   QStringLiteral("groups"), QStringLiteral("enums"), QStringLiteral("blocks"),
                   QStringLiteral("entries")},
                  QStringLiteral("map"));
    if (top.value(QStringLiteral("format")).toString() != kFormat) {
        error(QStringLiteral("map"), QStringLiteral("format"),
              QStringLiteral("must be \"%1\"").arg(kFormat));
        return false;
    }
    if (top.value(QStringLiteral("schema")).toInt(-1) != 1) {
        error(QStringLiteral("map"), QStringLiteral("schema"),
              QStringLiteral("unsupported schema version (this StepCom reads 1)"));
        return false;
    }
    m_map.m_id = top.value(QStringLiteral("id")).toString();
    static const QRegularExpression idPattern(QStringLiteral("^[a-z0-9_.-]+$"));
    if (!idPattern.match(m_map.m_id).hasMatch())
        error(QStringLiteral("map"), QStringLiteral("id"),
              QStringLiteral("must be lower-case letters, digits, '_', '.' or '-'"));
    const QJsonValue version = top.value(QStringLiteral("version"));
    if (!isWholeNumber(version) || version.toInt() < 1)
        error(QStringLiteral("map"), QStringLiteral("version"),
              QStringLiteral("must be a whole number of at least 1"));
    m_map.m_version = version.toInt();
    if (auto name = text(top, QStringLiteral("name"), QStringLiteral("map"), true))
        m_map.m_name = *name;

    const QJsonObject limits = top.value(QStringLiteral("limits")).toObject();
    unknownFields(limits,
                  {QStringLiteral("maxRegistersPerRequest"), QStringLiteral("answerDelayMs")},
                  QStringLiteral("limits"));
    m_map.m_maxRegisters = limits.value(QStringLiteral("maxRegistersPerRequest")).toInt(49);
    if (m_map.m_maxRegisters < 2 || m_map.m_maxRegisters > 123)
        error(QStringLiteral("limits"), QStringLiteral("maxRegistersPerRequest"),
              QStringLiteral("must be between 2 and 123"));
    m_map.m_answerDelayMs = limits.value(QStringLiteral("answerDelayMs")).toInt(35);
    if (m_map.m_answerDelayMs < 0 || m_map.m_answerDelayMs > 10000)
        error(QStringLiteral("limits"), QStringLiteral("answerDelayMs"),
              QStringLiteral("must be between 0 and 10000"));

    loadGroups(top.value(QStringLiteral("groups")));
    loadEnums(top.value(QStringLiteral("enums")));

    const QJsonArray blocks = top.value(QStringLiteral("blocks")).toArray();
    for (int i = 0; i < blocks.size(); ++i)
        loadBlock(blocks.at(i).toObject(), i);
    const QJsonValue entries = top.value(QStringLiteral("entries"));
    if (!entries.isUndefined() && !entries.isArray())
        error(QStringLiteral("map"), QStringLiteral("entries"), QStringLiteral("must be an array"));
    const QJsonArray list = entries.toArray();
    for (int i = 0; i < list.size(); ++i) {
        if (!list.at(i).isObject()) {
            error(QStringLiteral("entries[%1]").arg(i), {}, QStringLiteral("must be an object"));
            continue;
        }
        const QJsonObject e = list.at(i).toObject();
        const QString key = e.value(QStringLiteral("key")).toString();
        const QString where = key.isEmpty() ? QStringLiteral("entries[%1]").arg(i)
                                            : QStringLiteral("entry '%1'").arg(key);
        loadEntry(e, where, QString(), 0, 0);
    }
    if (m_map.m_params.isEmpty())
        error(QStringLiteral("map"), {}, QStringLiteral("defines no registers or coils"));
    return true;
}

void RegisterMapLoader::loadGroups(const QJsonValue &value)
{
    if (!value.isArray()) {
        error(QStringLiteral("map"), QStringLiteral("groups"), QStringLiteral("must be an array"));
        return;
    }
    const QJsonArray groups = value.toArray();
    for (int i = 0; i < groups.size(); ++i) {
        const QJsonObject g = groups.at(i).toObject();
        const QString where = QStringLiteral("groups[%1]").arg(i);
        unknownFields(g, {QStringLiteral("id"), QStringLiteral("label")}, where);
        ParameterGroup group;
        group.id = g.value(QStringLiteral("id")).toString();
        if (group.id.isEmpty())
            error(where, QStringLiteral("id"), QStringLiteral("missing"));
        if (auto label = text(g, QStringLiteral("label"), where, true))
            group.label = *label;
        m_map.m_groups << group;
    }
}

void RegisterMapLoader::loadEnums(const QJsonValue &value)
{
    if (value.isUndefined())
        return;
    const QJsonObject enums = value.toObject();
    for (auto it = enums.begin(); it != enums.end(); ++it) {
        const QString where = QStringLiteral("enum '%1'").arg(it.key());
        const QJsonArray items = it.value().toArray();
        if (items.isEmpty())
            error(where, {}, QStringLiteral("must be a non-empty array"));
        QList<EnumValue> values;
        for (int i = 0; i < items.size(); ++i) {
            const QJsonObject item = items.at(i).toObject();
            const QString itemWhere = where + QStringLiteral("[%1]").arg(i);
            unknownFields(item, {QStringLiteral("value"), QStringLiteral("label")}, itemWhere);
            EnumValue v;
            if (!isWholeNumber(item.value(QStringLiteral("value"))))
                error(itemWhere, QStringLiteral("value"), QStringLiteral("must be a whole number"));
            else
                v.value = qint64(item.value(QStringLiteral("value")).toDouble());
            if (auto label = text(item, QStringLiteral("label"), itemWhere, true))
                v.label = *label;
            values << v;
        }
        m_enums.insert(it.key(), values);
    }
}

void RegisterMapLoader::loadBlock(const QJsonObject &block, int index)
{
    const QString prefix = block.value(QStringLiteral("prefix")).toString();
    const QString where =
        QStringLiteral("block '%1'").arg(prefix.isEmpty() ? QString::number(index) : prefix);
    unknownFields(block,
                  {QStringLiteral("prefix"), QStringLiteral("count"), QStringLiteral("label"),
                   QStringLiteral("entries")},
                  where);
    static const QRegularExpression prefixPattern(QStringLiteral("^[a-z][a-z_]*$"));
    if (!prefixPattern.match(prefix).hasMatch()) {
        error(where, QStringLiteral("prefix"), QStringLiteral("must be lower-case letters or '_'"));
        return;
    }
    const QJsonValue countValue = block.value(QStringLiteral("count"));
    const int count = countValue.toInt(0);
    if (!isWholeNumber(countValue) || count < 1 || count > 32) {
        error(where, QStringLiteral("count"),
              QStringLiteral("must be a whole number from 1 to 32"));
        return;
    }
    text(block, QStringLiteral("label"), where, true, 1);
    m_map.m_blockCounts.insert(prefix, count);
    const QJsonArray entries = block.value(QStringLiteral("entries")).toArray();
    for (int n = 1; n <= count; ++n) {
        for (int i = 0; i < entries.size(); ++i) {
            const QJsonObject e = entries.at(i).toObject();
            const QString key = prefix + QString::number(n) + QLatin1Char('.') +
                                e.value(QStringLiteral("key")).toString();
            loadEntry(e, QStringLiteral("entry '%1'").arg(key), prefix, n, count);
        }
    }
}

void RegisterMapLoader::loadEntry(const QJsonObject &e, const QString &where, const QString &prefix,
                                  int n, int count)
{
    const int before = m_errorCount;
    Parameter p;
    const QString kind = e.value(QStringLiteral("kind")).toString();
    if (kind == QLatin1String("holding")) {
        p.kind = Kind::Holding;
    } else if (kind == QLatin1String("coil")) {
        p.kind = Kind::Coil;
    } else {
        error(where, QStringLiteral("kind"),
              kind.isEmpty()
                  ? QStringLiteral("missing (\"holding\" or \"coil\")")
                  : QStringLiteral("unknown kind '%1' (\"holding\" or \"coil\")").arg(kind));
        return;
    }
    QStringList allowed{QStringLiteral("key"),   QStringLiteral("kind"),  QStringLiteral("plc"),
                        QStringLiteral("group"), QStringLiteral("label"), QStringLiteral("help")};
    if (!prefix.isEmpty())
        allowed << QStringLiteral("stride");
    if (p.isHolding())
        allowed << QStringLiteral("words") << QStringLiteral("signed") << QStringLiteral("scale")
                << QStringLiteral("unit") << QStringLiteral("min") << QStringLiteral("max")
                << QStringLiteral("enum") << QStringLiteral("access");
    else
        allowed << QStringLiteral("command");
    unknownFields(e, allowed, where);

    p.localKey = e.value(QStringLiteral("key")).toString();
    static const QRegularExpression localPattern(QStringLiteral("^[a-z0-9_]+$"));
    static const QRegularExpression fullPattern(QStringLiteral("^[a-z0-9_]+(\\.[a-z0-9_]+)?$"));
    if (!(prefix.isEmpty() ? fullPattern : localPattern).match(p.localKey).hasMatch())
        error(where, QStringLiteral("key"),
              p.localKey.isEmpty() ? QStringLiteral("missing")
                                   : QStringLiteral("must be lower-case letters, digits or '_'"));
    p.key =
        prefix.isEmpty() ? p.localKey : prefix + QString::number(n) + QLatin1Char('.') + p.localKey;
    p.block = prefix;
    p.instance = n;

    const QJsonValue plcValue = e.value(QStringLiteral("plc"));
    int stride = 0;
    if (!prefix.isEmpty()) {
        const QJsonValue s = e.value(QStringLiteral("stride"));
        if (count > 1 && (!isWholeNumber(s) || s.toInt() < 1))
            error(where, QStringLiteral("stride"),
                  QStringLiteral("must be a whole number of at least 1 in a block"));
        stride = s.toInt(0);
    }
    if (!isWholeNumber(plcValue)) {
        error(where, QStringLiteral("plc"), QStringLiteral("missing or not a whole number"));
        return;
    }
    // In 64 bits: a large plc or stride must give "outside", not an overflow.
    const qint64 plc = qint64(plcValue.toDouble()) + (n > 0 ? qint64(n - 1) * stride : 0);
    const int base = p.isHolding() ? 40001 : 1;
    const int last = p.isHolding() ? 49999 : 9999;
    if (plc < base || plc > last) {
        error(where, QStringLiteral("plc"),
              QStringLiteral("%1 is outside %2-%3 for a %4")
                  .arg(plc)
                  .arg(base, 5, 10, QLatin1Char('0'))
                  .arg(last, 5, 10, QLatin1Char('0'))
                  .arg(kind));
        return;
    }
    p.plc = int(plc);
    p.address = quint16(p.plc - base);

    p.group = e.value(QStringLiteral("group")).toString();
    if (p.group.isEmpty())
        error(where, QStringLiteral("group"), QStringLiteral("missing"));
    else if (!m_map.group(p.group))
        error(where, QStringLiteral("group"), QStringLiteral("unknown group '%1'").arg(p.group));
    if (auto label = text(e, QStringLiteral("label"), where, true, n))
        p.label = *label;
    if (auto help = text(e, QStringLiteral("help"), where, true, n))
        p.help = *help;

    if (p.isCoil()) {
        p.access = Access::Command;
        p.words = 1;
        static const QHash<QString, CommandClass> classes{
            {QStringLiteral("emergency"), CommandClass::Emergency},
            {QStringLiteral("motion"), CommandClass::Motion},
            {QStringLiteral("output"), CommandClass::Output},
            {QStringLiteral("setting"), CommandClass::Setting},
            {QStringLiteral("destructive"), CommandClass::Destructive}};
        const QString c = e.value(QStringLiteral("command")).toString();
        if (!classes.contains(c))
            error(where, QStringLiteral("command"),
                  QStringLiteral("must be one of emergency, motion, output, setting, destructive"));
        p.command = classes.value(c, CommandClass::None);
    } else {
        const QJsonValue words = e.value(QStringLiteral("words"));
        p.words = words.isUndefined() ? 1 : (isWholeNumber(words) ? words.toInt() : -1);
        if (p.words != 1 && p.words != 2)
            error(where, QStringLiteral("words"),
                  QStringLiteral("must be 1 or 2, got %1").arg(words.toVariant().toString()));
        p.isSigned = e.value(QStringLiteral("signed")).toBool(false);
        const QJsonValue scale = e.value(QStringLiteral("scale"));
        p.scale = scale.isUndefined() ? 1 : scale.toInt(-1);
        if (p.scale != 1 && p.scale != 10 && p.scale != 100 && p.scale != 1000)
            error(where, QStringLiteral("scale"), QStringLiteral("must be 1, 10, 100 or 1000"));
        p.unit = e.value(QStringLiteral("unit")).toString();
        const QString access = e.value(QStringLiteral("access")).toString();
        if (access == QLatin1String("r"))
            p.access = Access::ReadOnly;
        else if (access == QLatin1String("rw"))
            p.access = Access::ReadWrite;
        else
            error(where, QStringLiteral("access"), QStringLiteral("must be \"r\" or \"rw\""));

        const int bits = 16 * std::clamp(p.words, 1, 2);
        const qint64 widthMin = p.isSigned ? -(qint64(1) << (bits - 1)) : 0;
        const qint64 widthMax =
            p.isSigned ? (qint64(1) << (bits - 1)) - 1 : (qint64(1) << bits) - 1;
        p.enumName = e.value(QStringLiteral("enum")).toString();
        if (!p.enumName.isEmpty()) {
            if (!m_enums.contains(p.enumName))
                error(where, QStringLiteral("enum"),
                      QStringLiteral("unknown enum '%1'").arg(p.enumName));
            p.values = m_enums.value(p.enumName);
            p.rawMin = widthMax;
            p.rawMax = widthMin;
            for (const EnumValue &v : std::as_const(p.values)) {
                if (v.value < widthMin || v.value > widthMax)
                    error(where, QStringLiteral("enum"),
                          QStringLiteral("value %1 does not fit %2 bits").arg(v.value).arg(bits));
                p.rawMin = std::min(p.rawMin, v.value);
                p.rawMax = std::max(p.rawMax, v.value);
            }
        } else {
            const QJsonValue minV = e.value(QStringLiteral("min"));
            const QJsonValue maxV = e.value(QStringLiteral("max"));
            if (!minV.isDouble())
                error(where, QStringLiteral("min"), QStringLiteral("missing (or give an enum)"));
            if (!maxV.isDouble())
                error(where, QStringLiteral("max"), QStringLiteral("missing (or give an enum)"));
            p.rawMin = scaledRaw(minV, p.scale);
            p.rawMax = scaledRaw(maxV, p.scale);
            if (minV.isDouble() && maxV.isDouble()) {
                if (p.rawMin > p.rawMax)
                    error(where, QStringLiteral("min"), QStringLiteral("is greater than max"));
                if (p.rawMin < widthMin)
                    error(
                        where, QStringLiteral("min"),
                        QStringLiteral("does not fit %1 %2 bits")
                            .arg(p.isSigned ? QStringLiteral("signed") : QStringLiteral("unsigned"))
                            .arg(bits));
                if (p.rawMax > widthMax)
                    error(
                        where, QStringLiteral("max"),
                        QStringLiteral("does not fit %1 %2 bits")
                            .arg(p.isSigned ? QStringLiteral("signed") : QStringLiteral("unsigned"))
                            .arg(bits));
            }
        }
        if (p.isHolding() && p.address + p.words - 1 > 0xFFFF)
            error(where, QStringLiteral("plc"), QStringLiteral("runs past the last address"));
    }
    if (m_errorCount == before)
        m_map.m_params << p;
}

void RegisterMapLoader::index()
{
    std::stable_sort(m_map.m_params.begin(), m_map.m_params.end(),
                     [](const Parameter &a, const Parameter &b) {
                         if (a.kind != b.kind)
                             return a.kind == Kind::Holding;
                         return a.address < b.address;
                     });
    for (int i = 0; i < m_map.m_params.size(); ++i) {
        const Parameter &p = m_map.m_params.at(i);
        if (m_map.m_byKey.contains(p.key)) {
            error(QStringLiteral("entry '%1'").arg(p.key), QStringLiteral("key"),
                  QStringLiteral("defined twice"));
            continue;
        }
        m_map.m_byKey.insert(p.key, i);
        auto &byAddress = p.isHolding() ? m_map.m_holdingByAddress : m_map.m_coilByAddress;
        for (int w = 0; w < (p.isHolding() ? p.words : 1); ++w) {
            const auto a = quint16(p.address + w);
            if (byAddress.contains(a)) {
                const Parameter &other = m_map.m_params.at(byAddress.value(a));
                error(QStringLiteral("entry '%1'").arg(p.key), {},
                      QStringLiteral("address %1 overlaps '%2' (%3)")
                          .arg(hex(a), other.key, other.registerName()));
                break;
            }
            byAddress.insert(a, i);
        }
    }
}

} // namespace stepcom
