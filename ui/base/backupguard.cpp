#include "base/backupguard.h"

#include "profile/sessionbackup.h"

#include <QPointer>

namespace stepcom {

BackupGuard::BackupGuard(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_dir(BackupStore::defaultDirectory())
{
    QPointer<BackupGuard> self(this);
    session->risks()->setGuard(
        [self](DeviceSession::Risk risk, int id, DeviceSession::Proceed proceed) {
            if (self)
                self->run(risk, id, std::move(proceed));
            else
                proceed(QString());
        });
}

BackupGuard::~BackupGuard()
{
    if (m_session)
        m_session->risks()->setGuard({});
}

void BackupGuard::run(DeviceSession::Risk risk, int id, DeviceSession::Proceed proceed)
{
    QPointer<BackupGuard> self(this);
    SessionBackup::save(
        m_session, BackupStore(m_dir), risk, id,
        [self, risk, proceed](const BackupStore::Saved &saved) {
            const QString what = BackupStore::operationLabel(
                BackupStore::operationWord(SessionBackup::operation(risk)));
            if (!saved.ok()) {
                proceed(tr("No backup of the controller's settings could be saved (%1): %2 was "
                           "not done")
                            .arg(saved.error, what));
                return;
            }
            if (self && self->m_session) {
                self->m_last = saved.path;
                Q_EMIT self->m_session->message(
                    DeviceSession::Severity::Info,
                    tr("Backup of the controller's settings before %1: %2").arg(what, saved.path));
                Q_EMIT self->saved(saved.path);
            }
            proceed(QString());
        });
}

} // namespace stepcom
