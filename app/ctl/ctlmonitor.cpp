#include "ctlmonitor.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/reconnector.h"
#include "signalwatcher.h"

#include <QDateTime>

#include <cstdio>

namespace stepcom {

namespace {

int rank(const Parameter *p)
{
    if (p->key.endsWith(QLatin1String(".position")))
        return 0;
    if (p->key.endsWith(QLatin1String(".running")))
        return 1;
    return 2;
}

// JSON string escaping for keys: map keys are plain ASCII, but a custom map may say otherwise.
QString quoted(const QString &text)
{
    QString out = QStringLiteral("\"");
    for (const QChar c : text) {
        if (c == QLatin1Char('"') || c == QLatin1Char('\\'))
            out += QLatin1Char('\\') + c;
        else if (c.unicode() < 0x20)
            out += QStringLiteral("\\u%1").arg(int(c.unicode()), 4, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out + QLatin1Char('"');
}

} // namespace

CtlMonitor::CtlMonitor(DeviceSession *session, int count, int intervalMs, bool json,
                       QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_count(count)
    , m_json(json)
    , m_out(stdout)
    , m_err(stderr)
{
    m_session->status()->setIntervalMs(intervalMs);
    m_params = statusParameters(*m_session);
    connect(m_session->status(), &SessionStatus::statusCycleFinished, this,
            [this](bool ok, qint64) { onCycle(ok); });
    // A pulled cable is no reason to stop watching: try again, say so, go on.
    Reconnector *reconnector = m_session->connection()->reconnector();
    reconnector->setEnabled(true);
    connect(m_session->connection(), &SessionConnection::linkLost, this,
            [this](const QString &reason) {
                event(QStringLiteral("lost"),
                      tr("link lost: %1; trying again on its own (Ctrl-C ends)").arg(reason),
                      QStringLiteral(",\"reason\":") + quoted(reason));
            });
    connect(reconnector, &Reconnector::restored, this, [this](const LinkSettings &s, int n) {
        event(QStringLiteral("back"),
              tr("link back at %1 after %n attempt(s)", nullptr, n).arg(s.describe()),
              QStringLiteral(",\"port\":") +
                  quoted(s.transport == LinkSettings::Transport::Tcp
                             ? QStringLiteral("%1:%2").arg(s.host).arg(s.tcpPort)
                             : s.portName));
    });
    connect(reconnector, &Reconnector::cancelled, this, [this] { end(1); });
    sayRestarts(m_session, this,
                [this](const QString &name, const QString &text, const QString &fields) {
                    event(name, text, fields);
                });
}

void CtlMonitor::sayRestarts(DeviceSession *session, QObject *context, const EventSink &event)
{
    connect(session, &DeviceSession::controllerRestarted, context,
            [session, event](int id, const QStringList &lost, const RestartWatch::Evidence &seen) {
                const QString axes = RestartWatch::describe(seen, session->map());
                event(QStringLiteral("restarted"),
                      tr("controller %1 restarted (power off?): positions and references lost%2%3")
                          .arg(id)
                          .arg(lost.isEmpty() ? QString()
                                              : tr("; not saved to flash, lost: %1")
                                                    .arg(lost.join(QLatin1String(", "))),
                               axes.isEmpty() ? QString() : tr("; seen: %1").arg(axes)),
                      QStringLiteral(",\"lost\":") + quoted(lost.join(QLatin1String(", "))) +
                          evidenceFields(session->map(), id, seen));
            });
    // Zeros after a silence where only moving axes went to 0: said as what it is, not hidden.
    connect(session, &DeviceSession::controllerMayHaveRestarted, context,
            [session, event](int id, const RestartWatch::Evidence &seen) {
                event(QStringLiteral("possible_restart"),
                      tr("controller %1 may have restarted (power off?): it did not answer for "
                         "%2 s and every axis reads 0 (%3); whether a motion ended there cannot "
                         "be told: the references are not known, home again")
                          .arg(id)
                          .arg(double(seen.silentMs) / 1000.0, 0, 'f', 1)
                          .arg(RestartWatch::describe(seen, session->map())),
                      evidenceFields(session->map(), id, seen));
            });
}

QString CtlMonitor::evidenceFields(const RegisterMap &map, int id,
                                   const RestartWatch::Evidence &seen)
{
    const auto name = [&map](int motor) {
        const Parameter *p =
            map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"));
        return p ? p->key.section(QLatin1Char('.'), 0, 0) : QStringLiteral("motor%1").arg(motor);
    };
    const auto names = [&name](const QList<int> &motors) {
        QStringList out;
        for (const int motor : motors)
            out << quoted(name(motor));
        return QLatin1Char('[') + out.join(QLatin1Char(',')) + QLatin1Char(']');
    };
    // Where each axis stood at the last answer before: an axis that stood still there and
    // reads 0 now is the proof.
    QStringList before;
    QList<int> motors = seen.before.keys();
    std::sort(motors.begin(), motors.end());
    for (const int motor : std::as_const(motors)) {
        const Parameter *p =
            map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"));
        const qint64 raw = seen.before.value(motor);
        before << quoted(name(motor)) + QLatin1Char(':') +
                      (p ? p->formatRaw(raw) : QString::number(raw));
    }
    return QStringLiteral(",\"id\":%1,\"silent_ms\":%2,\"zeroed\":%3,\"stood_still\":%4,"
                          "\"moving\":%5,\"before\":{%6}")
        .arg(id)
        .arg(seen.silentMs)
        .arg(names(seen.zeroed), names(seen.stoodStill), names(seen.moving),
             before.join(QLatin1Char(',')));
}

void CtlMonitor::event(const QString &name, const QString &text, const QString &fields)
{
    if (m_ended)
        return;
    ++m_events;
    if (!m_json) {
        m_err << QStringLiteral("stepcomctl: ") << text << Qt::endl;
        return;
    }
    m_out << eventLine(name, m_clock.elapsed(), fields) << QLatin1Char('\n');
    m_out.flush();
    std::fflush(stdout);
}

QString CtlMonitor::eventLine(const QString &name, qint64 tMs, const QString &fields)
{
    return QStringLiteral("{\"event\":") + quoted(name) + QLatin1Char(',') + timeFields(tMs) +
           fields + QLatin1Char('}');
}

void CtlMonitor::start()
{
    // Ctrl-C and SIGTERM end the run between two lines, never in the middle of one.
    m_signals = new SignalWatcher(this);
    connect(m_signals, &SignalWatcher::terminationRequested, this, [this] { end(0); });
    m_clock.start();
    m_session->status()->start();
}

QList<const Parameter *> CtlMonitor::statusParameters(const DeviceSession &session)
{
    QList<const Parameter *> params;
    for (const QString &key : session.status()->keys()) {
        if (const Parameter *p = session.map().find(key))
            params << p;
    }
    std::stable_sort(params.begin(), params.end(),
                     [](const Parameter *a, const Parameter *b) { return rank(a) < rank(b); });
    return params;
}

QString CtlMonitor::timeFields(qint64 tMs)
{
    QDateTime now = QDateTime::currentDateTime();
    now = now.toOffsetFromUtc(now.offsetFromUtc()); // so the text carries the offset
    return QStringLiteral("\"time\":\"%1\",\"t_ms\":%2")
        .arg(now.toString(Qt::ISODateWithMs))
        .arg(tMs);
}

QString CtlMonitor::valueFields(const QList<const Parameter *> &params,
                                const std::function<std::optional<qint64>(const QString &)> &raw)
{
    QString fields;
    for (const Parameter *p : params) {
        const std::optional<qint64> value = raw(p->key);
        fields += QLatin1Char(',') + quoted(p->key) + QLatin1Char(':') +
                  (value ? p->formatRaw(*value) : QStringLiteral("null"));
    }
    return fields;
}

QString CtlMonitor::sampleLine(qint64 tMs) const
{
    const ParameterStore *store = m_session->parameters()->store();
    return QLatin1Char('{') + timeFields(tMs) +
           valueFields(m_params, [store](const QString &key) { return store->deviceValue(key); }) +
           QLatin1Char('}');
}

void CtlMonitor::onCycle(bool ok)
{
    if (m_ended)
        return;
    if (!ok) {
        // A bad moment on the line is no reason to stop watching: say so and go on.
        sayError(m_session->status()->error());
        return;
    }
    m_out << sampleLine(m_clock.elapsed()) << QLatin1Char('\n');
    m_out.flush();
    std::fflush(stdout);
    if (++m_printed >= m_count && m_count > 0)
        end(0);
}

void CtlMonitor::sayError(const QString &text)
{
    m_err << QStringLiteral("stepcomctl: ") << text << Qt::endl;
    m_errors << text;
}

QJsonObject CtlMonitor::summary() const
{
    return {{QStringLiteral("samples"), m_printed}, {QStringLiteral("events"), m_events}};
}

void CtlMonitor::end(int exitCode)
{
    if (m_ended)
        return;
    m_ended = true;
    m_session->connection()->reconnector()->stop();
    m_session->status()->stop();
    if (exitCode == 0 && m_printed == 0) {
        // Stopped before a single sample: that is no successful run.
        sayError(tr("no sample was read: every poll failed (see the errors above)"));
        exitCode = 1;
    }
    m_out.flush();
    Q_EMIT finished(exitCode);
}

} // namespace stepcom
