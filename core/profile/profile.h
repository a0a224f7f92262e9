#pragma once

#include "motion/travellimits.h"
#include "profile/profilevariance.h"

#include <QDateTime>
#include <QMap>
#include <QString>

namespace stepcom {

class RegisterMap;
struct Parameter;

// A controller's settings as a file: every read-write parameter of one register map, in raw
// units (what the wire holds), plus who/what/when. Keys are map keys; device.id and device.baud
// are optional (a profile is usually meant for the next machine, which keeps its own link).
struct Profile
{
    QString mapId;
    int mapVersion = 0;
    QString name;
    QString notes;
    QDateTime created; // UTC
    QString stepcomVersion;
    int deviceId = 0; // metadata: the controller it was saved from (0 = unknown)
    // metadata: settings the controller it was saved from does not have (a firmware variant
    // that refuses to read them): not "missing" from the file
    QStringList unsupported;
    int baud = 0;
    QMap<QString, qint64> values; // raw, by key, ordered by key
    // A profile of another map (mapId/mapVersion differ): what this map cannot take. `values`
    // then holds only what both maps have, within this map's ranges.
    ProfileVariance variance;
    // StepCom's own settings for this machine, not controller registers (schema 2, "stepcom").
    TravelLimits travelLimits;
    // A backup made before a risky operation (schema 2, metadata "backup"): the operation that
    // followed ("apply", "factory-reset", "save-to-flash", "device-id", "baud") and the link.
    QString backupOperation;
    QString backupDevice;
    // Read from StepCom's built-in simulator, not from a machine (schema 2, metadata "source":
    // "simulator"): a report of it says so on its face.
    bool fromSimulator = false;

    // The parameters a profile holds for `map`: every read-write holding register; the link
    // settings only when `withLink`.
    static QList<const Parameter *> profileParameters(const RegisterMap &map, bool withLink);
    // device.id and device.baud: applied only when asked for explicitly.
    static bool isLinkSetting(const QString &key);
    // A profile for `map` from raw values (those it does not hold are skipped); the metadata
    // stepcomVersion and created are filled in.
    static Profile fromValues(const RegisterMap &map, const QHash<QString, qint64> &raw,
                              bool withLink);
};

} // namespace stepcom
