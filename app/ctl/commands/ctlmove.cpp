// stepcomctl move: a step or a move-to over the single move, its distance and direction put
// back and verified.
#include "../ctlcontext.h"
#include "ctlcommands.h"

#include "session/stepmove.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <cmath>

namespace stepcom {

void runMove(CtlContext &ctx)
{
    static const QRegularExpression motorName(QStringLiteral("^motor([0-9]+)$"));
    const auto match = ctx.options.arguments.size() == 1
                           ? motorName.match(ctx.options.arguments.first())
                           : QRegularExpressionMatch();
    if (!match.hasMatch()) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("move needs one motor: move motor1 --by D or --to X"));
        return;
    }
    const int motor = match.captured(1).toInt();
    const int motors = ctx.map.blockCount(QStringLiteral("motor"));
    if (motor < 1 || motor > motors) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("there is no motor %1 (this map has motor1 .. motor%2)")
                     .arg(motor)
                     .arg(motors));
        return;
    }
    if (ctx.options.by.isEmpty() == ctx.options.to.isEmpty()) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("move needs exactly one of --by D and --to X"));
        return;
    }
    const QString text = ctx.options.by.isEmpty() ? ctx.options.to : ctx.options.by;
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        ctx.fail(CtlRunner::UsageError, CtlRunner::tr("%1: '%2' is not a number")
                                            .arg(ctx.options.by.isEmpty() ? QStringLiteral("--to")
                                                                          : QStringLiteral("--by"),
                                                 text));
        return;
    }
    // As write refuses a third decimal: a step the axis cannot count is not rounded silently.
    const QString option =
        ctx.options.by.isEmpty() ? QStringLiteral("--to") : QStringLiteral("--by");
    if (const Parameter *pos =
            ctx.map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"))) {
        const double counts = value * double(pos->scale);
        if (std::abs(counts - std::round(counts)) > 1e-6) {
            ctx.fail(CtlRunner::UsageError,
                     CtlRunner::tr("%1: %2 has more decimals than motor %3 counts in (steps of %4 "
                                   "%5): nothing was moved")
                         .arg(option, text)
                         .arg(motor)
                         .arg(pos->formatRaw(1), pos->unit));
            return;
        }
    }
    StepMoveRequest request;
    request.kind = ctx.options.by.isEmpty() ? StepMoveRequest::Kind::To : StepMoveRequest::Kind::By;
    request.motor = motor;
    request.value = value;
    ctx.connectThen([&ctx, request] {
        StepMove *step = ctx.session->stepMove();
        QObject::connect(step, &StepMove::warned, ctx.runner(), [&ctx](const QString &warning) {
            ctx.err << QStringLiteral("stepcomctl: ") << warning << Qt::endl;
        });
        QObject::connect(step, &StepMove::finished, ctx.runner(), [&ctx](const StepMoveResult &r) {
            const Parameter *pos = ctx.map.blockParameter(QStringLiteral("motor"), r.request.motor,
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
            if (ctx.options.json) {
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
                ctx.out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            } else {
                (r.ok() ? ctx.out : ctx.err)
                    << (r.ok() ? QString() : QStringLiteral("stepcomctl: ")) << r.text << Qt::endl;
            }
            ctx.finish(r.ok() ? CtlRunner::Ok : CtlRunner::DeviceError);
        });
        if (const QString why = step->start(request); !why.isEmpty())
            ctx.fail(CtlRunner::DeviceError, why);
    });
}

} // namespace stepcom
