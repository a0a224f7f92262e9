#include "profile/busdump.h"

#include "profile/profilefile.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

namespace stepcom {

QString BusDump::fileName(int id, const QString &name, const QDate &date)
{
    static const QRegularExpression unsafe(QStringLiteral("[/\\\\:*?\"<>|\\x00-\\x1f]+"));
    QString safe = name.trimmed();
    safe.replace(unsafe, QStringLiteral("-"));
    const QString day = date.toString(Qt::ISODate);
    return safe.isEmpty() ? QStringLiteral("id%1 %2.json").arg(id).arg(day)
                          : QStringLiteral("id%1 %2 %3.json").arg(id).arg(safe, day);
}

QString BusDump::checkDirectory(const QString &directory)
{
    const QFileInfo info(directory);
    if (!info.exists())
        return tr("%1: no such folder").arg(directory);
    if (!info.isDir())
        return tr("%1 is not a folder").arg(directory);
    if (!info.isWritable())
        return tr("%1: the folder cannot be written to").arg(directory);
    return {};
}

BusDump::Saved BusDump::save(const QString &directory, const RegisterMap &map, int id,
                             const QString &name, const QString &notes,
                             const QHash<QString, qint64> &values, const QDate &date,
                             bool fromSimulator)
{
    Profile profile = Profile::fromValues(map, values, true);
    profile.name = name.trimmed().isEmpty() ? tr("Controller id %1").arg(id) : name.trimmed();
    profile.notes = notes;
    profile.deviceId = id;
    profile.fromSimulator = fromSimulator;
    Saved saved;
    saved.path = QDir(directory).filePath(fileName(id, name, date));
    saved.error = ProfileFile::save(saved.path, profile, map); // QSaveFile: whole or nothing
    return saved;
}

} // namespace stepcom
