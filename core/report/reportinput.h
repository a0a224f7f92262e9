#pragma once

#include "commissioning/checklist.h"
#include "map/registermap.h"
#include "motion/travellimits.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QHash>
#include <QStringList>

#include <optional>

namespace stepcom {

class DeviceSession;
struct Profile;

// Everything the commissioning sheet shows: raw values as read from a controller, or as a
// profile file holds them (then `sourceFile` is set and the sheet says so everywhere).
struct ReportInput
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ReportInput)
public:
    RegisterMap map;
    QHash<QString, qint64> values;
    QString link; // LinkSettings::describe()
    // Read from StepCom's built-in simulator (or from a profile made of it): no machine. The
    // report says so on its face.
    bool simulator = false;
    QString line; // what the line showed: LinkStats::lineText() ("answers in 4-6 ms, ...")
    int deviceId = 0;
    QString title; // e.g. the machine's name
    QString notes;
    QDateTime date;
    QString locale; // "zh_CN" for the map's Chinese labels, else English
    // When the values were read from the controller (invalid: made from a file).
    QDateTime lastRead;
    // Whether what StepCom wrote is in the controller's flash: true when nothing was written
    // since connecting or since the last verified save to flash, false when a write since then
    // would be lost at power-off; unknown (nullopt) when the program did not watch (stepcomctl).
    std::optional<bool> savedToFlash;
    QStringList unsupported; // keys the controller does not have (refused to read them)

    // Made from a file, not read from a controller: the file's name, and what its metadata
    // says about the controller it was saved from (information only).
    QString sourceFile;
    QDateTime fileCreated;
    QString fileStepcomVersion;
    int fileBaud = 0;
    QString fileMap;         // the profile's register map when it is another one ("stepper3/1")
    QStringList notFromFile; // what of the file this map cannot show (ProfileVariance lines)

    // The commissioning checklist run on this machine (the certificate's results), the name of
    // its file, or why a checklist file beside the profile could not be read (then no report
    // should be made: a certificate must not silently lose its results).
    std::optional<Checklist> checklist;
    QString checklistFile;
    QStringList checklistErrors;
    TravelLimits travelLimits; // StepCom's software limits, shown when set

    bool fromFile() const { return !sourceFile.isEmpty(); }

    // The sheet of a profile file (`path` names it): its values and metadata, the name and
    // notes of the profile unless `title`/`notes` are given, its travel limits, and the
    // checklist kept beside it (ChecklistFile::pathFor) when there is one.
    static ReportInput fromProfile(const RegisterMap &map, const Profile &profile,
                                   const QString &path, const QString &locale);
    // Controller `id` of the session's line, with `values` read from it at `read`: the link and
    // what the line showed, and -- for the device in view of a live session (the window) --
    // the flash state and StepCom's travel limits; a one-shot session (stepcomctl) does not
    // watch the flash state, so it stays unknown. Dated now.
    static ReportInput fromSession(const DeviceSession &session, int id,
                                   const QHash<QString, qint64> &values, const QDateTime &read);
    // The same read from the file at `path` (profiles of other maps too); nullopt and why
    // not when it is no profile StepCom can read.
    static std::optional<ReportInput> fromProfileFile(const RegisterMap &map, const QString &path,
                                                      const QString &locale, QStringList *errors);
};

} // namespace stepcom
