// stepcomctl for a whole machine: every controller of the line in one report, every one saved
// into one folder.
#include "../ctlcontext.h"
#include "ctlcommands.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include "line/bussweep.h"
#include "profile/busdump.h"
#include "report/machinereport.h"

#include <QDate>
#include <QFileInfo>

namespace stepcom {

void dumpIntoFolder(CtlContext &ctx, const QString &folder, const QHash<QString, qint64> &values)
{
    const int id = ctx.session->line()->deviceInView();
    const BusDump::Saved saved =
        BusDump::save(folder, ctx.map, id, ctx.options.name, ctx.options.notes, values,
                      QDate::currentDate(), ctx.session->connection()->isSimulator());
    if (!saved.ok()) {
        ctx.fail(CtlRunner::UsageError, saved.error);
        return;
    }
    ctx.out << CtlRunner::tr("saved the settings of %1 to %2")
                   .arg(ctx.session->line()->describeDevice(id), saved.path)
            << Qt::endl;
    ctx.finish(CtlRunner::Ok);
}

void runMachineReport(CtlContext &ctx)
{
    const QString path = reportPath(ctx);
    if (path.isEmpty())
        return;
    if (!ctx.options.from.isEmpty()) {
        ctx.fail(
            CtlRunner::UsageError,
            CtlRunner::tr("report --from makes the report of one profile file: give one --id"));
        return;
    }
    ctx.connectThen([&ctx, path] {
        readMachine(ctx, CtlRunner::tr("no report: not every controller could be read completely"),
                    [&ctx, path](const QList<ReportInput> &inputs) {
                        const MachineReport report(inputs, ctx.options.name, ctx.options.notes,
                                                   ctx.options.language);
                        if (const QString e = report.write(path); !e.isEmpty()) {
                            ctx.fail(CtlRunner::UsageError, e);
                            return;
                        }
                        ctx.result =
                            QJsonObject{{QStringLiteral("file"), path},
                                        {QStringLiteral("controllers"), int(inputs.size())}};
                        ctx.out << CtlRunner::tr("report of %n controller(s) written to %1",
                                                 nullptr, int(inputs.size()))
                                       .arg(path)
                                << Qt::endl;
                        ctx.finish(CtlRunner::Ok);
                    });
    });
}

void readMachine(CtlContext &ctx, const QString &failure,
                 std::function<void(const QList<ReportInput> &)> done)
{
    auto *sweep = new BusSweep(ctx.session, ctx.runner());
    QObject::connect(
        sweep, &BusSweep::finished, ctx.runner(), [&ctx, sweep, failure, done](bool ok) {
            sweep->deleteLater();
            if (!ok) {
                // A machine's report never leaves a controller out silently: none then.
                for (int id : ctx.options.ids) {
                    for (const QString &e : sweep->outcome(id).errors)
                        ctx.err << QStringLiteral("stepcomctl: ")
                                << CtlRunner::tr("id %1: %2").arg(id).arg(e) << Qt::endl;
                }
                ctx.fail(CtlRunner::DeviceError, failure);
                return;
            }
            QList<ReportInput> inputs;
            const QDateTime now = QDateTime::currentDateTime();
            for (int id : ctx.options.ids) {
                inputs << ReportInput::fromSession(*ctx.session, id, sweep->outcome(id).values,
                                                   now);
            }
            done(inputs);
        });
    sweep->start(ctx.options.ids, ctx.map.holdings());
}

} // namespace stepcom
