// stepcomctl move and the risk guard (the backups before risky commands): parts of CtlRunner.
#include "../ctlrunner.h"

#include "profile/sessionbackup.h"
#include "session/stepmove.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <cmath>

namespace stepcom {

void CtlRunner::installRiskGuard()
{
    // The session is this runner's child: it never outlives `this`.
    m_session->setRiskGuard([this](DeviceSession::Risk risk, int id,
                                   DeviceSession::Proceed proceed) {
        if (m_options.noBackup) {
            proceed(QString());
            return;
        }
        SessionBackup::save(
            m_session, BackupStore(), risk, id,
            [this, risk, proceed](const BackupStore::Saved &saved) {
                if (!saved.ok()) {
                    proceed(risk == DeviceSession::Risk::Apply
                                ? tr("no backup of the controller's settings could be saved "
                                     "(%1): nothing was written (--no-backup applies without "
                                     "one)")
                                      .arg(saved.error)
                                : tr("no backup of the controller's settings could be saved "
                                     "(%1): nothing was done (--no-backup goes on without "
                                     "one)")
                                      .arg(saved.error));
                    return;
                }
                m_out << tr("backup of the controller's settings: %1").arg(saved.path) << Qt::endl;
                proceed(QString());
            });
    });
}

void CtlRunner::guardThen(DeviceSession::Risk risk, std::function<void()> next)
{
    m_session->guard(risk, [this, next](const QString &refusal) {
        if (!refusal.isEmpty()) {
            fail(DeviceError, refusal);
            return;
        }
        next();
    });
}

void CtlRunner::runMove()
{
    static const QRegularExpression motorName(QStringLiteral("^motor([0-9]+)$"));
    const auto match = m_options.arguments.size() == 1
                           ? motorName.match(m_options.arguments.first())
                           : QRegularExpressionMatch();
    if (!match.hasMatch()) {
        fail(UsageError, tr("move needs one motor: move motor1 --by D or --to X"));
        return;
    }
    const int motor = match.captured(1).toInt();
    const int motors = m_map.blockCount(QStringLiteral("motor"));
    if (motor < 1 || motor > motors) {
        fail(UsageError,
             tr("there is no motor %1 (this map has motor1 .. motor%2)").arg(motor).arg(motors));
        return;
    }
    if (m_options.by.isEmpty() == m_options.to.isEmpty()) {
        fail(UsageError, tr("move needs exactly one of --by D and --to X"));
        return;
    }
    const QString text = m_options.by.isEmpty() ? m_options.to : m_options.by;
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        fail(UsageError,
             tr("%1: '%2' is not a number")
                 .arg(m_options.by.isEmpty() ? QStringLiteral("--to") : QStringLiteral("--by"),
                      text));
        return;
    }
    // As write refuses a third decimal: a step the axis cannot count is not rounded silently.
    const QString option = m_options.by.isEmpty() ? QStringLiteral("--to") : QStringLiteral("--by");
    if (const Parameter *pos =
            m_map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"))) {
        const double counts = value * double(pos->scale);
        if (std::abs(counts - std::round(counts)) > 1e-6) {
            fail(UsageError, tr("%1: %2 has more decimals than motor %3 counts in (steps of %4 "
                                "%5): nothing was moved")
                                 .arg(option, text)
                                 .arg(motor)
                                 .arg(pos->formatRaw(1), pos->unit));
            return;
        }
    }
    StepMoveRequest request;
    request.kind = m_options.by.isEmpty() ? StepMoveRequest::Kind::To : StepMoveRequest::Kind::By;
    request.motor = motor;
    request.value = value;
    connectThen([this, request] {
        StepMove *step = m_session->stepMove();
        connect(step, &StepMove::warned, this, [this](const QString &warning) {
            m_err << QStringLiteral("stepcomctl: ") << warning << Qt::endl;
        });
        connect(step, &StepMove::finished, this, [this](const StepMoveResult &r) {
            const Parameter *pos = m_map.blockParameter(QStringLiteral("motor"), r.request.motor,
                                                        QStringLiteral("position"));
            const auto units = [](std::optional<double> v) {
                return v ? QJsonValue(*v) : QJsonValue();
            };
            std::optional<double> end;
            if (r.outcome) {
                if (const AxisEnd *a = r.outcome->axis(r.request.motor); a && a->position && pos)
                    end = pos->toEngineering(*a->position);
            } else if (r.arrived) {
                end = r.startPosition;
            }
            if (m_options.json) {
                const QJsonObject o{
                    {QStringLiteral("motor"), r.request.motor},
                    {QStringLiteral("start"), units(r.startPosition)},
                    {QStringLiteral("target"), units(r.target)},
                    {QStringLiteral("position"), units(end)},
                    {QStringLiteral("arrived"), r.arrived},
                    {QStringLiteral("restored"), r.restored},
                    {QStringLiteral("outcome"),
                     r.outcome ? r.outcome->verdictWord() : QJsonValue()},
                    {QStringLiteral("cause"), r.outcome ? r.outcome->causeWord() : QJsonValue()},
                    {QStringLiteral("warning"), r.warning.isEmpty() ? QJsonValue() : r.warning},
                    {QStringLiteral("message"), r.text}};
                m_out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            } else {
                (r.ok() ? m_out : m_err)
                    << (r.ok() ? QString() : QStringLiteral("stepcomctl: ")) << r.text << Qt::endl;
            }
            finish(r.ok() ? Ok : DeviceError);
        });
        if (const QString why = step->start(request); !why.isEmpty())
            fail(DeviceError, why);
    });
}

} // namespace stepcom
