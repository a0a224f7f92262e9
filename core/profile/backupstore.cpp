#include "profile/backupstore.h"

#include "map/registermap.h"
#include "profile/profile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

namespace stepcom {

namespace {

const QString kPrefix = QStringLiteral("backup-");
const QString kStamp = QStringLiteral("yyyyMMdd-HHmmss-zzz");

} // namespace

BackupStore::BackupStore(const QString &directory, int limit)
    : m_dir(directory)
    , m_limit(std::max(1, limit))
{}

QString BackupStore::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/StepCom/stepcom/backups");
}

QString BackupStore::operationWord(Operation op)
{
    switch (op) {
    case Operation::Apply:
        return QStringLiteral("apply");
    case Operation::FactoryReset:
        return QStringLiteral("factory-reset");
    case Operation::SaveToFlash:
        return QStringLiteral("save-to-flash");
    case Operation::DeviceId:
        return QStringLiteral("device-id");
    case Operation::Baud:
        return QStringLiteral("baud");
    }
    return {};
}

QString BackupStore::operationLabel(const QString &word)
{
    if (word == QLatin1String("apply"))
        return tr("apply a profile");
    if (word == QLatin1String("factory-reset"))
        return tr("factory reset");
    if (word == QLatin1String("save-to-flash"))
        return tr("save to flash");
    if (word == QLatin1String("device-id"))
        return tr("device id change");
    if (word == QLatin1String("baud"))
        return tr("baud rate change");
    return word;
}

QStringList BackupStore::files() const
{
    QStringList names =
        QDir(m_dir).entryList({kPrefix + QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (QString &n : names)
        n = QDir(m_dir).filePath(n);
    return names;
}

BackupStore::Saved BackupStore::save(const RegisterMap &map, const QHash<QString, qint64> &values,
                                     Operation op, const QString &device,
                                     const QDateTime &now) const
{
    Saved out;
    if (!QDir().mkpath(m_dir)) {
        out.error = tr("cannot create the backup folder %1").arg(m_dir);
        return out;
    }
    Profile profile = Profile::fromValues(map, values, true);
    if (profile.values.isEmpty()) {
        out.error = tr("no settings to back up: the controller was not read");
        return out;
    }
    const QDateTime utc = now.toUTC();
    profile.created = utc;
    profile.name = tr("Backup before %1").arg(operationLabel(operationWord(op)));
    profile.backupOperation = operationWord(op);
    profile.backupDevice = device.left(200);
    // A fixed-width UTC stamp: the names sort by time. Two in the same millisecond get a count.
    const QString base = kPrefix + utc.toString(kStamp) + QLatin1Char('-') + operationWord(op);
    QString path = QDir(m_dir).filePath(base + QStringLiteral(".json"));
    for (int n = 2; QFileInfo::exists(path); ++n)
        path = QDir(m_dir).filePath(QStringLiteral("%1-%2.json").arg(base).arg(n));
    if (const QString e = ProfileFile::save(path, profile, map); !e.isEmpty()) {
        out.error = e;
        return out;
    }
    out.path = path;
    QStringList all = files();
    all.removeAll(path); // the one just written stays, whatever its time says
    while (all.size() + 1 > m_limit) {
        const QString oldest = all.takeFirst();
        if (QFile::remove(oldest))
            out.removed << oldest;
    }
    return out;
}

QList<BackupEntry> BackupStore::list(const RegisterMap &map) const
{
    QList<BackupEntry> out;
    const QStringList paths = files();
    for (auto it = paths.crbegin(); it != paths.crend(); ++it) {
        BackupEntry e;
        e.path = *it;
        const ProfileParseResult r = load(*it, map);
        if (!r.ok()) {
            e.error = r.errors.join(QLatin1String("; "));
            const QString stamp = QFileInfo(*it).fileName().mid(kPrefix.size(), kStamp.size());
            e.time = QDateTime::fromString(stamp, kStamp);
            e.time.setTimeSpec(Qt::UTC);
        } else {
            e.time = r.profile->created;
            e.operation = r.profile->backupOperation;
            e.device = r.profile->backupDevice;
            e.deviceId = r.profile->deviceId;
            e.settings = int(r.profile->values.size());
        }
        out << e;
    }
    return out;
}

ProfileParseResult BackupStore::load(const QString &path, const RegisterMap &map)
{
    // A backup made by an older map is still worth restoring what both maps have.
    return ProfileFile::load(path, map, ProfileFile::OtherMaps::Accept);
}

} // namespace stepcom
