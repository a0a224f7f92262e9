#include "window/givenfile.h"

#include <QFile>
#include <QFileInfo>

namespace stepcom {

GivenFile::Kind GivenFile::classify(const QString &path, QString *why)
{
    const QFileInfo info(path);
    QFile file(path);
    if (!info.exists()) {
        *why = tr("%1: no such file").arg(path);
        return Kind::Unreadable;
    }
    if (info.isDir()) {
        *why = tr("%1 is a folder, not a file").arg(path);
        return Kind::Unreadable;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        *why = tr("%1 cannot be read: %2").arg(path, file.errorString());
        return Kind::Unreadable;
    }
    const QByteArray head = file.read(4096);
    if (head.startsWith(QByteArrayLiteral("PK\x03\x04")))
        return Kind::SupportBundle; // the replay names what is missing in another .zip
    if (head.startsWith(QByteArrayLiteral("# StepCom ")))
        return Kind::SessionLog;
    // A sequence and a profile are JSON objects, told apart by their "format"; the readers say
    // what is wrong with a broken one.
    if (head.trimmed().startsWith('{'))
        return head.contains("\"stepcom-sequence\"") ||
                       info.suffix().compare(QLatin1String("stepseq"), Qt::CaseInsensitive) == 0
                   ? Kind::Sequence
                   : Kind::Profile;
    *why = tr("%1 is neither a StepCom profile, a sequence, a session log nor a support bundle: "
              "StepCom opens those.")
               .arg(path);
    return Kind::Unknown;
}

} // namespace stepcom
