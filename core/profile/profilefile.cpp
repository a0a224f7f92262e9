#include "profile/profilefile.h"

#include "map/registermap.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSet>

#include <cmath>

namespace stepcom {

namespace {

const QString kFormat = QStringLiteral("stepcom-profile");

QString typeName(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
        return ProfileFile::tr("null");
    case QJsonValue::Bool:
        return ProfileFile::tr("true/false");
    case QJsonValue::Double:
        return ProfileFile::tr("a number");
    case QJsonValue::String:
        return ProfileFile::tr("a text \"%1\"").arg(v.toString().left(40));
    case QJsonValue::Array:
        return ProfileFile::tr("a list");
    case QJsonValue::Object:
        return ProfileFile::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return ProfileFile::tr("nothing");
}

// A whole number that fits an int, or nullopt.
std::optional<int> wholeNumber(const QJsonValue &v)
{
    if (!v.isDouble())
        return std::nullopt;
    const double d = v.toDouble();
    if (!std::isfinite(d) || d != std::floor(d) || d < -2147483648.0 || d > 2147483647.0)
        return std::nullopt;
    return int(d);
}

// QJsonDocument keeps one of two equal keys silently; a profile with a key twice is ambiguous,
// so this walks the (already valid) JSON text and reports every object key seen twice.
QStringList duplicateKeys(const QByteArray &bytes)
{
    struct Frame
    {
        bool object = false;
        bool expectKey = false;
        QString name; // the key this object or array is the value of
        QSet<QString> keys;
    };
    QStringList found;
    QList<Frame> stack;
    QString lastKey;
    const qsizetype n = bytes.size();
    for (qsizetype i = 0; i < n; ++i) {
        const char c = bytes.at(i);
        if (c == '{' || c == '[') {
            Frame f;
            f.object = c == '{';
            f.expectKey = f.object;
            f.name = lastKey;
            stack.append(f);
            lastKey.clear();
        } else if (c == '}' || c == ']') {
            if (!stack.isEmpty())
                stack.removeLast();
        } else if (c == ',') {
            if (!stack.isEmpty() && stack.last().object)
                stack.last().expectKey = true;
        } else if (c == '"') {
            const qsizetype start = i;
            for (++i; i < n && bytes.at(i) != '"'; ++i) {
                if (bytes.at(i) == '\\')
                    ++i;
            }
            if (stack.isEmpty() || !stack.last().object || !stack.last().expectKey)
                continue;
            stack.last().expectKey = false;
            const QByteArray raw = bytes.mid(start, i - start + 1);
            const QString key = QJsonDocument::fromJson("[" + raw + "]").array().at(0).toString();
            lastKey = key;
            if (stack.last().keys.contains(key)) {
                const QString where = stack.last().name;
                found << (where.isEmpty()
                              ? ProfileFile::tr("the key \"%1\" appears more than once").arg(key)
                              : ProfileFile::tr("\"%1\": the key \"%2\" appears more than once")
                                    .arg(where, key));
            } else {
                stack.last().keys.insert(key);
            }
        }
    }
    return found;
}

class Parser
{
public:
    Parser(const RegisterMap &map, ProfileFile::OtherMaps otherMaps)
        : m_map(map)
        , m_acceptOtherMaps(otherMaps == ProfileFile::OtherMaps::Accept)
    {}

    ProfileParseResult run(const QByteArray &bytes)
    {
        ProfileParseResult result;
        if (bytes.trimmed().isEmpty()) {
            result.errors << ProfileFile::tr("the file is empty");
            return result;
        }
        if (bytes.size() > ProfileFile::MaxBytes) {
            result.errors << ProfileFile::tr("the file is %1 bytes: far too large for a profile")
                                 .arg(bytes.size());
            return result;
        }
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
        if (parseError.error != QJsonParseError::NoError) {
            int line = 0;
            int column = 0;
            // Qt's offset is just past the character it could not take; people count that
            // character itself.
            ProfileFile::lineColumn(bytes, parseError.offset - 1, &line, &column);
            result.errors << ProfileFile::tr("not valid JSON at line %1, column %2: %3")
                                 .arg(line)
                                 .arg(column)
                                 .arg(parseError.errorString());
            return result;
        }
        if (!doc.isObject()) {
            result.errors << ProfileFile::tr("the file holds a JSON list, not a profile object");
            return result;
        }
        m_errors = duplicateKeys(bytes);
        Profile profile;
        readTop(doc.object(), &profile);
        if (m_errors.size() > ProfileFile::MaxErrors) {
            const qsizetype more = m_errors.size() - ProfileFile::MaxErrors;
            m_errors = m_errors.mid(0, ProfileFile::MaxErrors);
            m_errors << ProfileFile::tr("… and %1 more problems").arg(more);
        }
        result.errors = m_errors;
        profile.variance = m_variance;
        if (m_errors.isEmpty())
            result.profile = profile;
        return result;
    }

private:
    void unknownFields(const QJsonObject &o, const QStringList &allowed, const QString &where)
    {
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (!allowed.contains(it.key()))
                m_errors << (where.isEmpty()
                                 ? ProfileFile::tr("unknown field \"%1\" (allowed: %2)")
                                       .arg(it.key(), allowed.join(QLatin1String(", ")))
                                 : ProfileFile::tr("\"%1\": unknown field \"%2\" (allowed: %3)")
                                       .arg(where, it.key(), allowed.join(QLatin1String(", "))));
        }
    }

