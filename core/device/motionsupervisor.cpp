#include "device/motionsupervisor.h"

#include "bus/modbuslink.h"
#include "device/devicesession.h"
#include "device/motionjudge.h"
#include "device/referencetracker.h"

#include <QPointer>

namespace stepcom {

MotionSupervisor::MotionSupervisor(DeviceSession *session, ModbusLink *link)
    : QObject(session)
    , m_session(session)
    , m_references(new ReferenceTracker(session->map().blockCount(QStringLiteral("motor")), this))
{
    for (const Parameter &p : session->map().parameters()) {
        if (p.isCoil())
            m_coils.insert(p.address, p.key);
    }
    connect(session, &DeviceSession::commandFinished, this, &MotionSupervisor::onCommandFinished);
    connect(session, &DeviceSession::disconnected, this, &MotionSupervisor::onDisconnected);
    // Every stop goes through the link, whoever sent it (jog controller, E-STOP, stop buttons).
    connect(link, &ModbusLink::dispatched, this,
            [this](quint64, const Request &r) { onDispatched(r); });
    connect(session, &DeviceSession::statusCycleFinished, this,
            [this](bool ok, qint64) { onCycle(ok); });
}

MotionSupervisor::~MotionSupervisor() = default;

StatusValues MotionSupervisor::snapshot() const
{
    StatusValues v;
    const ParameterStore *store = m_session->parameters();
    for (const Parameter *p : m_session->map().holdings()) {
        if (const auto raw = store->deviceValue(p->key))
            v.insert(p->key, *raw);
    }
    return v;
}

std::optional<MotionStart> MotionSupervisor::active(int motor) const
{
    for (const Followed &f : m_followed) {
        if (f.watch.start().motors.contains(motor))
            return f.watch.start();
    }
    return std::nullopt;
}

std::optional<MotionStart> MotionSupervisor::active(MotionKind kind) const
{
    for (const Followed &f : m_followed) {
        if (f.watch.start().kind == kind)
            return f.watch.start();
    }
    return std::nullopt;
}

QList<int> MotionSupervisor::running(MotionKind kind) const
{
    for (const Followed &f : m_followed) {
        if (f.watch.start().kind == kind)
            return f.watch.running();
    }
    return {};
}

std::optional<MotionOutcome> MotionSupervisor::lastOutcome(int motor) const
{
    const auto it = m_byMotor.constFind(motor);
    return it == m_byMotor.cend() ? std::nullopt : std::optional<MotionOutcome>(*it);
}

std::optional<MotionOutcome> MotionSupervisor::lastOutcome(MotionKind kind) const
{
    const auto it = m_byKind.constFind(int(kind));
    return it == m_byKind.cend() ? std::nullopt : std::optional<MotionOutcome>(*it);
}

QString MotionSupervisor::text(const MotionOutcome &outcome) const
{
    return MotionJudge::text(m_session->map(), outcome);
}

QString MotionSupervisor::startWarning(const QString &command) const
{
    return MotionJudge::limitWarning(m_session->map(), command, snapshot());
}

int MotionSupervisor::indexOf(quint64 id) const
{
    for (int i = 0; i < m_followed.size(); ++i) {
        if (m_followed.at(i).id == id)
            return i;
    }
    return -1;
}

void MotionSupervisor::onCommandFinished(const QString &key, bool ok)
{
    if (!ok)
        return;
    // The store still holds what the last poll read before the command went out.
    const auto start = MotionJudge::plan(m_session->map(), key, snapshot());
    if (!start)
        return;
    // A new motion of the same axes replaces the one followed so far.
    for (int i = int(m_followed.size()) - 1; i >= 0; --i) {
        for (int n : start->motors) {
            if (m_followed.at(i).watch.start().motors.contains(n)) {
                m_followed.removeAt(i);
                break;
            }
        }
    }
    m_followed.append({m_nextId++, MotionWatch(m_session->map(), *start), false});
    Q_EMIT started(*start);
    Q_EMIT changed();
}

void MotionSupervisor::onDispatched(const Request &request)
{
    if (request.type != Request::Type::WriteCoil || !request.coilOn)
        return;
    const QString key = m_coils.value(request.address);
    const Parameter *p = m_session->map().find(key);
    if (!p)
        return;
    if (key == QLatin1String("estop")) {
        for (Followed &f : m_followed)
            f.watch.interrupt(MotionCause::EmergencyStop);
        m_references->loseAll(ReferenceTracker::Reason::EmergencyStop);
        Q_EMIT emergencyStopSent();
    } else if (key == QLatin1String("zero_coordinates")) {
        m_references->loseAll(ReferenceTracker::Reason::Zeroed);
    } else if (p->block == QLatin1String("motor") && p->localKey == QLatin1String("stop")) {
        for (Followed &f : m_followed) {
            if (f.watch.start().motors.contains(p->instance))
                f.watch.interrupt(MotionCause::Stop);
        }
    } else if (key == QLatin1String("arc.stop") || key == QLatin1String("line.stop")) {
        const MotionKind kind =
            key == QLatin1String("arc.stop") ? MotionKind::Arc : MotionKind::Line;
        for (Followed &f : m_followed) {
            if (f.watch.start().kind == kind)
                f.watch.interrupt(MotionCause::Stop);
        }
    }
}

void MotionSupervisor::onCycle(bool ok)
{
    if (!ok || m_followed.isEmpty())
        return;
    const StatusValues now = snapshot();
    QList<quint64> over;
    for (Followed &f : m_followed) {
        if (!f.judging && f.watch.sample(now)) {
            f.judging = true;
            over << f.id;
        }
    }
    Q_EMIT changed();
    for (quint64 id : std::as_const(over))
        readEndThenJudge(id);
}

void MotionSupervisor::readEndThenJudge(quint64 id)
{
    // Fast polls leave the inputs out: read where the axes ended and what the inputs say now.
    QList<const Parameter *> params;
    for (const QString &k : MotionJudge::watchKeys(m_session->map()))
        params << m_session->map().find(k);
    m_session->read(
        params,
        [self = QPointer<MotionSupervisor>(this), id](const ReadOutcome &r) {
            if (!self || self->indexOf(id) < 0)
                return;
            StatusValues end = self->snapshot();
            for (auto it = r.values.cbegin(); it != r.values.cend(); ++it)
                end.insert(it.key(), it.value());
            self->conclude(id, end);
        },
        Priority::Read);
}

void MotionSupervisor::conclude(quint64 id, const StatusValues &end)
{
    const int i = indexOf(id);
    if (i < 0)
        return;
    const Followed f = m_followed.takeAt(i);
    const MotionOutcome o =
        MotionJudge::judge(m_session->map(), f.watch.start(), end, f.watch.cause());
    for (const AxisEnd &a : o.axes)
        m_byMotor.insert(a.motor, o);
    m_byKind.insert(int(o.start.kind), o);
    if (o.start.kind == MotionKind::Home || o.start.kind == MotionKind::HomeInOrder) {
        using Reason = ReferenceTracker::Reason;
        for (const AxisEnd &a : o.axes)
            m_references->setReason(a.motor, a.referenced && o.cause == MotionCause::None
                                                 ? Reason::Homed
                                             : o.cause != MotionCause::None ? Reason::HomingStopped
                                                                            : Reason::HomingFailed);
    }
    Q_EMIT finished(o);
    Q_EMIT changed();
}

void MotionSupervisor::onDisconnected()
{
    m_references->loseAll(ReferenceTracker::Reason::LinkLost);
    // The store has forgotten the device values: judge from the last sample each one saw.
    QList<QPair<quint64, StatusValues>> open;
    for (Followed &f : m_followed) {
        f.watch.interrupt(MotionCause::LinkLost);
        open.append({f.id, f.watch.last()});
    }
    for (const auto &[id, last] : std::as_const(open))
        conclude(id, last);
}

} // namespace stepcom
