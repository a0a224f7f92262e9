#include "line/idassigner.h"

#include "session/devicesession.h"
#include "session/idlist.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QPointer>

#include <algorithm>

namespace stepcom {

IdAssigner::IdAssigner(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_change(new IdChange(session, this))
{
    connect(m_change, &IdChange::progress, this, &IdAssigner::progress);
    connect(m_change, &IdChange::finished, this, &IdAssigner::onChanged);
}

IdAssigner::~IdAssigner()
{
    resumeLive();
}

void IdAssigner::setFirstId(int id)
{
    m_firstId = std::clamp(id, kFactoryId + 1, 255);
}

void IdAssigner::setCommonBaud(int baud)
{
    m_commonBaud = baud == kFactoryBaud ? 0 : std::max(0, baud);
}

int IdAssigner::nextId() const
{
    const QList<int> listed = m_session->line()->deviceIds();
    for (int id = m_firstId; id <= 255; ++id)
        if (!m_assigned.contains(id) && (id == kFactoryId || !listed.contains(id)))
            return id;
    return 0;
}

bool IdAssigner::start(bool newLine)
{
    if (m_state == State::Working)
        return false;
    if (!m_session->connection()->isConnected()) {
        setState(State::Idle, tr("Connect to the line first (the port the controllers are on, "
                                 "%1 baud, device id %2), then start the assistant.")
                                  .arg(kFactoryBaud)
                                  .arg(kFactoryId));
        return false;
    }
    m_assigned.clear();
    if (newLine)
        m_session->line()->setDeviceIds({});
    if (!m_paused) {
        // The live reads would go to controllers while their id and baud move.
        m_wasLive = m_session->isLive();
        m_session->setLive(false);
        m_paused = true;
    }
    setState(State::Waiting, tr("Connect the first controller, alone (a new one answers at id "
                                "%1, %2 baud), then press Next. It gets id %3.")
                                 .arg(kFactoryId)
                                 .arg(kFactoryBaud)
                                 .arg(nextId()));
    return true;
}

void IdAssigner::next()
{
    if (m_state != State::Waiting && m_state != State::Collision && m_state != State::Failed)
        return;
    m_target = nextId();
    if (m_target == 0) {
        setState(State::Failed,
                 tr("No free id is left (every id from %1 to 255 is on the list).").arg(m_firstId));
        return;
    }
    setState(State::Working,
             tr("Giving the controller at id %1 the id %2…").arg(kFactoryId).arg(m_target));
    // New controllers listen at the factory baud; the last one may have moved the line.
    QPointer<IdAssigner> self(this);
    m_session->line()->setLineBaud(kFactoryBaud, [self](bool ok, const QString &reason) {
        if (!self)
            return;
        if (!ok) {
            self->setState(State::Failed,
                           tr("Cannot open the port at %1 baud: %2").arg(kFactoryBaud).arg(reason));
            return;
        }
        self->change();
    });
}

void IdAssigner::change()
{
    m_change->start(kFactoryId, m_target, m_commonBaud);
}

void IdAssigner::onChanged(bool ok, const QString &text)
{
    if (m_state != State::Working)
        return;
    if (!ok) {
        if (m_change->problem() == IdChange::Problem::Collision)
            setState(State::Collision,
                     tr("Refused: %1. Two controllers with the same id answer at once and garble "
                        "each other's answers; nothing was written.")
                         .arg(text));
        else
            setState(State::Failed, tr("The controller did not get id %1: %2. Check it is "
                                       "the only new controller on the line, then press Next to "
                                       "try again.")
                                        .arg(m_target)
                                        .arg(text));
        return;
    }
    m_assigned << m_target;
    Q_EMIT deviceAdded(m_target);
    setState(State::Waiting, tr("%1. Connect the next controller, alone, then press Next (it "
                                "gets id %2), or Finish.")
                                 .arg(text)
                                 .arg(nextId()));
}

void IdAssigner::finish()
{
    if (m_state == State::Working || m_state == State::Idle)
        return;
    const int baud = m_commonBaud > 0 ? m_commonBaud : kFactoryBaud;
    setState(State::Working, tr("Moving the line to %1 baud…").arg(baud));
    QPointer<IdAssigner> self(this);
    m_session->line()->setLineBaud(baud, [self, baud](bool ok, const QString &reason) {
        if (!self)
            return;
        if (!ok) {
            self->setState(State::Failed,
                           tr("Cannot open the port at %1 baud: %2").arg(baud).arg(reason));
            return;
        }
        self->rollCall(0, baud, {});
    });
}

void IdAssigner::rollCall(int index, int baud, QList<int> silent)
{
    // Every controller given an id answers at the line's final baud, or the text says which not.
    if (index < m_assigned.size()) {
        const int id = m_assigned.at(index);
        const Parameter *idParam = m_session->map().find(QStringLiteral("device.id"));
        Q_EMIT progress(tr("Asking id %1 at %2 baud").arg(id).arg(baud));
        QPointer<IdAssigner> self(this);
        m_session->line()->readAt(id, {idParam},
                                  [self, index, baud, silent, id](const ReadOutcome &r) {
                                      if (!self)
                                          return;
                                      QList<int> still = silent;
                                      if (!r.ok)
                                          still << id;
                                      self->rollCall(index + 1, baud, still);
                                  });
        return;
    }
    if (!m_assigned.isEmpty()) {
        // The factory id was only where new controllers arrived.
        QList<int> ids = m_session->line()->deviceIds();
        ids.removeAll(kFactoryId);
        for (int id : std::as_const(m_assigned))
            if (!ids.contains(id))
                ids << id;
        m_session->line()->setDeviceIds(ids);
        m_session->line()->showDevice(m_assigned.constFirst());
    }
    resumeLive();
    QList<int> answering = m_assigned;
    for (int id : std::as_const(silent))
        answering.removeAll(id);
    QString text;
    if (m_assigned.isEmpty())
        text = tr("Finished: no controller was given an id.");
    else if (silent.isEmpty())
        text = tr("Finished: the line is at %1 baud; every controller given an id answers: id %2.")
                   .arg(baud)
                   .arg(IdList::format(m_assigned));
    else
        text = tr("Finished: the line is at %1 baud. Answering: id %2. NOT answering: id %3 — "
                  "check its power and wiring; it stays on the device list.")
                   .arg(baud)
                   .arg(answering.isEmpty() ? tr("none") : IdList::format(answering),
                        IdList::format(silent));
    setState(State::Finished, text);
}

void IdAssigner::setState(State state, const QString &text)
{
    m_text = text;
    m_state = state;
    Q_EMIT stateChanged(state);
}

void IdAssigner::resumeLive()
{
    if (!std::exchange(m_paused, false))
        return;
    m_session->setLive(m_wasLive);
}

} // namespace stepcom