    void readTop(const QJsonObject &top, Profile *profile)
    {
        const QJsonValue format = top.value(QLatin1String("format"));
        if (format.toString() != kFormat) {
            if (format.toString() == QLatin1String("stepcom-register-map"))
                m_errors << ProfileFile::tr("this is a register map, not a profile");
            else
                m_errors << ProfileFile::tr(
                                "not a StepCom profile: \"format\" must be \"%1\", found %2")
                                .arg(kFormat, typeName(format));
            return; // nothing else in it can be trusted
        }
        const auto schema = wholeNumber(top.value(QLatin1String("schema")));
        if (!schema) {
            m_errors << ProfileFile::tr("\"schema\" must be a whole number, found %1")
                            .arg(typeName(top.value(QLatin1String("schema"))));
            return;
        }
        if (*schema < ProfileFile::FirstSchema || *schema > ProfileFile::Schema) {
            m_errors << (*schema > ProfileFile::Schema
                             ? ProfileFile::tr(
                                   "profile schema %1 is newer than this StepCom reads (%2): "
                                   "update StepCom")
                                   .arg(*schema)
                                   .arg(ProfileFile::Schema)
                             : ProfileFile::tr(
                                   "profile schema %1 is unknown (this StepCom reads %2)")
                                   .arg(*schema)
                                   .arg(ProfileFile::Schema));
            return;
        }
        m_schema = *schema;
        QStringList fields{QStringLiteral("format"), QStringLiteral("schema"),
                           QStringLiteral("map"), QStringLiteral("metadata"),
                           QStringLiteral("values")};
        if (m_schema >= 2)
            fields << QStringLiteral("stepcom");
        unknownFields(top, fields, QString());
        if (!readMap(top.value(QLatin1String("map")), profile))
            return; // values of another map would only give misleading messages
        readMetadata(top.value(QLatin1String("metadata")), profile);
        readValues(top.value(QLatin1String("values")), profile);
        if (m_schema >= 2 && top.contains(QLatin1String("stepcom")))
            readStepcom(top.value(QLatin1String("stepcom")), profile);
    }

    // StepCom's own settings (schema 2): {"travelLimits": {...}}.
    void readStepcom(const QJsonValue &value, Profile *profile)
    {
        if (!value.isObject()) {
            m_errors
                << ProfileFile::tr("\"stepcom\" must be an object, found %1").arg(typeName(value));
            return;
        }
        const QJsonObject o = value.toObject();
        unknownFields(o, {QStringLiteral("travelLimits")}, QStringLiteral("stepcom"));
        if (!o.contains(QLatin1String("travelLimits")))
            return;
        QStringList errors;
        if (auto limits =
                TravelLimits::fromJson(o.value(QLatin1String("travelLimits")), m_map, &errors))
            profile->travelLimits = *limits;
        for (const QString &e : std::as_const(errors))
            m_errors << QStringLiteral("\"stepcom\": ") + e;
    }

    // A backup's origin (schema 2): {"operation": "apply", "device": "/dev/ttyUSB0 …"}.
    void readBackup(const QJsonValue &value, Profile *profile)
    {
        static const QStringList operations{
            QStringLiteral("apply"), QStringLiteral("factory-reset"),
            QStringLiteral("save-to-flash"), QStringLiteral("device-id"), QStringLiteral("baud")};
        const QJsonObject o = value.toObject();
        unknownFields(o, {QStringLiteral("operation"), QStringLiteral("device")},
                      QStringLiteral("metadata.backup"));
        const QString operation = o.value(QLatin1String("operation")).toString();
        if (!value.isObject() || !operations.contains(operation))
            m_errors << ProfileFile::tr("\"metadata\": \"backup\" must be {\"operation\": one of "
                                        "%1, \"device\": text}")
                            .arg(operations.join(QLatin1String(", ")));
        else if (const QJsonValue d = o.value(QLatin1String("device"));
                 !d.isUndefined() && (!d.isString() || d.toString().size() > 200))
            m_errors << ProfileFile::tr("\"metadata\": \"backup\": \"device\" must be a text of "
                                        "at most 200 characters");
        else {
            profile->backupOperation = operation;
            profile->backupDevice = o.value(QLatin1String("device")).toString();
        }
    }

