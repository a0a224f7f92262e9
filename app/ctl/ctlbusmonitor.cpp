#include "ctlbusmonitor.h"

#include "ctlmonitor.h"
#include "session/buspoller.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "signalwatcher.h"

#include <algorithm>
#include <cstdio>

namespace stepcom {

CtlBusMonitor::CtlBusMonitor(DeviceSession *session, const QList<int> &ids, int count,
                             int intervalMs, bool json, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_ids(ids)
    , m_params(CtlMonitor::statusParameters(*session))
    , m_poller(new BusPoller(
          session->map(),
          [this](int id, const QList<const Parameter *> &params,
                 std::function<void(const ReadOutcome &)> done) { read(id, params, done); },
          this))
    , m_count(count)
    , m_json(json)
    , m_out(stdout)
    , m_err(stderr)
{
    QStringList keys;
    for (const Parameter *p : std::as_const(m_params))
        keys << p->key;
    m_poller->setKeys(keys);
    m_poller->setPacing(BusPoller::Pacing::Rounds);
    m_poller->setIntervalMs(intervalMs);
    m_poller->setDevices(m_ids);
    connect(m_session->connection(), &SessionConnection::linkLost, this,
            [this](const QString &reason) {
                sayError(tr("link lost: %1").arg(reason));
                end(1);
            });
    // The session watches each device's reads for a restart; said per device as `monitor`
    // of one says it.
    CtlMonitor::sayRestarts(m_session, this,
                            [this](const QString &name, const QString &text,
                                   const QString &fields) { event(name, text, fields); });
}

void CtlBusMonitor::event(const QString &name, const QString &text, const QString &fields)
{
    if (m_ended)
        return;
    ++m_events;
    if (!m_json) {
        m_err << QStringLiteral("stepcomctl: ") << text << Qt::endl;
        return;
    }
    m_out << CtlMonitor::eventLine(name, m_clock.elapsed(), fields) << QLatin1Char('\n');
    m_out.flush();
    std::fflush(stdout);
}

void CtlBusMonitor::start()
{
    // Ctrl-C and SIGTERM end the run between two lines, never in the middle of one.
    m_signals = new SignalWatcher(this);
    connect(m_signals, &SignalWatcher::terminationRequested, this,
            [this] { end(anyFailed() ? 1 : 0); });
    m_clock.start();
    m_poller->start();
}

QString CtlBusMonitor::sampleLine(int id, qint64 tMs, const QHash<QString, qint64> &values) const
{
    const auto raw = [&values](const QString &key) {
        const auto it = values.constFind(key);
        return it == values.cend() ? std::nullopt : std::optional<qint64>(*it);
    };
    if (m_json)
        return QStringLiteral("{\"id\":%1,").arg(id) + CtlMonitor::timeFields(tMs) +
               CtlMonitor::valueFields(m_params, raw) + QLatin1Char('}');
    QString line = tr("id %1").arg(id) + QStringLiteral("  t_ms=%1").arg(tMs);
    for (const Parameter *p : m_params) {
        const std::optional<qint64> value = raw(p->key);
        line += QStringLiteral("  %1=%2").arg(p->key,
                                              value ? p->formatRaw(*value) : QStringLiteral("?"));
    }
    return line;
}

void CtlBusMonitor::read(int id, const QList<const Parameter *> &params,
                         const std::function<void(const ReadOutcome &)> &done)
{
    m_session->line()->showDevice(id); // the one-shot session reads nothing on its own when shown
    m_session->parameters()->read(
        params,
        [this, id, done](const ReadOutcome &r) {
            done(r); // the poller counts it and arms the next turn
            onRead(id, r);
        },
        Priority::Poll);
}

void CtlBusMonitor::onRead(int id, const ReadOutcome &outcome)
{
    if (m_ended)
        return;
    m_session->statusSampled(id, outcome.ok, outcome.values);
    if (outcome.ok) {
        m_out << sampleLine(id, m_clock.elapsed(), outcome.values) << QLatin1Char('\n');
        m_out.flush();
        std::fflush(stdout);
    } else {
        // A device that does not answer is no reason to stop watching the others.
        sayError(tr("id %1: %2").arg(id).arg(outcome.errors.join(QLatin1String("; "))));
    }
    if (countReached())
        end(anyFailed() ? 1 : 0);
}

bool CtlBusMonitor::countReached() const
{
    if (m_count < 1)
        return false;
    return std::all_of(m_ids.cbegin(), m_ids.cend(),
                       [this](int id) { return m_poller->status(id).cycles >= m_count; });
}

bool CtlBusMonitor::anyFailed() const
{
    return std::any_of(m_ids.cbegin(), m_ids.cend(),
                       [this](int id) { return m_poller->status(id).errors > 0; });
}

void CtlBusMonitor::sayError(const QString &text)
{
    m_err << QStringLiteral("stepcomctl: ") << text << Qt::endl;
    m_errors << text;
}

QJsonObject CtlBusMonitor::summary() const
{
    QJsonObject samples;
    QJsonObject failed;
    for (const int id : m_ids) {
        const BusDeviceStatus s = m_poller->status(id);
        samples.insert(QString::number(id), s.cycles - s.errors);
        failed.insert(QString::number(id), s.errors);
    }
    return {{QStringLiteral("samples"), samples},
            {QStringLiteral("failed"), failed},
            {QStringLiteral("events"), m_events}};
}

void CtlBusMonitor::end(int exitCode)
{
    if (m_ended)
        return;
    m_ended = true;
    m_poller->stop();
    m_out.flush();
    Q_EMIT finished(exitCode);
}

} // namespace stepcom
