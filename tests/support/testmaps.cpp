#include "testmaps.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace stepcom::test {

std::optional<RegisterMap> builtinMapWithMotors(int count, QStringList *errors)
{
    QFile file(QStringLiteral(":/maps/controller.json"));
    if (!file.open(QIODevice::ReadOnly)) {
        *errors << QStringLiteral("the built-in map resource is missing");
        return std::nullopt;
    }
    QJsonObject top = QJsonDocument::fromJson(file.readAll()).object();
    QJsonArray blocks = top.value(QStringLiteral("blocks")).toArray();
    QJsonObject motor = blocks.at(0).toObject();
    if (motor.value(QStringLiteral("prefix")).toString() != QLatin1String("motor")) {
        *errors << QStringLiteral("the built-in map's first block is not the motor block");
        return std::nullopt;
    }
    motor.insert(QStringLiteral("count"), count);
    blocks[0] = motor;
    top.insert(QStringLiteral("blocks"), blocks);
    return RegisterMap::fromJson(QJsonDocument(top).toJson(), errors);
}

} // namespace stepcom::test
