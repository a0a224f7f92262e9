// stepcomctl run FILE: a machine cycle (.stepseq, docs/sequence.md) run on the controller,
// shown and asked about first, each step said on standard error as it starts.
#include "../ctlcontext.h"
#include "ctlcommands.h"

#include "proof/axisproof.h"
#include "sequence/sequencecheck.h"
#include "sequence/sequenceparser.h"
#include "sequence/sequenceplan.h"
#include "sequence/sequencerunner.h"
#include "signalwatcher.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <memory>

namespace stepcom {

namespace {

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

void report(CtlContext &ctx, const SequenceResult &r, const QList<LostStepResult> &checks = {})
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
    int code = exitFor(r.outcome);
    if (ctx.options.checkSteps) {
        // After a run that ended well: each moved axis's lost-step test, the worst verdict.
        QJsonArray list;
        QString verdict = checks.isEmpty() ? QStringLiteral("unknown") : QStringLiteral("kept");
        for (const LostStepResult &c : checks) {
            list.append(c.toJson());
            if (c.outcome != ProofOutcome::Done || c.verdict == LostStepResult::Verdict::Unknown)
                verdict = verdict == QLatin1String("lost") ? verdict : QStringLiteral("unknown");
            if (c.verdict == LostStepResult::Verdict::Lost)
                verdict = QStringLiteral("lost");
            const QString line = CtlRunner::tr("check-steps: %1").arg(c.text);
            if (c.ok() && !ctx.options.json)
                ctx.out << line << Qt::endl;
            else if (!c.ok())
                ctx.err << QStringLiteral("stepcomctl: ") << line << Qt::endl;
        }
        ctx.result.insert(QStringLiteral("check_steps"), list);
        ctx.result.insert(QStringLiteral("check_steps_verdict"), verdict);
        if (code == CtlRunner::Ok && verdict != QLatin1String("kept"))
            code = CtlRunner::DeviceError;
    }
    ctx.finish(code);
}

// --check-steps: the lost-step test on each motor in turn, then the run's report with them.
// `current` is the test under way, which Ctrl-C stops.
void checkSteps(CtlContext &ctx, const SequenceResult &run, QList<int> motors,
                std::shared_ptr<QPointer<AxisProof>> current, QList<LostStepResult> done = {})
{
    if (motors.isEmpty()) {
        report(ctx, run, done);
        return;
    }
    auto *proof = new AxisProof(ctx.session, ctx.runner());
    *current = proof;
    QObject::connect(proof, &AxisProof::progress, ctx.runner(), [&ctx](const QString &t) {
        QTextStream(stderr) << (ctx.options.json
                                    ? QString::fromUtf8(
                                          QJsonDocument(QJsonObject{{QStringLiteral("event"),
                                                                     QStringLiteral("check_steps")},
                                                                    {QStringLiteral("text"), t}})
                                              .toJson(QJsonDocument::Compact))
                                    : t)
                            << Qt::endl;
    });
    QObject::connect(proof, &AxisProof::finished, ctx.runner(),
                     [&ctx, run, motors, current, done, proof](const LostStepResult &r) mutable {
                         proof->deleteLater();
                         done << r;
                         motors.removeFirst();
                         // A check that could not end (the link, an E-STOP) ends them all.
                         if (r.outcome != ProofOutcome::Done)
                             motors.clear();
                         checkSteps(ctx, run, motors, current, done);
                     });
    AxisProof::Options o;
    o.motor = motors.first();
    proof->start(o);
}

void startRun(CtlContext &ctx, const Sequence &sequence)
{
    ctx.connectThen([&ctx, sequence] {
        auto *runner = new SequenceRunner(ctx.session, ctx.runner());
        auto checking = std::make_shared<QPointer<AxisProof>>(); // --check-steps' test
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
                         [&ctx, moved = SequencePlan::movedMotors(sequence),
                          limits = sequence.limits, checking](const SequenceResult &r) {
                             if (ctx.options.checkSteps && r.ok()) {
                                 // The file's limits hold for the tests' moves too.
                                 ctx.session->setTravelLimits(limits);
                                 checkSteps(ctx, r, moved, checking);
                             } else
                                 report(ctx, r);
                         });
        // Ctrl-C and SIGTERM stop the motors (and the outputs, as on_stop says) before it ends.
        auto *watcher = new SignalWatcher(runner);
        QObject::connect(watcher, &SignalWatcher::terminationRequested, runner, [runner, checking] {
            runner->stop();
            if (*checking)
                (*checking)->stop();
        });
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
    const QString shown =
        SequencePlan::describe(*sequence, ctx.map, ctx.options.cycles, ctx.options.checkSteps);
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
