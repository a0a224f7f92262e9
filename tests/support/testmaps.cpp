#include "testmaps.h"

#include "profile/profilefile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

namespace stepcom::test {

namespace {

// Applies `change` to every entry (top level and in blocks) named `key`; drops it on false.
void forEntries(QJsonObject &top,
                const std::function<bool(const QString &key, QJsonObject &)> &change)
{
    auto walk = [&](QJsonArray entries) {
        QJsonArray kept;
        for (const QJsonValue &v : entries) {
            QJsonObject e = v.toObject();
            if (change(e.value(QStringLiteral("key")).toString(), e))
                kept.append(e);
        }
        return kept;
    };
    top.insert(QStringLiteral("entries"), walk(top.value(QStringLiteral("entries")).toArray()));
    QJsonArray blocks = top.value(QStringLiteral("blocks")).toArray();
    for (int i = 0; i < blocks.size(); ++i) {
        QJsonObject block = blocks.at(i).toObject();
        block.insert(QStringLiteral("entries"),
                     walk(block.value(QStringLiteral("entries")).toArray()));
        blocks[i] = block;
    }
    top.insert(QStringLiteral("blocks"), blocks);
}

} // namespace

std::optional<RegisterMap> builtinMapEdited(const std::function<void(QJsonObject &top)> &edit,
                                            QStringList *errors)
{
    QFile file(QStringLiteral(":/maps/controller.json"));
    if (!file.open(QIODevice::ReadOnly)) {
        *errors << QStringLiteral("the built-in map resource is missing");
        return std::nullopt;
    }
    QJsonObject top = QJsonDocument::fromJson(file.readAll()).object();
    edit(top);
    return RegisterMap::fromJson(QJsonDocument(top).toJson(), errors);
}

void setIdentity(QJsonObject &top, const QString &id, int version)
{
    top.insert(QStringLiteral("id"), id);
    top.insert(QStringLiteral("version"), version);
}

void setMotorCount(QJsonObject &top, int count)
{
    QJsonArray blocks = top.value(QStringLiteral("blocks")).toArray();
    QJsonObject motor = blocks.at(0).toObject();
    motor.insert(QStringLiteral("count"), count);
    blocks[0] = motor;
    top.insert(QStringLiteral("blocks"), blocks);
}

void dropEntries(QJsonObject &top, const QStringList &keys)
{
    forEntries(top, [&](const QString &key, QJsonObject &) { return !keys.contains(key); });
}

void setEntryField(QJsonObject &top, const QString &key, const QString &field,
                   const QJsonValue &value)
{
    forEntries(top, [&](const QString &k, QJsonObject &e) {
        if (k == key)
            e.insert(field, value);
        return true;
    });
}

std::optional<RegisterMap> builtinMapWithMotors(int count, QStringList *errors)
{
    QFile file(QStringLiteral(":/maps/controller.json"));
    if (!file.open(QIODevice::ReadOnly)) {
        *errors << QStringLiteral("the built-in map resource is missing");
        return std::nullopt;
    }
    const QJsonObject top = QJsonDocument::fromJson(file.readAll()).object();
    const QJsonObject motor = top.value(QStringLiteral("blocks")).toArray().at(0).toObject();
    if (motor.value(QStringLiteral("prefix")).toString() != QLatin1String("motor")) {
        *errors << QStringLiteral("the built-in map's first block is not the motor block");
        return std::nullopt;
    }
    return builtinMapEdited([count](QJsonObject &t) { setMotorCount(t, count); }, errors);
}

std::optional<RegisterMap> threeAxisMap(QStringList *errors)
{
    return builtinMapEdited(
        [](QJsonObject &top) {
            setIdentity(top, QStringLiteral("stepper3"), 1);
            setMotorCount(top, 3);
            setEntryField(top, QStringLiteral("speed"), QStringLiteral("max"), 6000);
        },
        errors);
}

std::optional<RegisterMap> liteVariantMap(QStringList *errors)
{
    return builtinMapEdited(
        [](QJsonObject &top) {
            setIdentity(top, QStringLiteral("stepper2-lite"), 1);
            dropEntries(top, {QStringLiteral("home_input"), QStringLiteral("line.enabled"),
                              QStringLiteral("line.start_x"), QStringLiteral("line.start_y"),
                              QStringLiteral("line.end_x"), QStringLiteral("line.end_y"),
                              QStringLiteral("line.speed"), QStringLiteral("line.start"),
                              QStringLiteral("line.stop")});
        },
        errors);
}

QByteArray profileSavedWith(const RegisterMap &other, const QHash<QString, qint64> &values,
                            const QString &name)
{
    Profile p = Profile::fromValues(other, values, false);
    p.name = name;
    return ProfileFile::toJson(p, other);
}

} // namespace stepcom::test