    bool readMap(const QJsonValue &value, Profile *profile)
    {
        if (!value.isObject()) {
            m_errors << ProfileFile::tr(
                            "\"map\" must be an object {\"id\": …, \"version\": …}, found %1")
                            .arg(typeName(value));
            return false;
        }
        const QJsonObject o = value.toObject();
        unknownFields(o, {QStringLiteral("id"), QStringLiteral("version")}, QStringLiteral("map"));
        const QJsonValue id = o.value(QLatin1String("id"));
        const auto version = wholeNumber(o.value(QLatin1String("version")));
        if (!id.isString()) {
            m_errors
                << ProfileFile::tr("\"map\": \"id\" must be a text, found %1").arg(typeName(id));
            return false;
        }
        if (!version) {
            m_errors << ProfileFile::tr("\"map\": \"version\" must be a whole number, found %1")
                            .arg(typeName(o.value(QLatin1String("version"))));
            return false;
        }
        if ((id.toString() != m_map.id() || *version != m_map.version()) && m_acceptOtherMaps) {
            // A firmware variant or a larger model: read what both maps have, list the rest.
            m_variance.fileMap =
                id.toString().left(60) + QLatin1Char('/') + QString::number(*version);
            m_variance.thisMap = m_map.identity();
        } else if (id.toString() != m_map.id() || *version != m_map.version()) {
            m_errors << ProfileFile::tr(
                            "the profile is for register map \"%1\" version %2, but the "
                            "controller's map is \"%3\" version %4")
                            .arg(id.toString().left(60))
                            .arg(*version)
                            .arg(m_map.id())
                            .arg(m_map.version());
            return false;
        }
        profile->mapId = id.toString();
        profile->mapVersion = *version;
        return true;
    }

    void readMetadata(const QJsonValue &value, Profile *profile)
    {
        if (!value.isObject()) {
            m_errors
                << ProfileFile::tr("\"metadata\" must be an object, found %1").arg(typeName(value));
            return;
        }
        const QJsonObject o = value.toObject();
        QStringList fields{QStringLiteral("name"),       QStringLiteral("notes"),
                           QStringLiteral("created"),    QStringLiteral("stepcomVersion"),
                           QStringLiteral("deviceId"),   QStringLiteral("baud"),
                           QStringLiteral("unsupported")};
        if (m_schema >= 2)
            fields << QStringLiteral("backup") << QStringLiteral("source");
        unknownFields(o, fields, QStringLiteral("metadata"));
        if (m_schema >= 2 && o.contains(QLatin1String("backup")))
            readBackup(o.value(QLatin1String("backup")), profile);
        if (const QJsonValue u = o.value(QLatin1String("unsupported")); !u.isUndefined()) {
            if (!u.isArray())
                m_errors << ProfileFile::tr("\"metadata\": \"unsupported\" must be a list of "
                                            "keys, found %1")
                                .arg(typeName(u));
            for (const QJsonValue &k : u.toArray()) {
                if (!k.isString() || !m_map.find(k.toString()))
                    m_errors << ProfileFile::tr("\"metadata\": \"unsupported\": %1 is no "
                                                "parameter of the map")
                                    .arg(k.isString() ? k.toString() : typeName(k));
                else
                    profile->unsupported << k.toString();
            }
        }
        auto text = [&](const char *field, QString *out) {
            const QJsonValue v = o.value(QLatin1String(field));
            if (v.isUndefined())
                return;
            if (!v.isString())
                m_errors << ProfileFile::tr("\"metadata\": \"%1\" must be a text, found %2")
                                .arg(QLatin1String(field), typeName(v));
            else
                *out = v.toString();
        };
        text("name", &profile->name);
        text("notes", &profile->notes);
        text("stepcomVersion", &profile->stepcomVersion);
        QString created;
        text("created", &created);
        if (!created.isEmpty()) {
            profile->created = QDateTime::fromString(created, Qt::ISODate);
            if (!profile->created.isValid())
                m_errors << ProfileFile::tr("\"metadata\": \"created\" is not a date and time "
                                            "(2024-05-31T14:02:00Z): \"%1\"")
                                .arg(created.left(40));
        }
        auto link = [&](const char *field, const char *key, int *out) {
            const QJsonValue v = o.value(QLatin1String(field));
            if (v.isUndefined())
                return;
            const auto n = wholeNumber(v);
            const Parameter *p = m_map.find(QLatin1String(key));
            // Another map may allow other ids or bauds; metadata is information only.
            const bool checkRange = p && !m_variance.isVariant();
            if (!n || (checkRange && !p->checkRaw(*n).isEmpty()))
                m_errors << ProfileFile::tr("\"metadata\": \"%1\" must be a %2, found %3")
                                .arg(QLatin1String(field),
                                     checkRange ? p->rangeText() : ProfileFile::tr("whole number"),
                                     v.isDouble() ? QString::number(v.toDouble(), 'g', 17)
                                                  : typeName(v));
            else
                *out = *n;
        };
        link("deviceId", "device.id", &profile->deviceId);
        link("baud", "device.baud", &profile->baud);
        QString source;
        text("source", &source);
        if (!source.isEmpty() && source != QLatin1String("simulator"))
            m_errors << ProfileFile::tr("\"metadata\": \"source\" is \"simulator\" or absent, "
                                        "found \"%1\"")
                            .arg(source.left(40));
        profile->fromSimulator = source == QLatin1String("simulator");
    }

