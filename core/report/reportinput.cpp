#include "report/reportinput.h"

#include "profile/profile.h"

#include <QFileInfo>

namespace stepcom {

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
    if (profile.variance.isVariant())
        in.fileMap = profile.variance.fileMap;
    in.notFromFile = profile.variance.describe(map, locale);
    return in;
}

} // namespace stepcom
