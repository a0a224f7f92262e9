#pragma once

#include "commissioning/checklist.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;

struct ChecklistParseResult
{
    std::optional<Checklist> checklist;
    QStringList errors; // every problem, each naming the step, the field or the line
    bool ok() const { return checklist.has_value(); }
};

// The checklist's progress as a file beside the profile (machine-a.json →
// machine-a.checklist.json): JSON, schema-versioned, read strictly (docs/profiles.md), saved
// atomically; a file with problems is not used at all.
class ChecklistFile
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ChecklistFile)
public:
    static constexpr int Schema = 1;
    static constexpr qsizetype MaxBytes = 1024 * 1024;
    static constexpr int MaxErrors = 40;

    // The checklist file that belongs to a profile file.
    static QString pathFor(const QString &profilePath);

    // Pure: no I/O. The steps come from `map` (its motors); the file must name the same map.
    static ChecklistParseResult parse(const QByteArray &bytes, const RegisterMap &map);
    static ChecklistParseResult load(const QString &path, const RegisterMap &map);
    static QByteArray toJson(const Checklist &checklist);
    // Atomic (QSaveFile): an interrupted save leaves the old file whole. Empty on success.
    static QString save(const QString &path, const Checklist &checklist);
};

} // namespace stepcom
