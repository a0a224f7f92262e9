#include "profile/sessionbackup.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include "profile/profile.h"

#include <QPointer>

namespace stepcom {

BackupStore::Operation SessionBackup::operation(DeviceSession::Risk risk)
{
    using Op = BackupStore::Operation;
    switch (risk) {
    case DeviceSession::Risk::Apply:
        return Op::Apply;
    case DeviceSession::Risk::FactoryReset:
        return Op::FactoryReset;
    case DeviceSession::Risk::SaveToFlash:
        return Op::SaveToFlash;
    case DeviceSession::Risk::DeviceId:
        return Op::DeviceId;
    case DeviceSession::Risk::Baud:
        break;
    }
    return Op::Baud;
}

QList<const Parameter *> SessionBackup::settings(const RegisterMap &map)
{
    return Profile::profileParameters(map, true);
}

void SessionBackup::save(DeviceSession *session, const BackupStore &store, DeviceSession::Risk risk,
                         int id, std::function<void(const BackupStore::Saved &)> done)
{
    const QList<const Parameter *> params = settings(session->map());
    const BackupStore::Operation op = operation(risk);
    const bool inView = id == session->line()->deviceInView();
    const QString device =
        inView ? session->connection()->settings().describe() : session->line()->describeDevice(id);
    if (inView) {
        QHash<QString, qint64> known;
        for (const Parameter *p : params) {
            if (const auto v = session->parameters()->store()->deviceValue(p->key))
                known.insert(p->key, *v);
        }
        if (known.size() == params.size()) {
            done(store.save(session->map(), known, op, device));
            return;
        }
    }
    // Not all known (or another device, whose values here may be old): read them first.
    QPointer<DeviceSession> guard(session);
    const auto saveRead = [guard, store, op, device, done](const ReadOutcome &r) {
        BackupStore::Saved saved;
        if (!guard) {
            saved.error = tr("the session ended");
        } else if (!r.ok) {
            saved.error = tr("the controller's settings could not be read: %1")
                              .arg(r.errors.join(QLatin1String("; ")));
        } else {
            saved = store.save(guard->map(), r.values, op, device);
        }
        done(saved);
    };
    if (inView) // at command priority: the user is waiting for the operation
        session->parameters()->read(params, saveRead, Priority::Command);
    else
        session->line()->readDevice(id, params, saveRead);
}

} // namespace stepcom
