#include "commissioning/checklistfile.h"

#include "map/registermap.h"
#include "profile/profilefile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSet>

namespace stepcom {

namespace {

const QString kFormat = QStringLiteral("stepcom-checklist");

QString kindOf(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
        return ChecklistFile::tr("null");
    case QJsonValue::Bool:
        return ChecklistFile::tr("true/false");
    case QJsonValue::Double:
        return ChecklistFile::tr("a number");
    case QJsonValue::String:
        return ChecklistFile::tr("a text");
    case QJsonValue::Array:
        return ChecklistFile::tr("a list");
    case QJsonValue::Object:
        return ChecklistFile::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return ChecklistFile::tr("nothing");
}

std::optional<StepResult> resultFromWord(const QString &word)
{
    for (StepResult r : {StepResult::Passed, StepResult::Failed, StepResult::Skipped}) {
        if (ChecklistStep::resultWord(r) == word)
            return r;
    }
    return std::nullopt;
}

class Reader
{
public:
    explicit Reader(const RegisterMap &map)
        : m_map(map)
    {}

    ChecklistParseResult run(const QByteArray &bytes)
    {
        ChecklistParseResult result;
        if (bytes.trimmed().isEmpty()) {
            result.errors << ChecklistFile::tr("the file is empty");
            return result;
        }
        if (bytes.size() > ChecklistFile::MaxBytes) {
            result.errors << ChecklistFile::tr("the file is %1 bytes: far too large for a "
                                               "checklist")
                                 .arg(bytes.size());
            return result;
        }
        QJsonParseError error;
        const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
        if (error.error != QJsonParseError::NoError) {
            int line = 0;
            int column = 0;
            ProfileFile::lineColumn(bytes, error.offset - 1, &line, &column);
            result.errors << ChecklistFile::tr("not valid JSON at line %1, column %2: %3")
                                 .arg(line)
                                 .arg(column)
                                 .arg(error.errorString());
            return result;
        }
        if (!doc.isObject()) {
            result.errors << ChecklistFile::tr("the file holds a JSON list, not a checklist");
            return result;
        }
        Checklist checklist = Checklist::forMap(m_map);
        readTop(doc.object(), &checklist);
        if (m_errors.size() > ChecklistFile::MaxErrors) {
            const qsizetype more = m_errors.size() - ChecklistFile::MaxErrors;
            m_errors = m_errors.mid(0, ChecklistFile::MaxErrors);
            m_errors << ChecklistFile::tr("… and %1 more problems").arg(more);
        }
        result.errors = m_errors;
        if (m_errors.isEmpty())
            result.checklist = checklist;
        return result;
    }

private:
    void unknown(const QJsonObject &o, const QStringList &allowed, const QString &where)
    {
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (!allowed.contains(it.key()))
                m_errors << ChecklistFile::tr("%1unknown field \"%2\" (allowed: %3)")
                                .arg(where.isEmpty() ? QString() : where + QStringLiteral(": "),
                                     it.key().left(40), allowed.join(QLatin1String(", ")));
        }
    }

    bool text(const QJsonObject &o, const char *field, const QString &where, QString *out,
              bool required)
    {
        const QJsonValue v = o.value(QLatin1String(field));
        if (v.isUndefined() && !required)
            return true;
        if (!v.isString()) {
            m_errors << ChecklistFile::tr("%1\"%2\" must be a text, found %3")
                            .arg(where.isEmpty() ? QString() : where + QStringLiteral(": "),
                                 QLatin1String(field), kindOf(v));
            return false;
        }
        *out = v.toString();
        return true;
    }

