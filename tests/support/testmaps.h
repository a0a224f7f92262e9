#pragma once

#include "map/registermap.h"

#include <QJsonObject>

#include <functional>
#include <optional>

namespace stepcom::test {

// The built-in map with its motor block repeated `count` times: a larger model of the family
// is a change of data only, and tests prove it with this. Errors name what went wrong.
std::optional<RegisterMap> builtinMapWithMotors(int count, QStringList *errors);

// The built-in map's JSON changed by `edit` (another id or version, entries dropped, ranges
// widened): the maps of firmware variants and other models, for profiles made with them.
std::optional<RegisterMap> builtinMapEdited(const std::function<void(QJsonObject &top)> &edit,
                                            QStringList *errors);
// Helpers for `edit`: set the map's identity; drop the entries (top level) or block entries
// (by their local key, "home_input") named; change a field of one entry or block entry.
void setIdentity(QJsonObject &top, const QString &id, int version);
void setMotorCount(QJsonObject &top, int count);
void dropEntries(QJsonObject &top, const QStringList &keys);
void setEntryField(QJsonObject &top, const QString &key, const QString &field,
                   const QJsonValue &value);

// "stepper3/1": a model with a third motor, whose motors run up to 6000 rpm.
std::optional<RegisterMap> threeAxisMap(QStringList *errors);
// "stepper2-lite/1": a firmware variant without line interpolation and without home inputs.
std::optional<RegisterMap> liteVariantMap(QStringList *errors);
// The profile file StepCom running with `other` saves from `values` (raw, by key; the keys
// `other` has no setting for are skipped), named `name`.
QByteArray profileSavedWith(const RegisterMap &other, const QHash<QString, qint64> &values,
                            const QString &name);

} // namespace stepcom::test
