#pragma once

#include <QList>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

namespace stepcom {

struct ReportInput;

// Where the bundle's report comes from: the machine's sheets as the window knows them, and the
// sheet of a profile file (nullopt and why not). The window's devices give them; a dialog
// knows nothing above it.
struct ReportSheets
{
    std::function<QList<ReportInput>()> known;
    std::function<std::optional<ReportInput>(const QString &path, QStringList *problems)>
        fromProfile;
};

} // namespace stepcom