    // A key of another map's profile that this map has no setting for: listed, not used.
    void unknownToThisMap(const QString &key, const QJsonValue &v, const Parameter *p)
    {
        if (!v.isDouble()) { // every value of a profile is a number, whatever its map
            m_errors << ProfileFile::tr("%1: expected a number, found %2")
                            .arg(key.left(60), typeName(v));
            return;
        }
        const QString why =
            !p            ? ProfileFile::tr("not in register map \"%1\"").arg(m_map.identity())
            : p->isCoil() ? ProfileFile::tr("a command in register map \"%1\", not a setting")
                                .arg(m_map.identity())
                          : ProfileFile::tr("a status value in register map \"%1\", not a setting")
                                .arg(m_map.identity());
        m_variance.unknown.append({key, v.toDouble(), why});
    }

    void readValues(const QJsonValue &value, Profile *profile)
    {
        if (!value.isObject()) {
            m_errors << ProfileFile::tr("\"values\" must be an object of key: value, found %1")
                            .arg(typeName(value));
            return;
        }
        const QJsonObject o = value.toObject();
        const bool variant = m_variance.isVariant();
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString key = it.key();
            const QJsonValue v = it.value();
            const Parameter *p = m_map.find(key);
            if (!p || !p->writable()) {
                if (variant)
                    unknownToThisMap(key, v, p);
                else if (!p)
                    m_errors << ProfileFile::tr("unknown parameter \"%1\" (not in register map "
                                                "\"%2\")")
                                    .arg(key.left(60), m_map.identity());
                else if (p->isCoil())
                    m_errors << ProfileFile::tr("\"%1\" is a command, not a setting").arg(key);
                else
                    m_errors << ProfileFile::tr("\"%1\" is read-only (a status value), not a "
                                                "setting")
                                    .arg(key);
                continue;
            }
            if (!v.isDouble()) {
                m_errors
                    << ProfileFile::tr("%1: expected a number, found %2").arg(key, typeName(v));
                continue;
            }
            QString why;
            const auto raw = p->fromEngineering(v.toDouble(), &why);
            if (!raw) {
                if (variant)
                    m_variance.rejected.append({key, v.toDouble(), why});
                else
                    m_errors << why;
                continue;
            }
            profile->values.insert(key, *raw);
        }
        for (const Parameter *p : Profile::profileParameters(m_map, false)) {
            if (o.contains(p->key) || profile->unsupported.contains(p->key))
                continue;
            if (variant)
                m_variance.missing << p->key;
            else
                m_errors << ProfileFile::tr("missing \"%1\" (%2)").arg(p->key, p->label.en);
        }
    }

    const RegisterMap &m_map;
    const bool m_acceptOtherMaps;
    int m_schema = ProfileFile::Schema;
    QStringList m_errors;
    ProfileVariance m_variance;
};

QJsonValue engineering(const Parameter &p, qint64 raw)
{
    if (p.scale == 1)
        return QJsonValue(double(raw));
    return QJsonValue(p.formatRaw(raw).toDouble());
}

} // namespace

void ProfileFile::lineColumn(const QByteArray &bytes, qsizetype offset, int *line, int *column)
{
    offset = std::clamp<qsizetype>(offset, 0, bytes.size());
    const QByteArray before = bytes.left(offset);
    *line = int(before.count('\n')) + 1;
    const qsizetype lineStart = before.lastIndexOf('\n') + 1;
    *column = int(QString::fromUtf8(before.mid(lineStart)).size()) + 1;
}

