// stepcomctl run FILE: a machine cycle (.stepseq, docs/sequence.md) run on the controller,
// shown and asked about first, each step said on standard error as it starts.
#include "../ctlcontext.h"
#include "ctlcommands.h"

#include "sequence/sequencecheck.h"
#include "sequence/sequenceparser.h"
#include "sequence/sequencerunner.h"
#include "signalwatcher.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <memory>

namespace stepcom {

namespace {

QString axesText(const RegisterMap &map, const QMap<int, double> &axes)
{
    QStringList parts;
    for (auto it = axes.begin(); it != axes.end(); ++it) {
        const Parameter *p = map.blockParameter(kMotorBlock, it.key(), QStringLiteral("position"));
        parts << QStringLiteral("motor%1 %2 %3")
                     .arg(it.key())
                     .arg(it.value(), 0, 'f', p ? p->decimals() : 2)
                     .arg(p ? p->unit : QString());
    }
    return parts.join(QLatin1String(", "));
}

// What the run will do, said before it is asked about.
QString plan(const CtlContext &ctx, const Sequence &s)
{
    QString text =
        CtlRunner::tr("Sequence %1: %n step(s) in the file", nullptr, int(s.allSteps().size()))
            .arg(s.fileName) +
        QLatin1Char('\n');
    for (auto it = s.points.begin(); it != s.points.end(); ++it)
        text += CtlRunner::tr("  point %1: %2").arg(it.key(), axesText(ctx.map, it.value())) +
                QLatin1Char('\n');
    for (auto it = s.limits.axes().begin(); it != s.limits.axes().end(); ++it) {
        const Parameter *p =
            ctx.map.blockParameter(kMotorBlock, it.key(), QStringLiteral("position"));
        if (!p)
            continue;
        text += CtlRunner::tr("  limits motor%1: %2 .. %3 %4")
                    .arg(it.key())
                    .arg(it->min ? p->formatRaw(*it->min) : QStringLiteral("−∞"),
                         it->max ? p->formatRaw(*it->max) : QStringLiteral("+∞"), p->unit) +
                QLatin1Char('\n');
    }
    text += (s.outputsOffOnStop ? CtlRunner::tr("  on a stop: all outputs off")
                                : CtlRunner::tr("  on a stop: the outputs are left as they are")) +
            QLatin1Char('\n');
    text += CtlRunner::tr("  cycles: %1 (the whole step list each time)").arg(ctx.options.cycles) +
            QLatin1Char('\n');
    return text;
}

int exitFor(SequenceResult::Outcome outcome)
{
    using O = SequenceResult::Outcome;
    switch (outcome) {
    case O::Done:
        return CtlRunner::Ok;
    case O::Timeout:
    case O::Stopped:
    case O::EmergencyStop:
    case O::Limit:
    case O::Interrupted:
        return CtlRunner::DeviceError; // the machine (or the user) stopped the run
    case O::Refused:
        return CtlRunner::UsageError;
    case O::LinkLost:
    case O::Restarted:
    case O::DeviceError:
        break;
    }
    return CtlRunner::LinkError;
}

void report(CtlContext &ctx, const SequenceResult &r)
{
    const auto seconds = [](double s) { return std::round(s * 1000) / 1000; };
    ctx.result = QJsonObject{{QStringLiteral("outcome"), r.word()},
                             {QStringLiteral("cycles_done"), r.cyclesDone},
                             {QStringLiteral("step"), r.step.isEmpty() ? QJsonValue() : r.step},
                             {QStringLiteral("elapsed_s"), seconds(r.elapsedSeconds)},
                             {QStringLiteral("cycle_time_s"),
                              QJsonObject{{QStringLiteral("min"), seconds(r.minCycle())},
                                          {QStringLiteral("median"), seconds(r.medianCycle())},
                                          {QStringLiteral("max"), seconds(r.maxCycle())}}},
                             {QStringLiteral("restored"), r.restored},
                             {QStringLiteral("message"), r.text}};
    for (const QString &p : r.problems)
        ctx.err << QStringLiteral("stepcomctl: ") << p << Qt::endl;
    const QString summary =
        r.step.isEmpty() ? r.text : CtlRunner::tr("%1 (at %2)").arg(r.text, r.step);
    if (!r.ok()) {
        ctx.err << QStringLiteral("stepcomctl: ") << summary << Qt::endl;
    } else if (!ctx.options.json) {
        ctx.out << summary << Qt::endl;
    }
    if (!ctx.options.json && !r.cycleSeconds.isEmpty())
        ctx.out << CtlRunner::tr("cycles done: %1; cycle time min %2 s, median %3 s, max %4 s; "
                                 "%5 s in all")
                       .arg(r.cyclesDone)
                       .arg(r.minCycle(), 0, 'f', 3)
                       .arg(r.medianCycle(), 0, 'f', 3)
                       .arg(r.maxCycle(), 0, 'f', 3)
                       .arg(r.elapsedSeconds, 0, 'f', 3)
                << Qt::endl;
    ctx.finish(exitFor(r.outcome));
}

void startRun(CtlContext &ctx, const Sequence &sequence)
{
    ctx.connectThen([&ctx, sequence] {
        auto *runner = new SequenceRunner(ctx.session, ctx.runner());
        // Each step a line on standard error as it starts, never one of the JSON object's
        // errors; with --json a JSON line.
        auto clock = std::make_shared<QElapsedTimer>();
        clock->start();
        const bool json = ctx.options.json;
        const auto line = [json, clock](const QJsonObject &o, const QString &text) {
            QTextStream err(stderr);
            if (json) {
                QJsonObject withTime = o;
                withTime.insert(QStringLiteral("t_s"), clock->elapsed() / 1000.0);
                err << QString::fromUtf8(QJsonDocument(withTime).toJson(QJsonDocument::Compact))
                    << Qt::endl;
            } else {
                err << text << Qt::endl;
            }
        };
        QObject::connect(runner, &SequenceRunner::stepStarted, ctx.runner(),
                         [line](int cycle, const QString &path, const QString &text) {
                             line(QJsonObject{{QStringLiteral("event"), QStringLiteral("step")},
                                              {QStringLiteral("cycle"), cycle},
                                              {QStringLiteral("path"), path},
                                              {QStringLiteral("step"), text}},
                                  CtlRunner::tr("cycle %1 %2: %3").arg(cycle).arg(path, text));
                         });
        QObject::connect(
            runner, &SequenceRunner::cycleFinished, ctx.runner(),
            [line](int cycle, double seconds) {
                line(QJsonObject{{QStringLiteral("event"), QStringLiteral("cycle")},
                                 {QStringLiteral("cycle"), cycle},
                                 {QStringLiteral("time_s"), seconds}},
                     CtlRunner::tr("cycle %1 done in %2 s").arg(cycle).arg(seconds, 0, 'f', 3));
            });
        QObject::connect(runner, &SequenceRunner::finished, ctx.runner(),
                         [&ctx](const SequenceResult &r) { report(ctx, r); });
        // Ctrl-C and SIGTERM stop the motors (and the outputs, as on_stop says) before it ends.
        auto *watcher = new SignalWatcher(runner);
        QObject::connect(watcher, &SignalWatcher::terminationRequested, runner,
                         [runner] { runner->stop(); });
        if (!runner->start(sequence, ctx.options.cycles))
            ctx.fail(ctx.linkError, CtlRunner::tr("the run could not start: not connected"));
    });
}

} // namespace

void runRun(CtlContext &ctx)
{
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError, CtlRunner::tr("run needs one sequence file: run FILE"));
        return;
    }
    QStringList errors;
    const auto sequence = SequenceParser::load(ctx.options.arguments.first(), ctx.map, &errors);
    if (sequence) {
        // stepcomctl's one-shot session knows no axis referenced and no software travel limit:
        // every move_to needs a home step before it. The positions read before the first step
        // are checked again by the runner.
        SequenceCheck::Start start;
        for (int m = 1; m <= ctx.map.blockCount(kMotorBlock); ++m)
            start.axes.insert(m, SequenceCheck::Axis{});
        errors << SequenceCheck::check(*sequence, ctx.map, TravelLimits(), start,
                                       ctx.options.cycles);
    }
    if (!errors.isEmpty()) {
        for (const QString &e : std::as_const(errors))
            ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("the sequence file was refused: nothing was sent"));
        return;
    }
    const QString shown = plan(ctx, *sequence);
    if (ctx.options.yes) {
        ctx.out << shown;
        startRun(ctx, *sequence);
        return;
    }
    confirmThen(ctx, shown, CtlRunner::tr("Run it? The machine will move. [y/N] "),
                {CtlRunner::tr("not confirmed: nothing was sent"),
                 CtlRunner::tr("no answer on standard input: nothing was sent (use --yes)")},
                [&ctx, s = *sequence] { startRun(ctx, s); });
}

} // namespace stepcom
