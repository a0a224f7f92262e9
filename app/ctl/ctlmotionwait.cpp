#include "ctlmotionwait.h"

#include "motion/motionjudge.h"
#include "motion/motionwatch.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/restartwatch.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace stepcom {

namespace {

constexpr int kSampleMs = 100;
// No answer for this long: the controller is gone. A controller switched off and on answers
// again within a few seconds, and that is said as a restart, not as a lost link.
constexpr qint64 kSilenceBeforeLostMs = 6000;

} // namespace

CtlMotionWait::CtlMotionWait(DeviceSession *session, const Parameter &command, bool json,
                             QTextStream &out, QTextStream &err, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_command(command)
    , m_json(json)
    , m_out(out)
    , m_err(err)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(kSampleMs);
    connect(&m_timer, &QTimer::timeout, this, &CtlMotionWait::sample);
    connect(session->connection(), &SessionConnection::linkLost, this,
            [this](const QString &) { conclude(MotionCause::LinkLost); });
    m_restarts = new RestartWatch(session->map(), this);
    connect(m_restarts, &RestartWatch::suspected, this,
            [this](int, const QString &, RestartWatch::Zeros zeros) {
                if (zeros == RestartWatch::Zeros::Reset)
                    conclude(MotionCause::Restarted);
                else if (zeros == RestartWatch::Zeros::AfterMotion)
                    conclude(MotionCause::Silent); // it may have ended there: not known
            });
}

CtlMotionWait::~CtlMotionWait() = default;

void CtlMotionWait::fail(const QString &message)
{
    if (std::exchange(m_done, true))
        return;
    m_err << QStringLiteral("stepcomctl: ") << message << Qt::endl;
    Q_EMIT finished(1);
}

void CtlMotionWait::start()
{
    // Where it should end, and what may stop it, from what the controller holds now: the
    // registers the judge reads, as `move` reads them.
    QList<const Parameter *> params;
    for (const QString &k : MotionJudge::inputKeys(m_session->map(), m_command.key))
        params << m_session->map().find(k);
    m_session->parameters()->read(params, [this](const ReadOutcome &r) {
        m_values = r.values;
        if (!r.ok) {
            fail(r.errors.join(QLatin1String("; ")));
            return;
        }
        const auto plan = MotionJudge::plan(m_session->map(), m_command.key, m_values);
        if (!plan) {
            fail(tr("%1 would not move anything here (nothing in the homing order, or every "
                    "motor runs): nothing to wait for")
                     .arg(m_command.key));
            return;
        }
        const QString warning =
            MotionJudge::limitWarning(m_session->map(), m_command.key, m_values);
        if (!warning.isEmpty())
            m_err << QStringLiteral("stepcomctl: ") << warning << Qt::endl;
        m_watch = std::make_unique<MotionWatch>(m_session->map(), *plan, 0);
        m_session->command(m_command, [this](const Result &c) {
            if (!c.ok) {
                fail(c.errorText);
                return;
            }
            m_answeredAtMs = QDateTime::currentMSecsSinceEpoch();
            m_restarts->commandSent(m_session->line()->deviceInView(), m_answeredAtMs);
            if (!m_json)
                m_out << tr("%1: sent, waiting for the motion to end").arg(m_command.key)
                      << Qt::endl;
            m_timer.start();
        });
    });
}

void CtlMotionWait::sample()
{
    if (m_done)
        return;
    QList<const Parameter *> params;
    for (const QString &k : MotionJudge::watchKeys(m_session->map()))
        params << m_session->map().find(k);
    m_session->parameters()->read(
        params,
        [this](const ReadOutcome &r) {
            if (m_done)
                return;
            const qint64 now = QDateTime::currentMSecsSinceEpoch();
            m_restarts->statusRead(m_session->line()->deviceInView(), r.ok, r.values, now);
            if (m_done)
                return; // the controller restarted
            if (!r.ok) {
                if (now - m_answeredAtMs >= kSilenceBeforeLostMs) {
                    conclude(MotionCause::LinkLost);
                    return;
                }
                m_timer.start();
                return;
            }
            m_answeredAtMs = now;
            for (auto it = r.values.cbegin(); it != r.values.cend(); ++it)
                m_values.insert(it.key(), it.value());
            if (m_watch->sample(r.values))
                conclude(MotionCause::None);
            else
                m_timer.start();
        },
        Priority::Read);
}

void CtlMotionWait::conclude(MotionCause cause)
{
    if (!m_watch || std::exchange(m_done, true))
        return;
    m_timer.stop();
    m_watch->interrupt(cause);
    const RegisterMap &map = m_session->map();
    const MotionOutcome o = MotionJudge::judge(map, m_watch->start(), m_values, m_watch->cause());
    const QString text = MotionJudge::text(map, o);
    if (m_json) {
        QJsonArray axes;
        for (const AxisEnd &a : o.axes) {
            const Parameter *pos =
                map.blockParameter(QStringLiteral("motor"), a.motor, QStringLiteral("position"));
            const auto units = [pos](std::optional<qint64> raw) {
                return raw && pos ? QJsonValue(pos->toEngineering(*raw)) : QJsonValue();
            };
            QJsonObject axis{{QStringLiteral("motor"), a.motor},
                             {QStringLiteral("position"), units(a.position)}};
            if (a.target)
                axis.insert(QStringLiteral("target"), units(a.target));
            if (o.start.kind == MotionKind::Home || o.start.kind == MotionKind::HomeInOrder)
                axis.insert(QStringLiteral("referenced"), a.referenced);
            axes.append(axis);
        }
        const QJsonObject out{{QStringLiteral("command"), o.start.command},
                              {QStringLiteral("outcome"), o.verdictWord()},
                              {QStringLiteral("ok"), o.ok()},
                              {QStringLiteral("cause"), o.causeWord()},
                              {QStringLiteral("message"), text},
                              {QStringLiteral("axes"), axes}};
        m_out << QString::fromUtf8(QJsonDocument(out).toJson(QJsonDocument::Indented));
    } else {
        (o.ok() ? m_out : m_err) << text << Qt::endl;
    }
    m_out.flush();
    m_err.flush();
    Q_EMIT finished(o.ok() ? 0 : 1);
}

} // namespace stepcom