ProfileParseResult ProfileFile::parse(const QByteArray &bytes, const RegisterMap &map,
                                      OtherMaps otherMaps)
{
    if (!map.isValid()) {
        ProfileParseResult r;
        r.errors << ProfileFile::tr("no register map to check the profile against");
        return r;
    }
    return Parser(map, otherMaps).run(bytes);
}

ProfileParseResult ProfileFile::load(const QString &path, const RegisterMap &map,
                                     OtherMaps otherMaps)
{
    ProfileParseResult r;
    QFile file(path);
    if (!QFileInfo(path).isFile()) {
        r.errors << ProfileFile::tr("%1: no such file").arg(path);
        return r;
    }
    if (file.size() > MaxBytes) {
        r.errors << ProfileFile::tr("%1: %2 bytes, far too large for a profile")
                        .arg(path)
                        .arg(file.size());
        return r;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        r.errors << ProfileFile::tr("%1: %2").arg(path, file.errorString());
        return r;
    }
    r = parse(file.readAll(), map, otherMaps);
    for (QString &e : r.errors)
        e = QFileInfo(path).fileName() + QStringLiteral(": ") + e;
    return r;
}

QByteArray ProfileFile::toJson(const Profile &profile, const RegisterMap &map)
{
    QJsonObject metadata{{QStringLiteral("name"), profile.name},
                         {QStringLiteral("notes"), profile.notes},
                         {QStringLiteral("stepcomVersion"), profile.stepcomVersion}};
    if (profile.created.isValid())
        metadata.insert(QStringLiteral("created"), profile.created.toUTC().toString(Qt::ISODate));
    if (profile.deviceId > 0)
        metadata.insert(QStringLiteral("deviceId"), profile.deviceId);
    if (profile.baud > 0)
        metadata.insert(QStringLiteral("baud"), profile.baud);
    if (!profile.unsupported.isEmpty())
        metadata.insert(QStringLiteral("unsupported"),
                        QJsonArray::fromStringList(profile.unsupported));
    // Schema 2 only when its fields are used: such a file stays readable by every StepCom.
    bool schema2 = false;
    if (!profile.backupOperation.isEmpty()) {
        QJsonObject backup{{QStringLiteral("operation"), profile.backupOperation}};
        if (!profile.backupDevice.isEmpty())
            backup.insert(QStringLiteral("device"), profile.backupDevice);
        metadata.insert(QStringLiteral("backup"), backup);
        schema2 = true;
    }
    if (profile.fromSimulator) {
        metadata.insert(QStringLiteral("source"), QStringLiteral("simulator"));
        schema2 = true;
    }
    QJsonObject values;
    for (auto it = profile.values.cbegin(); it != profile.values.cend(); ++it) {
        if (const Parameter *p = map.find(it.key()))
            values.insert(it.key(), engineering(*p, it.value()));
    }
    for (const QList<ProfileNote> *notes :
         {&profile.variance.unknown, &profile.variance.rejected}) {
        for (const ProfileNote &n : *notes)
            values.insert(n.key, n.number);
    }
    const bool own = profile.mapId.isEmpty();
    const QJsonObject limits = profile.travelLimits.toJson(map);
    schema2 = schema2 || !limits.isEmpty();
    QJsonObject top{
        {QStringLiteral("format"), kFormat},
        {QStringLiteral("schema"), schema2 ? Schema : FirstSchema},
        {QStringLiteral("map"),
         QJsonObject{{QStringLiteral("id"), own ? map.id() : profile.mapId},
                     {QStringLiteral("version"), own ? map.version() : profile.mapVersion}}},
        {QStringLiteral("metadata"), metadata},
        {QStringLiteral("values"), values},
    };
    if (!limits.isEmpty())
        top.insert(QStringLiteral("stepcom"),
                   QJsonObject{{QStringLiteral("travelLimits"), limits}});
    return QJsonDocument(top).toJson(QJsonDocument::Indented);
}

QString ProfileFile::save(const QString &path, const Profile &profile, const RegisterMap &map)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return ProfileFile::tr("cannot write %1: %2").arg(path, file.errorString());
    const QByteArray json = toJson(profile, map);
    if (file.write(json) != json.size()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return ProfileFile::tr("cannot write %1: %2").arg(path, why);
    }
    if (!file.commit())
        return ProfileFile::tr("cannot write %1: %2").arg(path, file.errorString());
    return {};
}

} // namespace stepcom
