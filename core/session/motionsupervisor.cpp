#include "session/motionsupervisor.h"

#include "bus/modbuslink.h"
#include "motion/motionjudge.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"

#include <QPointer>

namespace stepcom {

namespace {

// Why an axis is not referenced once `cause` (not None) cut a homing or came after it.
ReferenceTracker::Reason lostReference(MotionCause cause)
{
    using Reason = ReferenceTracker::Reason;
    switch (cause) {
    case MotionCause::Silent:
        return Reason::Silent;
    case MotionCause::Restarted:
        return Reason::Restarted;
    case MotionCause::None:
    case MotionCause::Stop:
    case MotionCause::EmergencyStop:
    case MotionCause::LinkLost:
        break;
    }
    return Reason::HomingStopped;
}

} // namespace

MotionSupervisor::MotionSupervisor(DeviceSession *session, ModbusLink *link)
    : QObject(session)
    , m_session(session)
    , m_link(link)
    , m_references(new ReferenceTracker(session->map().blockCount(QStringLiteral("motor")), this))
{
    for (const Parameter &p : session->map().parameters()) {
        if (p.isCoil())
            m_coils.insert(p.address, p.key);
    }
    connect(session->connection(), &SessionConnection::disconnected, this,
            &MotionSupervisor::onDisconnected);
    // Every stop goes through the link, whoever sent it (jog controller, E-STOP, stop buttons).
    connect(link, &ModbusLink::dispatched, this,
            [this](quint64, const Request &r) { onDispatched(r); });
    connect(session->status(), &SessionStatus::statusCycleFinished, this,
            [this](bool ok, qint64) { statusRead(m_session->line()->deviceInView(), ok); });
    connect(session->line(), &SessionLine::deviceStatusChanged, this, [this](int device) {
        statusRead(device, m_session->line()->deviceStatus(device).state ==
                               BusDeviceStatus::State::Answering);
    });
    connect(session->connection(), &SessionConnection::connected, this, [this](bool ok) {
        if (ok)
            setView(m_session->line()->deviceInView());
    });
    connect(session->line(), &SessionLine::deviceInViewChanged, this, &MotionSupervisor::setView);
    // A write of device.id moved the controller in view: what is known of it goes along.
    connect(session->line(), &SessionLine::linkChanged, this, [this](const LinkSettings &s) {
        if (s.deviceId == m_view || m_devices.contains(s.deviceId))
            return setView(s.deviceId);
        m_devices.insert(s.deviceId, m_devices.take(m_view));
        m_references->renameView(s.deviceId);
        m_view = s.deviceId;
        Q_EMIT changed();
    });
}

MotionSupervisor::~MotionSupervisor() = default;

StatusValues MotionSupervisor::snapshot(int device) const
{
    return m_session->line()->knownValues(device);
}

const MotionSupervisor::Device &MotionSupervisor::inView() const
{
    static const Device none;
    const auto it = m_devices.constFind(m_view);
    return it == m_devices.cend() ? none : *it;
}

void MotionSupervisor::setView(int device)
{
    if (device == m_view)
        return;
    m_view = device;
    m_references->setView(device);
    Q_EMIT changed();
}

std::optional<MotionStart> MotionSupervisor::active(int motor) const
{
    for (const Followed &f : inView().followed) {
        if (f.watch.start().motors.contains(motor))
            return f.watch.start();
    }
    return std::nullopt;
}

std::optional<MotionStart> MotionSupervisor::active(MotionKind kind) const
{
    for (const Followed &f : inView().followed) {
        if (f.watch.start().kind == kind)
            return f.watch.start();
    }
    return std::nullopt;
}

QList<MotionStart> MotionSupervisor::activeOn(int device) const
{
    QList<MotionStart> starts;
    for (const Followed &f : m_devices.value(device).followed)
        starts << f.watch.start();
    return starts;
}

QList<int> MotionSupervisor::running(MotionKind kind) const
{
    for (const Followed &f : inView().followed) {
        if (f.watch.start().kind == kind)
            return f.watch.running();
    }
    return {};
}

std::optional<MotionOutcome> MotionSupervisor::lastOutcome(int motor) const
{
    const auto it = inView().byMotor.constFind(motor);
    return it == inView().byMotor.cend() ? std::nullopt : std::optional<MotionOutcome>(*it);
}

std::optional<MotionOutcome> MotionSupervisor::lastOutcome(MotionKind kind) const
{
    const auto it = inView().byKind.constFind(int(kind));
    return it == inView().byKind.cend() ? std::nullopt : std::optional<MotionOutcome>(*it);
}

QString MotionSupervisor::text(const MotionOutcome &outcome) const
{
    return MotionJudge::text(m_session->map(), outcome);
}

QString MotionSupervisor::startWarning(const QString &command) const
{
    return MotionJudge::limitWarning(m_session->map(), command, snapshot(m_view));
}

int MotionSupervisor::indexOf(const Device &d, quint64 id)
{
    for (int i = 0; i < d.followed.size(); ++i) {
        if (d.followed.at(i).id == id)
            return i;
    }
    return -1;
}

void MotionSupervisor::commandAcknowledged(int device, const QString &key)
{
    // The values still hold what the last poll read before the command went out.
    const auto start = MotionJudge::plan(m_session->map(), key, snapshot(device));
    if (!start)
        return;
    QList<Followed> &followed = m_devices[device].followed;
    // A new motion of the same axes replaces the one followed so far.
    for (int i = int(followed.size()) - 1; i >= 0; --i) {
        for (int n : start->motors) {
            if (followed.at(i).watch.start().motors.contains(n)) {
                followed.removeAt(i);
                break;
            }
        }
    }
    followed.append({m_nextId++, MotionWatch(m_session->map(), *start), false});
    if (device == m_view)
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
    // The controller it is addressed to (0: the link's device id as it went out).
    const int device = request.unitId > 0 ? request.unitId : m_link->settings().deviceId;
    QList<Followed> &followed = m_devices[device].followed;
    if (key == QLatin1String("estop")) {
        for (Followed &f : followed)
            f.watch.interrupt(MotionCause::EmergencyStop);
        m_references->loseAll(device, ReferenceTracker::Reason::EmergencyStop);
        Q_EMIT emergencyStopSent();
    } else if (key == QLatin1String("zero_coordinates")) {
        m_references->loseAll(device, ReferenceTracker::Reason::Zeroed);
    } else if (p->block == QLatin1String("motor") && p->localKey == QLatin1String("stop")) {
        for (Followed &f : followed) {
            if (f.watch.start().motors.contains(p->instance))
                f.watch.interrupt(MotionCause::Stop);
        }
    } else if (key == QLatin1String("arc.stop") || key == QLatin1String("line.stop")) {
        const MotionKind kind =
            key == QLatin1String("arc.stop") ? MotionKind::Arc : MotionKind::Line;
        for (Followed &f : followed) {
            if (f.watch.start().kind == kind)
                f.watch.interrupt(MotionCause::Stop);
        }
    }
}

void MotionSupervisor::statusRead(int device, bool ok)
{
    const auto it = m_devices.find(device);
    if (!ok || it == m_devices.end() || it->followed.isEmpty())
        return;
    const StatusValues now = snapshot(device);
    QList<quint64> over;
    for (Followed &f : it->followed) {
        if (!f.judging && f.watch.sample(now)) {
            f.judging = true;
            over << f.id;
        }
    }
    Q_EMIT changed();
    for (quint64 id : std::as_const(over))
        readEndThenJudge(device, id);
}

void MotionSupervisor::readEndThenJudge(int device, quint64 id)
{
    // Fast polls leave the inputs out: read where the axes ended and what the inputs say now,
    // from the controller that moved, whichever is in view by now.
    QList<const Parameter *> params;
    for (const QString &k : MotionJudge::watchKeys(m_session->map()))
        params << m_session->map().find(k);
    auto *client = new DeviceClient(m_link, m_session->map(), this);
    client->setUnitId(device);
    client->read(
        params, Priority::Read,
        [self = QPointer<MotionSupervisor>(this), client, device, id](const ReadOutcome &r) {
            client->deleteLater();
            if (!self || indexOf(self->m_devices.value(device), id) < 0)
                return;
            StatusValues end = self->snapshot(device);
            for (auto it = r.values.cbegin(); it != r.values.cend(); ++it)
                end.insert(it.key(), it.value());
            self->conclude(device, id, end);
        });
}

void MotionSupervisor::conclude(int device, quint64 id, const StatusValues &end)
{
    Device &d = m_devices[device];
    const int i = indexOf(d, id);
    if (i < 0)
        return;
    const Followed f = d.followed.takeAt(i);
    const MotionOutcome o =
        MotionJudge::judge(m_session->map(), f.watch.start(), end, f.watch.cause());
    for (const AxisEnd &a : o.axes)
        d.byMotor.insert(a.motor, o);
    d.byKind.insert(int(o.start.kind), o);
    if (o.start.kind == MotionKind::Home || o.start.kind == MotionKind::HomeInOrder) {
        using Reason = ReferenceTracker::Reason;
        for (const AxisEnd &a : o.axes)
            m_references->setReasonOn(device, a.motor,
                                      a.referenced && o.cause == MotionCause::None ? Reason::Homed
                                      : o.cause != MotionCause::None ? lostReference(o.cause)
                                                                     : Reason::HomingFailed);
    }
    if (device == m_view)
        Q_EMIT finished(o);
    Q_EMIT deviceFinished(device, o);
    Q_EMIT changed();
}

void MotionSupervisor::interrupted(int device, MotionCause cause)
{
    // Judged from the last sample before the restart (or the silence): the positions after it
    // mean nothing.
    QList<std::pair<quint64, StatusValues>> open;
    for (Followed &f : m_devices[device].followed) {
        f.watch.interrupt(cause);
        open.append({f.id, f.watch.last()});
    }
    for (const auto &[id, last] : std::as_const(open))
        conclude(device, id, last);
    m_references->loseAll(device, lostReference(cause));
    // A silence that was only a possible restart, proven one after all (by what it lost).
    if (cause == MotionCause::Restarted) {
        using Reason = ReferenceTracker::Reason;
        for (int n = 1; n <= m_references->motorCount(); ++n) {
            if (m_references->reasonOn(device, n) == Reason::Silent)
                m_references->setReasonOn(device, n, Reason::Restarted);
        }
    }
}

void MotionSupervisor::onDisconnected()
{
    m_references->loseEverywhere(ReferenceTracker::Reason::LinkLost);
    // The values are forgotten: judge each motion from the last sample its watch saw.
    QList<std::tuple<int, quint64, StatusValues>> open;
    for (auto it = m_devices.begin(); it != m_devices.end(); ++it) {
        for (Followed &f : it->followed) {
            f.watch.interrupt(MotionCause::LinkLost);
            open.append({it.key(), f.id, f.watch.last()});
        }
    }
    for (const auto &[device, id, last] : std::as_const(open))
        conclude(device, id, last);
}

} // namespace stepcom
