// stepcomctl monitor and listen: the commands whose lines are printed as they come, the JSON
// object at the end a summary of them.
#include "../ctlbusmonitor.h"
#include "../ctlcontext.h"
#include "../ctllisten.h"
#include "../ctlmonitor.h"
#include "ctlcommands.h"

namespace stepcom {

void runMonitor(CtlContext &ctx)
{
    if (!ctx.options.arguments.isEmpty()) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("monitor takes no arguments, only --count and --interval"));
        return;
    }
    ctx.connectThen([&ctx] {
        if (ctx.isMulti()) {
            // Several ids: one status read per device in turn, each line keyed by its id.
            auto *bus = new CtlBusMonitor(ctx.session, ctx.options.ids, ctx.options.count,
                                          ctx.options.intervalMs, ctx.options.json, ctx.runner());
            QObject::connect(bus, &CtlBusMonitor::finished, ctx.runner(), [&ctx, bus](int code) {
                ctx.result = bus->summary();
                ctx.liveErrors = bus->errors();
                ctx.finish(code);
            });
            bus->start();
            return;
        }
        auto *monitor = new CtlMonitor(ctx.session, ctx.options.count, ctx.options.intervalMs,
                                       ctx.options.json, ctx.runner());
        QObject::connect(monitor, &CtlMonitor::finished, ctx.runner(), [&ctx, monitor](int code) {
            ctx.result = monitor->summary();
            ctx.liveErrors = monitor->errors();
            ctx.finish(code);
        });
        monitor->start();
    });
}

void runListen(CtlContext &ctx)
{
    if (!ctx.options.arguments.isEmpty()) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("listen takes no arguments, only --port, --baud, --parity, "
                               "--seconds, --json and --log"));
        return;
    }
    if (ctx.options.target != CtlOptions::Target::Port) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("listen hears a serial line: give --port (a line StepCom does not "
                               "drive; --tcp and --sim have no other master to hear)"));
        return;
    }
    auto *listen = new CtlListen(ctx.map, ctx.options.link, ctx.options.json, ctx.options.seconds,
                                 ctx.options.logFile, ctx.runner());
    QObject::connect(listen, &CtlListen::finished, ctx.runner(), [&ctx, listen](int code) {
        ctx.result = listen->summaryJson();
        ctx.liveErrors = listen->errors();
        ctx.finish(code);
    });
    listen->start();
}

} // namespace stepcom
