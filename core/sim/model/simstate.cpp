#include "sim/model/simstate.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace stepcom {

namespace {

const QLatin1String kFormat("stepcom-sim-state");

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::SimState", text);
}

} // namespace

bool SimState::save(const QString &path, const QString &mapIdentity,
                    const QHash<QString, qint64> &values, QString *error)
{
    QJsonObject params;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        params.insert(it.key(), it.value());
    QJsonObject root;
    root.insert(QStringLiteral("format"), kFormat);
    root.insert(QStringLiteral("version"), 1);
    root.insert(QStringLiteral("map"), mapIdentity);
    root.insert(QStringLiteral("parameters"), params);

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.write(QJsonDocument(root).toJson(QJsonDocument::Indented));
    if (!file.commit()) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

std::optional<QHash<QString, qint64>> SimState::load(const QString &path, QString *error)
{
    auto fail = [&](const QString &why) -> std::optional<QHash<QString, qint64>> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(tr("cannot read %1: %2").arg(path, file.errorString()));
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (!doc.isObject())
        return fail(tr("%1: not JSON (%2)").arg(path, parseError.errorString()));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("format")).toString() != kFormat)
        return fail(tr("%1: not a simulator state file").arg(path));
    QHash<QString, qint64> values;
    const QJsonObject params = root.value(QStringLiteral("parameters")).toObject();
    for (auto it = params.begin(); it != params.end(); ++it) {
        if (!it.value().isDouble())
            return fail(tr("%1: parameter %2 is not a number").arg(path, it.key()));
        values.insert(it.key(), it.value().toInteger());
    }
    return values;
}

} // namespace stepcom
