#pragma once

#include "session/devicesession.h"

#include <QObject>
#include <QPointer>

namespace stepcom {

// The window's automatic backups: installed as the session's risk guard, it saves the
// controller's settings with BackupStore before every apply, factory reset, save to flash and
// id or baud change (reading first what the store does not know), and lets the operation go on
// only when the backup was saved.
class BackupGuard : public QObject
{
    Q_OBJECT
public:
    BackupGuard(DeviceSession *session, QObject *parent = nullptr);
    ~BackupGuard() override;

    // Where backups go (the data location's backups/ unless a test says otherwise).
    void setDirectory(const QString &directory) { m_dir = directory; }
    QString directory() const { return m_dir; }
    QString lastBackup() const { return m_last; }

Q_SIGNALS:
    void saved(const QString &path);

private:
    void run(DeviceSession::Risk risk, int id, DeviceSession::Proceed proceed);

    QPointer<DeviceSession> m_session;
    QString m_dir;
    QString m_last;
};

} // namespace stepcom
