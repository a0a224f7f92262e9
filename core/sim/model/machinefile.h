#pragma once

#include "sim/model/machinesettings.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace stepcom {

// The simulator's machine file (JSON, format "stepcom-sim-machine", version 1): per axis the
// motor's limits, the backlash, the travel, the switches, the hard stops and the wiring; for the
// machine whether homing zeroes the count and the switches' seed. Strict: an unknown key, a wrong
// type or a value out of range is refused with the file, the key path and what is wrong.
class MachineFile
{
public:
    static std::optional<MachineSettings> load(const QString &path, QString *error);
    // `name` names the source in messages.
    static std::optional<MachineSettings> parse(const QByteArray &json, const QString &name,
                                                QString *error);
};

} // namespace stepcom
