#pragma once

#include "profile/profilefile.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QHash>
#include <QList>
#include <QStringList>

namespace stepcom {

class RegisterMap;

// One backup as listed: what it holds and why it was made.
struct BackupEntry
{
    QString path;
    QDateTime time;    // UTC, from the file (its name's when the file cannot be read)
    QString operation; // "apply", "factory-reset", "save-to-flash", "device-id", "baud"
    QString device;    // the link it was read over ("/dev/ttyUSB0 · 9600 8N1 · id 1")
    int deviceId = 0;
    int settings = 0;
    QString error; // why the file cannot be read; empty when it can
};

// Automatic backups: before an apply, a factory reset, a save to flash or an id or baud change,
// the caller saves the controller's settings (as just read) here as a time-stamped profile with
// the operation that followed. At most `limit` are kept: the oldest go. The directory is
// injectable (tests); by default it is backups/ in the window's data location, which stepcomctl
// shares.
class BackupStore
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::BackupStore)
public:
    enum class Operation { Apply, FactoryReset, SaveToFlash, DeviceId, Baud };
    static constexpr int DefaultLimit = 50;

    explicit BackupStore(const QString &directory = defaultDirectory(), int limit = DefaultLimit);

    // QStandardPaths::AppDataLocation of the window (organisation StepCom, application stepcom)
    // + "/backups", spelled out so stepcomctl, another application, finds the same place.
    static QString defaultDirectory();
    QString directory() const { return m_dir; }
    int limit() const { return m_limit; }

    static QString operationWord(Operation op);
    // "apply" → "apply a profile", translated; an unknown word as it is.
    static QString operationLabel(const QString &word);

    struct Saved
    {
        QString path;
        QStringList removed; // older backups removed to stay within the limit
        QString error;       // empty on success
        bool ok() const { return error.isEmpty(); }
    };
    // Saves `values` (the settings as read, link settings included) before `op`. `now` is UTC.
    Saved save(const RegisterMap &map, const QHash<QString, qint64> &values, Operation op,
               const QString &device, const QDateTime &now = QDateTime::currentDateTimeUtc()) const;

    // Newest first; every backup-*.json of the directory, readable or not.
    QList<BackupEntry> list(const RegisterMap &map) const;
    // For a restore through the usual compare and apply: a backup is a profile (link included).
    static ProfileParseResult load(const QString &path, const RegisterMap &map);

private:
    QStringList files() const; // backup-*.json, oldest first (the names sort by time)

    QString m_dir;
    int m_limit;
};

} // namespace stepcom