    void readTop(const QJsonObject &top, Checklist *checklist)
    {
        if (top.value(QLatin1String("format")).toString() != kFormat) {
            m_errors << (top.value(QLatin1String("format")).toString() ==
                                 QLatin1String("stepcom-profile")
                             ? ChecklistFile::tr("this is a profile, not a checklist")
                             : ChecklistFile::tr("not a StepCom checklist: \"format\" must be "
                                                 "\"%1\"")
                                   .arg(kFormat));
            return;
        }
        const QJsonValue schema = top.value(QLatin1String("schema"));
        if (!schema.isDouble() || schema.toDouble() != ChecklistFile::Schema) {
            const bool newer = schema.isDouble() && schema.toDouble() > ChecklistFile::Schema;
            m_errors
                << (newer ? ChecklistFile::tr("checklist schema %1 is newer than this "
                                              "StepCom reads (%2): update StepCom")
                                .arg(schema.toDouble())
                                .arg(ChecklistFile::Schema)
                          : ChecklistFile::tr("\"schema\" must be %1").arg(ChecklistFile::Schema));
            return;
        }
        unknown(top,
                {QStringLiteral("format"), QStringLiteral("schema"), QStringLiteral("map"),
                 QStringLiteral("machine"), QStringLiteral("settingsFingerprint"),
                 QStringLiteral("steps")},
                QString());
        QString map;
        if (text(top, "map", QString(), &map, true) && map != m_map.identity()) {
            m_errors << ChecklistFile::tr("the checklist is for register map \"%1\", but this "
                                          "map is \"%2\"")
                            .arg(map.left(60), m_map.identity());
            return; // its steps would be another machine's
        }
        text(top, "machine", QString(), &checklist->machine, false);
        text(top, "settingsFingerprint", QString(), &checklist->settingsFingerprint, false);
        if (checklist->machine.size() > 200 || checklist->settingsFingerprint.size() > 200)
            m_errors << ChecklistFile::tr("\"machine\" and \"settingsFingerprint\" hold at most "
                                          "200 characters");
        const QJsonValue steps = top.value(QLatin1String("steps"));
        if (!steps.isArray()) {
            m_errors << ChecklistFile::tr("\"steps\" must be a list, found %1").arg(kindOf(steps));
            return;
        }
        QSet<QString> seen;
        const QJsonArray list = steps.toArray();
        for (qsizetype i = 0; i < list.size(); ++i)
            readStep(list.at(i), int(i) + 1, &seen, checklist);
    }

    void readStep(const QJsonValue &value, int index, QSet<QString> *seen, Checklist *checklist)
    {
        const QString where = ChecklistFile::tr("step %1").arg(index);
        if (!value.isObject()) {
            m_errors
                << ChecklistFile::tr("%1: must be an object, found %2").arg(where, kindOf(value));
            return;
        }
        const QJsonObject o = value.toObject();
        unknown(o, {QStringLiteral("id"), QStringLiteral("attempts")}, where);
        QString id;
        if (!text(o, "id", where, &id, true))
            return;
        if (seen->contains(id)) {
            m_errors
                << ChecklistFile::tr("%1: \"%2\" appears more than once").arg(where, id.left(60));
            return;
        }
        seen->insert(id);
        const QString at = QStringLiteral("%1 (%2)").arg(where, id.left(60));
        const QJsonValue attempts = o.value(QLatin1String("attempts"));
        if (!attempts.isArray()) {
            m_errors << ChecklistFile::tr("%1: \"attempts\" must be a list, found %2")
                            .arg(at, kindOf(attempts));
            return;
        }
        QList<ChecklistAttempt> out;
        const QJsonArray list = attempts.toArray();
        bool ok = true;
        for (qsizetype i = 0; i < list.size() && i <= Checklist::MaxAttempts; ++i) {
            ChecklistAttempt a;
            ok = readAttempt(list.at(i), QStringLiteral("%1, attempt %2").arg(at).arg(i + 1), &a) &&
                 ok;
            out << a;
        }
        if (ok) {
            if (const QString e = checklist->restore(id, out); !e.isEmpty())
                m_errors << QStringLiteral("%1: %2").arg(where, e);
        }
    }

    bool readAttempt(const QJsonValue &value, const QString &where, ChecklistAttempt *a)
    {
        const qsizetype before = m_errors.size();
        if (!value.isObject()) {
            m_errors
                << ChecklistFile::tr("%1: must be an object, found %2").arg(where, kindOf(value));
            return false;
        }
        const QJsonObject o = value.toObject();
        unknown(o,
                {QStringLiteral("attempt"), QStringLiteral("result"), QStringLiteral("time"),
                 QStringLiteral("note"), QStringLiteral("measurements")},
                where);
        const QJsonValue number = o.value(QLatin1String("attempt"));
        if (!number.isDouble() || number.toDouble() < 1 || number.toDouble() > 1e6 ||
            number.toDouble() != double(int(number.toDouble())))
            m_errors
                << ChecklistFile::tr("%1: \"attempt\" must be a whole number from 1").arg(where);
        else
            a->number = int(number.toDouble());
        QString word;
        if (text(o, "result", where, &word, true)) {
            if (const auto r = resultFromWord(word))
                a->result = *r;
            else
                m_errors << ChecklistFile::tr("%1: \"result\" must be passed, failed or skipped, "
                                              "found \"%2\"")
                                .arg(where, word.left(40));
        }
        QString time;
        if (text(o, "time", where, &time, true)) {
            a->time = QDateTime::fromString(time, Qt::ISODate);
            if (!a->time.isValid())
                m_errors << ChecklistFile::tr("%1: \"time\" is not a date and time "
                                              "(2024-05-31T14:02:00Z): \"%2\"")
                                .arg(where, time.left(40));
        }
        text(o, "note", where, &a->note, false);
        const QJsonValue ms = o.value(QLatin1String("measurements"));
        if (!ms.isUndefined() && !ms.isArray()) {
            m_errors << ChecklistFile::tr("%1: \"measurements\" must be a list, found %2")
                            .arg(where, kindOf(ms));
        } else {
            const QJsonArray list = ms.toArray();
            for (qsizetype i = 0; i < list.size() && i <= Checklist::MaxMeasurements; ++i) {
                const QString w = QStringLiteral("%1, measurement %2").arg(where).arg(i + 1);
                if (!list.at(i).isObject()) {
                    m_errors << ChecklistFile::tr("%1: must be an object, found %2")
                                    .arg(w, kindOf(list.at(i)));
                    continue;
                }
                const QJsonObject m = list.at(i).toObject();
                unknown(m, {QStringLiteral("key"), QStringLiteral("value"), QStringLiteral("unit")},
                        w);
                ChecklistMeasurement out;
                text(m, "key", w, &out.key, true);
                text(m, "value", w, &out.value, true);
                text(m, "unit", w, &out.unit, false);
                a->measurements << out;
            }
        }
        return m_errors.size() == before;
    }

