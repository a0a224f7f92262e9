// DeviceSession: a restart of a controller seen and said. RestartWatch suspects it from the
// status reads; the session reads everything of that controller again and compares it with
// what it held, so what is said is what the controller showed, not a guess.
#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/devicememory.h"
#include "device/parameterstore.h"
#include "i18n/translators.h"
#include "motion/referencetracker.h"
#include "session/buspoller.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/restartwatch.h"

#include <QDateTime>

namespace stepcom {

namespace {

qint64 nowMs()
{
    return QDateTime::currentMSecsSinceEpoch();
}

} // namespace

void DeviceSession::watchRestarts()
{
    m_restarts = new RestartWatch(map(), this);
    connect(m_poller, &Poller::cycleFinished, m_restarts, [this](bool ok) {
        QHash<QString, qint64> values;
        for (const QString &key : m_poller->keys()) {
            if (const auto raw = m_store->deviceValue(key))
                values.insert(key, *raw);
        }
        m_restarts->statusRead(m_line->deviceInView(), ok, values, nowMs());
    });
    connect(m_bus, &BusPoller::statusChanged, m_restarts, [this](int id) {
        if (id == m_line->deviceInView())
            return; // the live poll's cycle above
        const BusDeviceStatus s = m_bus->status(id);
        m_restarts->statusRead(id, s.state == BusDeviceStatus::State::Answering, s.values, nowMs());
    });
    QHash<quint16, QString> coils;
    for (const Parameter *p : map().coils())
        coils.insert(p->address, p->key);
    connect(m_link, &ModbusLink::dispatched, m_restarts, [this, coils](quint64, const Request &r) {
        const QString key = coils.value(r.address);
        if (r.type == Request::Type::WriteCoil && r.coilOn && m_restarts->movesOrZeroes(key))
            m_restarts->commandSent(r.unitId > 0 ? r.unitId : m_link->settings().deviceId, nowMs(),
                                    RestartWatch::motorsOf(map(), key));
    });
    connect(m_connection, &SessionConnection::disconnected, m_restarts, &RestartWatch::forget);
    connect(m_restarts, &RestartWatch::suspected, this, &DeviceSession::checkRestart);
}

void DeviceSession::statusSampled(int id, bool ok, const QHash<QString, qint64> &values)
{
    m_restarts->statusRead(id, ok, values, nowMs());
}

void DeviceSession::checkRestart(int id, const QString &why, RestartWatch::Zeros zeros,
                                 const RestartWatch::Evidence &seen)
{
    // Before a motion is judged from the zeros.
    if (zeros == RestartWatch::Zeros::Reset)
        m_motion->restarted(id);
    else if (zeros == RestartWatch::Zeros::AfterMotion)
        m_motion->silent(id);
    if (m_checkingRestart.contains(id) || !m_link->isConnected())
        return;
    m_checkingRestart.insert(id);
    const QHash<QString, qint64> held = m_line->knownValues(id);
    m_line->readDevice(id, map().holdings(),
                       [this, id, why, zeros, seen, held](const ReadOutcome &r) {
                           m_checkingRestart.remove(id);
                           restartChecked(id, why, zeros, seen, held, r);
                       });
}

void DeviceSession::restartChecked(int id, const QString &why, RestartWatch::Zeros zeros,
                                   const RestartWatch::Evidence &seen,
                                   const QHash<QString, qint64> &held, const ReadOutcome &read)
{
    const QString locale = Translators::current();
    const QString device = m_line->deviceIds().size() > 1 ? tr("Device %1: ").arg(id) : QString();
    // What was seen, in words: the silence or the zeros, then each axis.
    const QString evidence = RestartWatch::describe(seen, map(), why);
    // Positions at 0 after a motion prove nothing: it may have ended there.
    const bool afterMotion = zeros == RestartWatch::Zeros::AfterMotion;
    if (!read.ok) {
        const QString failed = read.errors.join(QLatin1String("; "));
        if (zeros == RestartWatch::Zeros::Reset) {
            say(Severity::Warning,
                device + tr("The controller restarted (power off?): positions lost; references "
                            "lost. Seen: %1. Reading it again failed (%2): what else it lost is "
                            "not known.")
                             .arg(evidence, failed));
            Q_EMIT controllerRestarted(id, {}, seen);
            return;
        }
        say(Severity::Warning, device + tr("The controller may have restarted (%1), but reading it "
                                           "again failed: %2")
                                            .arg(evidence, failed));
        if (afterMotion)
            Q_EMIT controllerMayHaveRestarted(id, seen);
        return;
    }
    QStringList lost;
    bool positionsLost = zeros == RestartWatch::Zeros::Reset;
    for (const Parameter *p : map().holdings()) {
        const auto was = held.constFind(p->key);
        const auto now = read.values.constFind(p->key);
        if (was == held.cend() || now == read.values.cend() || *was == *now)
            continue;
        if (p->localKey == QLatin1String("position"))
            positionsLost = positionsLost || (*now == 0 && !afterMotion);
        else if (p->writable())
            lost << QStringLiteral("%1 %2 → %3")
                        .arg(p->key, p->displayRaw(*was, locale), p->displayRaw(*now, locale));
    }
    // The values read are what the controller holds now; edits the user holds stay held.
    if (id == m_line->deviceInView())
        m_store->setDeviceValues(read.values);
    else
        m_memory->setDeviceValues(id, read.values);
    if (lost.isEmpty() && !positionsLost && afterMotion) {
        say(Severity::Warning,
            device + tr("The controller may have restarted (power off?): %1. Every axis reads 0, "
                        "but only axes that were moving went there: whether they ended there or "
                        "the controller restarted cannot be told. The references are not known: "
                        "home again.")
                         .arg(evidence));
        Q_EMIT controllerMayHaveRestarted(id, seen);
        return;
    }
    if (lost.isEmpty() && !positionsLost) {
        say(Severity::Info, device + tr("The controller answers again (%1); what it holds is what "
                                        "StepCom held: nothing shows a restart.")
                                         .arg(why));
        return;
    }
    if (id == m_line->deviceInView())
        m_store->setUnsavedToFlash(false); // it came back with what its flash holds
    m_motion->restarted(id);
    QStringList what{tr("positions lost"), tr("references lost")};
    if (!lost.isEmpty())
        what << tr("changes not saved to flash lost: %1").arg(lost.join(QLatin1String(", ")));
    say(Severity::Warning, device + tr("The controller restarted (power off?): %1. Seen: %2.")
                                        .arg(what.join(QLatin1String("; ")), evidence));
    Q_EMIT controllerRestarted(id, lost, seen);
}

} // namespace stepcom
