// stepcomctl command NAME: one command coil pulsed, and with --wait, where its motion ended.
#include "../ctlcontext.h"
#include "../ctlmotionwait.h"
#include "ctlcommands.h"

#include "motion/motionjudge.h"

#include <QJsonObject>

namespace stepcom {

namespace {

// The one coil `command` names, checked; nullptr after failing with the reason.
const Parameter *commandArgument(CtlContext &ctx)
{
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("command needs exactly one command name (see: stepcomctl params)"));
        return nullptr;
    }
    const QString key = ctx.options.arguments.first();
    const Parameter *p = ctx.map.find(key);
    if (!p || !p->isCoil()) {
        ctx.fail(CtlRunner::UsageError,
                 p ? CtlRunner::tr("%1 is a parameter, not a command: use read or write").arg(key)
                   : CtlRunner::tr("unknown command '%1' (see: stepcomctl params)").arg(key));
        return nullptr;
    }
    if (p->command == CommandClass::Destructive && !ctx.options.yes) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("%1 destroys settings (%2); add --yes if you mean it")
                     .arg(key, p->help.en));
        return nullptr;
    }
    return p;
}

} // namespace

void runCommand(CtlContext &ctx)
{
    const Parameter *p = commandArgument(ctx);
    if (!p)
        return;
    ctx.connectThen([&ctx, p] {
        const bool risky =
            p->key == QLatin1String("factory_reset") || p->key == QLatin1String("save_to_flash");
        const auto risk = p->key == QLatin1String("factory_reset")
                              ? DeviceSession::Risk::FactoryReset
                              : DeviceSession::Risk::SaveToFlash;
        const auto send = [&ctx, p] {
            ctx.session->command(*p, [&ctx, p](const Result &r) {
                if (!r.ok) {
                    ctx.fail(CtlRunner::DeviceError, r.errorText);
                    return;
                }
                ctx.result =
                    QJsonObject{{QStringLiteral("command"), p->key},
                                {QStringLiteral("state"), p->command == CommandClass::Motion
                                                              ? QStringLiteral("sent")
                                                              : QStringLiteral("done")}};
                // A moving command is only acknowledged: its end is known with --wait.
                ctx.out << (p->command == CommandClass::Motion
                                ? CtlRunner::tr("%1: sent (add --wait to wait for how it ends)")
                                      .arg(p->key)
                                : CtlRunner::tr("%1: done").arg(p->key))
                        << Qt::endl;
                ctx.finish(CtlRunner::Ok);
            });
        };
        if (risky)
            ctx.guardThen(risk, send);
        else
            send();
    });
}

void runCommandWait(CtlContext &ctx)
{
    const Parameter *p = commandArgument(ctx);
    if (!p)
        return;
    if (!MotionJudge::kindOf(ctx.map, p->key)) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("--wait: %1 has no end to wait for (single move, home, home in "
                               "order, return to data zero, arc and line have one)")
                     .arg(p->key));
        return;
    }
    ctx.connectThen([&ctx, p] {
        auto *wait =
            new CtlMotionWait(ctx.session, *p, ctx.options.json, ctx.out, ctx.err, ctx.runner());
        QObject::connect(wait, &CtlMotionWait::finished, ctx.runner(),
                         [&ctx](int code) { ctx.finish(code); });
        wait->start();
    });
}

} // namespace stepcom
