#include "line/idchange.h"

#include "map/parameter.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QPointer>
#include <QTimer>

namespace stepcom {

IdChange::IdChange(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{}

IdChange::~IdChange()
{
    dropConnections();
}

void IdChange::start(int from, int to, int baud)
{
    if (m_running)
        return;
    m_from = from;
    m_to = to;
    m_problem = Problem::None;
    m_text.clear();
    m_running = true;
    const LinkSettings line = m_session->connection()->settings();
    m_baud =
        line.transport == LinkSettings::Transport::Rtu && baud > 0 && baud != line.baud ? baud : 0;
    m_idParam = m_session->map().find(QStringLiteral("device.id"));
    QString refusal;
    if (from < 1 || from > 255 || to < 1 || to > 255)
        refusal = tr("device ids are 1 to 255 (asked: %1 → %2)").arg(from).arg(to);
    else if (from == to)
        refusal = tr("the controller already has id %1").arg(to);
    else if (!m_idParam)
        refusal = tr("the register map has no device.id");
    else if (m_baud > 0 && !m_session->map().find(QStringLiteral("device.baud")))
        refusal = tr("the register map has no device.baud");
    else if (!m_session->connection()->isConnected())
        refusal = tr("not connected: connect to the line first");
    if (!refusal.isEmpty()) {
        // After the caller's start() returned, as every other outcome.
        QTimer::singleShot(0, this, [this, refusal] { fail(Problem::Refused, refusal); });
        return;
    }
    Q_EMIT progress(tr("Asking the controller at id %1").arg(from));
    probe(from, &IdChange::onFromProbed);
}

void IdChange::probe(int id, void (IdChange::*then)(const ReadOutcome &, bool garbled))
{
    const quint64 crcBefore = m_session->connection()->linkStats().crcErrors;
    QPointer<IdChange> self(this);
    m_session->line()->readAt(id, {m_idParam}, [self, then, crcBefore](const ReadOutcome &r) {
        if (!self)
            return;
        // Two controllers answering at once garble each other's answers: CRC errors.
        const bool garbled = self->m_session->connection()->linkStats().crcErrors > crcBefore;
        (self->*then)(r, garbled);
    });
}

void IdChange::onFromProbed(const ReadOutcome &r, bool garbled)
{
    if (garbled) {
        fail(Problem::Collision,
             tr("garbled answers at id %1: two or more controllers answer there. Connect only "
                "the controller that is to get id %2, then try again")
                 .arg(m_from)
                 .arg(m_to));
        return;
    }
    if (!r.ok) {
        fail(Problem::NoController, tr("no controller answers at id %1: %2")
                                        .arg(m_from)
                                        .arg(r.errors.join(QLatin1String("; "))));
        return;
    }
    probeTarget();
}

void IdChange::probeTarget()
{
    Q_EMIT progress(tr("Making sure nobody answers at id %1 yet").arg(m_to));
    probe(m_to, &IdChange::onTargetProbed);
}

void IdChange::onTargetProbed(const ReadOutcome &r, bool garbled)
{
    if (r.ok || garbled) {
        fail(Problem::Taken,
             tr("id %1 is taken: a controller answers there already. Choose a free id").arg(m_to));
        return;
    }
    writeId();
}

void IdChange::writeId()
{
    // The session writes to the device in view: put `from` there (on the list if need be).
    QList<int> ids = m_session->line()->deviceIds();
    if (!ids.contains(m_from)) {
        ids.append(m_from);
        m_session->line()->setDeviceIds(ids);
    }
    m_session->line()->showDevice(m_from);
    Q_EMIT progress(tr("Writing id %1 to the controller at id %2").arg(m_to).arg(m_from));
    changeLink(m_to, m_session->connection()->settings().baud, &IdChange::onIdWritten);
}

void IdChange::changeLink(int id, int baud, void (IdChange::*then)(bool, const QString &))
{
    dropConnections();
    m_changed = connect(m_session->line(), &SessionLine::linkChanged, this, [this, then] {
        dropConnections();
        (this->*then)(true, QString());
    });
    m_changeFailed = connect(m_session->line(), &SessionLine::linkChangeFailed, this,
                             [this, then](const LinkSettings &, const QString &reason) {
                                 dropConnections();
                                 (this->*then)(false, reason);
                             });
    m_session->line()->changeLink(id, baud);
}

void IdChange::onIdWritten(bool ok, const QString &reason)
{
    if (!ok) {
        fail(Problem::NotAtNewId,
             tr("the controller does not answer at id %1: %2").arg(m_to).arg(reason));
        return;
    }
    // The list names the controller by its new id, in the place the old one had.
    QList<int> ids = m_session->line()->deviceIds();
    ids.removeAll(m_to);
    const qsizetype at = ids.indexOf(m_from);
    if (at >= 0)
        ids[at] = m_to;
    else
        ids.append(m_to);
    m_session->line()->setDeviceIds(ids);
    checkOldIdSilent();
}

void IdChange::checkOldIdSilent()
{
    Q_EMIT progress(tr("Making sure nobody answers at id %1 any more").arg(m_from));
    probe(m_from, &IdChange::onOldIdProbed);
}

void IdChange::onOldIdProbed(const ReadOutcome &r, bool garbled)
{
    if (r.ok || garbled) {
        fail(Problem::StillAtOldId,
             tr("the controller answers at id %1 now, but a controller still answers at id %2: "
                "more than one controller was connected. Disconnect all but one and try again")
                 .arg(m_to)
                 .arg(m_from));
        return;
    }
    if (m_baud > 0) {
        writeBaud();
        return;
    }
    saveThenSucceed();
}

void IdChange::writeBaud()
{
    Q_EMIT progress(tr("Writing baud %1 to the controller at id %2").arg(m_baud).arg(m_to));
    changeLink(m_to, m_baud, &IdChange::onBaudWritten);
}

void IdChange::onBaudWritten(bool ok, const QString &reason)
{
    if (!ok) {
        fail(Problem::NotAtNewBaud, tr("the controller has id %1, but does not answer at %2 baud: "
                                       "%3")
                                        .arg(m_to)
                                        .arg(m_baud)
                                        .arg(reason));
        return;
    }
    saveThenSucceed();
}

void IdChange::saveThenSucceed()
{
    if (!m_saveToFlash) {
        succeed();
        return;
    }
    const Parameter *save = m_session->map().find(QStringLiteral("save_to_flash"));
    if (!save || !save->isCoil()) {
        fail(Problem::NotSaved, tr("the controller answers at id %1, but the register map has no "
                                   "save_to_flash: the id lasts until the power is switched off")
                                    .arg(m_to));
        return;
    }
    Q_EMIT progress(tr("Saving to flash at id %1").arg(m_to));
    QPointer<IdChange> self(this);
    m_session->command(*save, [self](const Result &r) {
        if (!self)
            return;
        if (!r.ok) {
            self->fail(Problem::NotSaved,
                       tr("the controller answers at id %1, but saving to flash failed (%2): the "
                          "id lasts until the power is switched off; save to flash again")
                           .arg(self->m_to)
                           .arg(r.errorText));
            return;
        }
        self->succeed();
    });
}

void IdChange::succeed()
{
    m_running = false;
    m_text = m_baud > 0
                 ? tr("device id %1 → %2: the controller answers at id %2 at %3 baud")
                       .arg(m_from)
                       .arg(m_to)
                       .arg(m_baud)
                 : tr("device id %1 → %2: the controller answers at id %2").arg(m_from).arg(m_to);
    m_text +=
        m_saveToFlash ? tr("; saved to flash") : tr("; not saved to flash: lost at power-off");
    Q_EMIT finished(true, m_text);
}

void IdChange::fail(Problem problem, const QString &text)
{
    dropConnections();
    m_running = false;
    m_problem = problem;
    m_text = text;
    Q_EMIT finished(false, m_text);
}

void IdChange::dropConnections()
{
    disconnect(m_changed);
    disconnect(m_changeFailed);
}

} // namespace stepcom
