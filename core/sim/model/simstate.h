#pragma once

#include <QHash>
#include <QString>

#include <optional>

namespace stepcom {

// The simulator's "flash": the saved parameters as a small JSON file, written atomically so a
// crash mid-save never leaves half a file.
class SimState
{
public:
    // {"format": "stepcom-sim-state", "version": 1, "map": "<identity>", "parameters": {...}}
    static bool save(const QString &path, const QString &mapIdentity,
                     const QHash<QString, qint64> &values, QString *error);
    // nullopt and a message when the file cannot be read or is not a state file.
    static std::optional<QHash<QString, qint64>> load(const QString &path, QString *error);
};

} // namespace stepcom
