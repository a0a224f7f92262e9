#pragma once

#include "profile/profile.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QStringList>

#include <optional>

namespace stepcom {

class RegisterMap;

// What reading a profile gave: the profile, or every problem found (each names the key, the
// field or the line and column), never both.
struct ProfileParseResult
{
    std::optional<Profile> profile;
    QStringList errors;
    bool ok() const { return profile.has_value(); }
};

// The profile file format (docs/profiles.md): JSON with a schema version, the register map's
// identity, metadata and the values in engineering units keyed by map keys.
class ProfileFile
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ProfileFile)
public:
    // Schema 2 added StepCom settings ("stepcom") and backup metadata; a file without them is
    // written as schema 1, which every StepCom reads.
    static constexpr int Schema = 2;
    static constexpr int FirstSchema = 1;
    static constexpr qsizetype MaxBytes = 1024 * 1024; // a real profile is a few kB
    static constexpr int MaxErrors = 40;

    // A profile that names another register map (a firmware variant, a model with more axes):
    // refused, or read with what this map knows and the rest listed in Profile::variance.
    // Malformed files are refused either way; a file of this very map must fit it exactly.
    enum class OtherMaps { Refuse, Accept };

    // Pure: no I/O, no device, never crashes on any input (a fuzz target points here).
    static ProfileParseResult parse(const QByteArray &bytes, const RegisterMap &map,
                                    OtherMaps otherMaps = OtherMaps::Refuse);
    static ProfileParseResult load(const QString &path, const RegisterMap &map,
                                   OtherMaps otherMaps = OtherMaps::Refuse);

    // The profile's own map identity (this map's when it names none), its values, and for a
    // profile of another map the values this map could not take, as the file held them: a
    // variant profile opened and saved again loses nothing its own map needs.
    static QByteArray toJson(const Profile &profile, const RegisterMap &map);
    // Atomic (QSaveFile): the old file stays whole when anything fails. Empty on success.
    static QString save(const QString &path, const Profile &profile, const RegisterMap &map);

    // 1-based line and column (in characters) of a byte offset into UTF-8 text.
    static void lineColumn(const QByteArray &bytes, qsizetype offset, int *line, int *column);
};

} // namespace stepcom
