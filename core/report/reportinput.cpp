#include "report/reportinput.h"

#include "commissioning/checklistfile.h"
#include "profile/profile.h"
#include "profile/profilefile.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QFileInfo>

namespace stepcom {

ReportInput ReportInput::fromSession(const DeviceSession &session, int id,
                                     const QHash<QString, qint64> &values, const QDateTime &read)
{
    ReportInput in;
    in.map = session.map();
    in.values = values;
    in.link = session.line()->describeDevice(id);
    in.simulator = session.connection()->isSimulator();
    in.line = session.connection()->linkStats().lineText(id);
    in.deviceId = id;
    in.date = QDateTime::currentDateTime();
    in.lastRead = read;
    if (session.isLive() && id == session.line()->deviceInView()) { // what the window follows
        in.travelLimits = session.travelLimits();
        in.savedToFlash = !session.parameters()->store()->unsavedToFlash();
    }
    return in;
}

ReportInput ReportInput::fromProfile(const RegisterMap &map, const Profile &profile,
                                     const QString &path, const QString &locale)
{
    ReportInput in;
    in.map = map;
    for (auto it = profile.values.cbegin(); it != profile.values.cend(); ++it)
        in.values.insert(it.key(), it.value());
    in.deviceId = profile.deviceId;
    in.title = profile.name;
    in.notes = profile.notes;
    in.date = QDateTime::currentDateTime();
    in.locale = locale;
    in.sourceFile = QFileInfo(path).fileName();
    in.fileCreated = profile.created;
    in.fileStepcomVersion = profile.stepcomVersion;
    in.fileBaud = profile.baud;
    in.simulator = profile.fromSimulator;
    if (profile.variance.isVariant())
        in.fileMap = profile.variance.fileMap;
    in.notFromFile = profile.variance.describe(map, locale);
    in.travelLimits = profile.travelLimits;
    if (const QString checklist = ChecklistFile::pathFor(path); QFileInfo::exists(checklist)) {
        const ChecklistParseResult r = ChecklistFile::load(checklist, map);
        in.checklistFile = QFileInfo(checklist).fileName();
        if (r.ok())
            in.checklist = *r.checklist;
        else
            in.checklistErrors = r.errors;
    }
    return in;
}

std::optional<ReportInput> ReportInput::fromProfileFile(const RegisterMap &map, const QString &path,
                                                        const QString &locale, QStringList *errors)
{
    const ProfileParseResult r = ProfileFile::load(path, map, ProfileFile::OtherMaps::Accept);
    if (!r.ok()) {
        if (errors)
            *errors = r.errors;
        return std::nullopt;
    }
    return fromProfile(map, *r.profile, path, locale);
}

} // namespace stepcom
