#include "ctlmonitor.h"

#include "session/devicesession.h"
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
    m_session->setStatusIntervalMs(intervalMs);
    m_params = statusParameters(*m_session);
    connect(m_session, &DeviceSession::statusCycleFinished, this,
            [this](bool ok, qint64) { onCycle(ok); });
    // A pulled cable is no reason to stop watching: try again, say so, go on.
    Reconnector *reconnector = m_session->reconnector();
    reconnector->setEnabled(true);
    connect(m_session, &DeviceSession::linkLost, this, [this](const QString &reason) {
        event(QStringLiteral("lost"),
              tr("link lost: %1; trying again on its own (Ctrl-C ends)").arg(reason),
              QStringLiteral("reason"), reason);
    });
    connect(reconnector, &Reconnector::restored, this, [this](const LinkSettings &s, int n) {
        event(QStringLiteral("back"),
              tr("link back at %1 after %n attempt(s)", nullptr, n).arg(s.describe()),
              QStringLiteral("port"),
              s.transport == LinkSettings::Transport::Tcp
                  ? QStringLiteral("%1:%2").arg(s.host).arg(s.tcpPort)
                  : s.portName);
    });
    connect(reconnector, &Reconnector::cancelled, this, [this] { end(1); });
    connect(m_session, &DeviceSession::controllerRestarted, this,
            [this](int id, const QStringList &lost) {
                event(QStringLiteral("restarted"),
                      tr("controller %1 restarted (power off?): positions and references lost%2")
                          .arg(id)
                          .arg(lost.isEmpty() ? QString()
                                              : tr("; not saved to flash, lost: %1")
                                                    .arg(lost.join(QLatin1String(", ")))),
                      QStringLiteral("lost"), lost.join(QLatin1String(", ")));
            });
}

void CtlMonitor::event(const QString &name, const QString &text, const QString &detailKey,
                       const QString &detail)
{
    if (m_ended)
        return;
    if (!m_json) {
        m_err << QStringLiteral("stepcomctl: ") << text << Qt::endl;
        return;
    }
    QDateTime now = QDateTime::currentDateTime();
    now = now.toOffsetFromUtc(now.offsetFromUtc());
    m_out << QStringLiteral("{\"event\":%1,\"time\":\"%2\",\"t_ms\":%3,%4:%5}")
                 .arg(quoted(name), now.toString(Qt::ISODateWithMs))
                 .arg(m_clock.elapsed())
                 .arg(quoted(detailKey), quoted(detail))
          << QLatin1Char('\n');
    m_out.flush();
    std::fflush(stdout);
}

void CtlMonitor::start()
{
    // Ctrl-C and SIGTERM end the run between two lines, never in the middle of one.
    m_signals = new SignalWatcher(this);
    connect(m_signals, &SignalWatcher::terminationRequested, this, [this] { end(0); });
    m_clock.start();
    m_session->startStatus();
}

QList<const Parameter *> CtlMonitor::statusParameters(const DeviceSession &session)
{
    QList<const Parameter *> params;
    for (const QString &key : session.statusKeys()) {
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
    const ParameterStore *store = m_session->parameters();
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
        m_err << QStringLiteral("stepcomctl: ") << m_session->statusError() << Qt::endl;
        return;
    }
    m_out << sampleLine(m_clock.elapsed()) << QLatin1Char('\n');
    m_out.flush();
    std::fflush(stdout);
    if (++m_printed >= m_count && m_count > 0)
        end(0);
}

void CtlMonitor::end(int exitCode)
{
    if (m_ended)
        return;
    m_ended = true;
    m_session->reconnector()->stop();
    m_session->stopStatus();
    if (exitCode == 0 && m_printed == 0) {
        // Stopped before a single sample: that is no successful run.
        m_err << QStringLiteral("stepcomctl: ")
              << tr("no sample was read: every poll failed (see the errors above)") << Qt::endl;
        exitCode = 1;
    }
    m_out.flush();
    Q_EMIT finished(exitCode);
}

} // namespace stepcom
