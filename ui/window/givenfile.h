#pragma once

#include <QCoreApplication>
#include <QString>

namespace stepcom {

// A file handed to the window (`stepcom FILE`, a file manager's "Open with StepCom"): what it
// is, told by what it holds, not by its name -- a profile is edited without a controller, a
// session log or a support bundle is replayed, a machine cycle (.stepseq) opens on the Sequence
// page.
class GivenFile
{
    Q_DECLARE_TR_FUNCTIONS(GivenFile)
public:
    enum class Kind { Unreadable, Profile, Sequence, SessionLog, SupportBundle, Unknown };

    // `why` says what is wrong with an Unreadable or Unknown file, naming it.
    static Kind classify(const QString &path, QString *why);
};

} // namespace stepcom
