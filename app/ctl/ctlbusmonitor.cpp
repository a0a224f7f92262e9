#include "ctlbusmonitor.h"

#include "ctlmonitor.h"
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
    , m_count(count)
    , m_intervalMs(std::max(0, intervalMs))
    , m_json(json)
    , m_out(stdout)
    , m_err(stderr)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &CtlBusMonitor::turn);
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
            [this] { end(m_failed.isEmpty() ? 0 : 1); });
    m_clock.start();
    m_round.start();
    turn();
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

void CtlBusMonitor::turn()
{
    if (m_ended)
        return;
    const int id = m_ids.at(m_next);
    if (m_next == 0)
        m_round.restart();
    m_session->line()->showDevice(id); // the one-shot session reads nothing on its own when shown
    const quint64 generation = m_generation;
    m_session->parameters()->read(
        m_params, [this, generation, id](const ReadOutcome &r) { onRead(generation, id, r); },
        Priority::Poll);
}

void CtlBusMonitor::onRead(quint64 generation, int id, const ReadOutcome &outcome)
{
    if (generation != m_generation || m_ended)
        return;
    ++m_samples[id];
    m_session->statusSampled(id, outcome.ok, outcome.values);
    if (outcome.ok) {
        m_out << sampleLine(id, m_clock.elapsed(), outcome.values) << QLatin1Char('\n');
        m_out.flush();
        std::fflush(stdout);
    } else {
        // A device that does not answer is no reason to stop watching the others.
        ++m_failed[id];
        sayError(tr("id %1: %2").arg(id).arg(outcome.errors.join(QLatin1String("; "))));
    }
    if (countReached()) {
        end(m_failed.isEmpty() ? 0 : 1);
        return;
    }
    m_next = (m_next + 1) % int(m_ids.size());
    // The next device at once; the next round no sooner than the interval after the last began.
    const qint64 wait = m_next == 0 ? std::max<qint64>(0, m_intervalMs - m_round.elapsed()) : 0;
    m_timer.start(int(wait));
}

bool CtlBusMonitor::countReached() const
{
    if (m_count < 1)
        return false;
    return std::all_of(m_ids.cbegin(), m_ids.cend(),
                       [this](int id) { return m_samples.value(id) >= m_count; });
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
        samples.insert(QString::number(id), m_samples.value(id) - m_failed.value(id));
        failed.insert(QString::number(id), m_failed.value(id));
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
    ++m_generation;
    m_timer.stop();
    m_out.flush();
    Q_EMIT finished(exitCode);
}

} // namespace stepcom