    const RegisterMap &m_map;
    QStringList m_errors;
};

} // namespace

QString ChecklistFile::pathFor(const QString &profilePath)
{
    const QFileInfo info(profilePath);
    QString base = info.fileName();
    if (base.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        base.chop(5);
    return info.dir().filePath(base + QStringLiteral(".checklist.json"));
}

ChecklistParseResult ChecklistFile::parse(const QByteArray &bytes, const RegisterMap &map)
{
    if (!map.isValid()) {
        ChecklistParseResult r;
        r.errors << tr("no register map to check the checklist against");
        return r;
    }
    return Reader(map).run(bytes);
}

ChecklistParseResult ChecklistFile::load(const QString &path, const RegisterMap &map)
{
    ChecklistParseResult r;
    QFile file(path);
    if (!QFileInfo(path).isFile()) {
        r.errors << tr("%1: no such file").arg(path);
        return r;
    }
    if (file.size() > MaxBytes) {
        r.errors << tr("%1: %2 bytes, far too large for a checklist").arg(path).arg(file.size());
        return r;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        r.errors << tr("%1: %2").arg(path, file.errorString());
        return r;
    }
    r = parse(file.readAll(), map);
    for (QString &e : r.errors)
        e = QFileInfo(path).fileName() + QStringLiteral(": ") + e;
    return r;
}

QByteArray ChecklistFile::toJson(const Checklist &checklist)
{
    QJsonArray steps;
    for (const ChecklistStep &s : checklist.steps()) {
        if (s.attempts.isEmpty())
            continue; // pending steps need no entry: the map gives every step
        QJsonArray attempts;
        for (const ChecklistAttempt &a : s.attempts) {
            QJsonArray ms;
            for (const ChecklistMeasurement &m : a.measurements) {
                QJsonObject mo{{QStringLiteral("key"), m.key}, {QStringLiteral("value"), m.value}};
                if (!m.unit.isEmpty())
                    mo.insert(QStringLiteral("unit"), m.unit);
                ms.append(mo);
            }
            QJsonObject ao{{QStringLiteral("attempt"), a.number},
                           {QStringLiteral("result"), ChecklistStep::resultWord(a.result)},
                           {QStringLiteral("time"), a.time.toUTC().toString(Qt::ISODate)}};
            if (!a.note.isEmpty())
                ao.insert(QStringLiteral("note"), a.note);
            if (!ms.isEmpty())
                ao.insert(QStringLiteral("measurements"), ms);
            attempts.append(ao);
        }
        steps.append(
            QJsonObject{{QStringLiteral("id"), s.id}, {QStringLiteral("attempts"), attempts}});
    }
    QJsonObject top{{QStringLiteral("format"), kFormat},
                    {QStringLiteral("schema"), Schema},
                    {QStringLiteral("map"), checklist.mapIdentity()},
                    {QStringLiteral("steps"), steps}};
    if (!checklist.machine.isEmpty())
        top.insert(QStringLiteral("machine"), checklist.machine);
    if (!checklist.settingsFingerprint.isEmpty())
        top.insert(QStringLiteral("settingsFingerprint"), checklist.settingsFingerprint);
    return QJsonDocument(top).toJson(QJsonDocument::Indented);
}

QString ChecklistFile::save(const QString &path, const Checklist &checklist)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return tr("cannot write %1: %2").arg(path, file.errorString());
    const QByteArray json = toJson(checklist);
    if (file.write(json) != json.size()) {
        const QString why = file.errorString();
        file.cancelWriting();
        return tr("cannot write %1: %2").arg(path, why);
    }
    if (!file.commit())
        return tr("cannot write %1: %2").arg(path, file.errorString());
    return {};
}

} // namespace stepcom
