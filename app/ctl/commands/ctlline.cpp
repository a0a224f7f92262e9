// stepcomctl assign-id and scan: the line's commands, a controller's id given and every
// controller on the line found.
#include "../ctlcontext.h"
#include "../ctllinkadvice.h"
#include "../ctlscan.h"
#include "ctlcommands.h"

#include "line/idchange.h"
#include "sim/host/builtinsimulator.h"

#include <QJsonObject>

#include <memory>

namespace stepcom {

void runAssignId(CtlContext &ctx)
{
    const int from = ctx.options.link.deviceId;
    const int to = ctx.options.assignTo;
    if (ctx.isMulti() || to == 0) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("assign-id: give the new id with --to N, and one --id (the id the "
                               "controller answers at now, 1 from the factory)"));
        return;
    }
    if (to == from) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("assign-id: the controller already has id %1").arg(to));
        return;
    }
    ctx.connectThen([&ctx, from, to] {
        // The same steps as the window's id assistant: core/line/idchange.
        auto *change = new IdChange(ctx.session, ctx.runner());
        change->setSaveToFlash(ctx.options.saveToFlash);
        QObject::connect(
            change, &IdChange::finished, ctx.runner(),
            [&ctx, change, to](bool ok, const QString &text) {
                change->deleteLater();
                if (!ok) {
                    // Answering at the new id but not saved: say how to reach it anyway.
                    if (change->problem() == IdChange::Problem::NotSaved)
                        ctx.err << QStringLiteral("stepcomctl: ")
                                << CtlRunner::tr("next commands: stepcomctl %1 ...")
                                       .arg(CtlLinkAdvice::nextOptions(ctx.options, to,
                                                                       ctx.options.link.baud))
                                << Qt::endl;
                    ctx.fail(change->problem() == IdChange::Problem::Refused
                                 ? CtlRunner::UsageError
                                 : CtlRunner::DeviceError,
                             text);
                    return;
                }
                ctx.result = QJsonObject{
                    {QStringLiteral("from"), ctx.options.link.deviceId},
                    {QStringLiteral("to"), to},
                    {QStringLiteral("saved"), ctx.options.saveToFlash},
                    {QStringLiteral("next"),
                     CtlLinkAdvice::nextOptions(ctx.options, to, ctx.options.link.baud)}};
                ctx.out << text << Qt::endl;
                if (!ctx.options.saveToFlash)
                    ctx.out << CtlRunner::tr(
                                   "id %1 lasts until the power is switched off, then the "
                                   "controller answers at the id in its flash again (id 1 from "
                                   "the factory); add --save-to-flash to keep it")
                                   .arg(to)
                            << Qt::endl;
                ctx.out << CtlRunner::tr("next commands: stepcomctl %1 ...")
                               .arg(CtlLinkAdvice::nextOptions(ctx.options, to,
                                                               ctx.options.link.baud))
                        << Qt::endl;
                ctx.finish(CtlRunner::Ok);
            });
        change->start(from, to);
    });
}

void runScan(CtlContext &ctx)
{
    if (ctx.options.target == CtlOptions::Target::None) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("scan: give the line to scan: --port, --rtu-tcp, --tcp or --sim"));
        return;
    }
    if (!ctx.options.arguments.isEmpty()) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("scan takes no arguments ('%1'): give --bauds, --parity and --ids")
                     .arg(ctx.options.arguments.first()));
        return;
    }
    // --sim: the simulator scanned, kept as long as the scan's end can be heard.
    std::shared_ptr<BuiltinSimulator> scanSim;
    BusScanner::Plan plan;
    plan.base = ctx.options.link;
    plan.bauds = ctx.options.scanBauds;
    plan.parities = ctx.options.scanParities;
    plan.ids = ctx.options.scanIds;
    plan.probeTimeoutMs = ctx.options.probeTimeoutMs;
    if (ctx.options.target == CtlOptions::Target::Sim) {
        // Its pty, whatever id and baud it saved to flash: finding them is what a scan is for.
        auto sim = std::make_unique<BuiltinSimulator>();
        sim->setFlashPath(BuiltinSimulator::defaultFlashPath());
        QString error;
        const std::optional<LinkSettings> link = sim->start(ctx.map, &error);
        if (!link || link->transport != LinkSettings::Transport::Rtu) {
            ctx.fail(CtlScan::LinkError,
                     CtlRunner::tr("cannot start the built-in simulator: %1")
                         .arg(link ? CtlRunner::tr("it has no serial line here") : error));
            return;
        }
        plan.base.portName = link->portName;
        scanSim = std::move(sim);
    }
    auto *scan = new CtlScan(plan, ctx.map, ctx.options.json, ctx.out, ctx.err, ctx.runner());
    QObject::connect(scan, &CtlScan::finished, ctx.runner(),
                     [&ctx, scanSim](int code) { ctx.finish(code); });
    scan->start();
}

} // namespace stepcom
