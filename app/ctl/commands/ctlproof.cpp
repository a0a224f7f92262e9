// stepcomctl lost-steps, margin and backlash: proving an axis (docs/proving.md), shown and asked
// about first, each step a line on standard error as it runs.
#include "../ctlcontext.h"
#include "ctlcommands.h"

#include "consolereader.h"
#include "device/writeplanner.h"
#include "proof/axisproof.h"
#include "proof/backlashtest.h"
#include "proof/marginfinder.h"
#include "signalwatcher.h"

#include <QJsonDocument>
#include <QRegularExpression>

#include <memory>

namespace stepcom {

namespace {

// "motorN" (the one argument), N from 1 to the map's motors; 0 and the run failed otherwise.
int motorArgument(CtlContext &ctx)
{
    static const QRegularExpression motor(QStringLiteral("^motor([0-9]+)$"));
    const QRegularExpressionMatch m = ctx.options.arguments.size() == 1
                                          ? motor.match(ctx.options.arguments.first())
                                          : QRegularExpressionMatch();
    const int n = m.hasMatch() ? m.captured(1).toInt() : 0;
    const int motors = ctx.map.blockCount(kMotorBlock);
    if (n < 1 || n > motors) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("%1 needs one motor: %1 motorN (N from 1 to %2)")
                     .arg(ctx.options.command)
                     .arg(motors));
        return 0;
    }
    return n;
}

// --distance D: a positive number of axis units; `fallback` when not given.
std::optional<double> distanceOption(CtlContext &ctx, double fallback)
{
    if (ctx.options.distance.isEmpty())
        return fallback;
    bool ok = false;
    const double d = ctx.options.distance.toDouble(&ok);
    if (!ok || !(d > 0)) {
        ctx.fail(
            CtlRunner::UsageError,
            CtlRunner::tr("--distance: '%1' is not a positive distance").arg(ctx.options.distance));
        return std::nullopt;
    }
    return d;
}

// A whole number option of margin (--from, --to, --step); true when not given.
bool wholeOption(CtlContext &ctx, const char *name, const QString &text, std::optional<qint64> *out)
{
    if (text.isEmpty())
        return true;
    bool ok = false;
    const qint64 v = text.toLongLong(&ok);
    if (!ok || v < 1) {
        ctx.fail(CtlRunner::UsageError, CtlRunner::tr("--%1: '%2' is not a positive whole number")
                                            .arg(QLatin1String(name), text));
        return false;
    }
    *out = v;
    return true;
}

// Each step of a proof a line on standard error as it runs (a JSON line with --json).
void sayProgress(CtlContext &ctx, const QString &text)
{
    QTextStream err(stderr);
    if (ctx.options.json)
        err << QString::fromUtf8(
                   QJsonDocument(QJsonObject{{QStringLiteral("event"), QStringLiteral("progress")},
                                             {QStringLiteral("text"), text}})
                       .toJson(QJsonDocument::Compact))
            << Qt::endl;
    else
        err << text << Qt::endl;
}

// Standard input as a queue of lines, read through the event loop: the confirmation and then
// every gauge reading come from the one reader, so lines typed ahead are not lost.
class ConsoleLines : public QObject
{
public:
    explicit ConsoleLines(QObject *parent)
        : QObject(parent)
        , m_reader(new ConsoleReader(this))
    {
        connect(m_reader, &ConsoleReader::lineRead, this, [this](const QString &line) {
            m_lines << line;
            serve();
        });
        connect(m_reader, &ConsoleReader::endOfInput, this, [this] {
            m_ended = true;
            serve();
        });
    }
    // The next line, or nullopt once standard input ended.
    void next(std::function<void(std::optional<QString>)> take)
    {
        m_take = std::move(take);
        serve();
    }

private:
    void serve()
    {
        if (!m_take || (m_lines.isEmpty() && !m_ended))
            return;
        auto take = std::exchange(m_take, {});
        take(m_lines.isEmpty() ? std::nullopt : std::optional<QString>(m_lines.takeFirst()));
    }
    ConsoleReader *m_reader;
    QStringList m_lines;
    bool m_ended = false;
    std::function<void(std::optional<QString>)> m_take;
};

// The plan, then the question on the console (standard error with --json); `yes` on y/yes. With
// --yes the plan is printed and `yes` runs at once.
void askThen(CtlContext &ctx, ConsoleLines *lines, const QString &plan, std::function<void()> yes)
{
    QTextStream console(ctx.options.json ? stderr : stdout);
    console << plan;
    if (ctx.options.yes) {
        console << Qt::flush;
        yes();
        return;
    }
    console << CtlRunner::tr("Run it? The axis will move. [y/N] ") << Qt::flush;
    lines->next([&ctx, yes](std::optional<QString> line) {
        if (!line) {
            ctx.fail(CtlRunner::UsageError,
                     CtlRunner::tr("no answer on standard input: nothing was moved (use --yes)"));
            return;
        }
        const QString a = line->trimmed().toLower();
        if (a == QLatin1String("y") || a == QLatin1String("yes")) {
            yes();
            return;
        }
        ctx.fail(CtlRunner::UsageError, CtlRunner::tr("not confirmed: nothing was moved"));
    });
}

// The exit code of a proof that did not come to its verdict.
int exitForOutcome(ProofOutcome outcome)
{
    switch (outcome) {
    case ProofOutcome::Done:
        return CtlRunner::Ok;
    case ProofOutcome::Refused:
        return CtlRunner::UsageError;
    case ProofOutcome::Stopped:
    case ProofOutcome::EmergencyStop:
        return CtlRunner::DeviceError;
    case ProofOutcome::LinkLost:
    case ProofOutcome::Restarted:
    case ProofOutcome::DeviceError:
        break;
    }
    return CtlRunner::LinkError;
}

// The result said: its message on standard output (standard error when it failed), the object
// in the JSON envelope.
void report(CtlContext &ctx, const QJsonObject &result, const QString &text, int code)
{
    ctx.result = result;
    if (code != CtlRunner::Ok)
        ctx.err << QStringLiteral("stepcomctl: ") << text << Qt::endl;
    else if (!ctx.options.json)
        ctx.out << text << Qt::endl;
    ctx.finish(code);
}

// Ctrl-C and SIGTERM stop the motor (and put the registers back) before the run ends.
template<typename Test>
void stopOnSignal(Test *test)
{
    auto *watcher = new SignalWatcher(test);
    QObject::connect(watcher, &SignalWatcher::terminationRequested, test, [test] { test->stop(); });
}

void startLostSteps(CtlContext &ctx, const AxisProof::Options &options)
{
    ctx.connectThen([&ctx, options] {
        auto *lines = new ConsoleLines(ctx.runner());
        auto *proof = new AxisProof(ctx.session, ctx.runner());
        QObject::connect(proof, &AxisProof::progress, ctx.runner(),
                         [&ctx](const QString &t) { sayProgress(ctx, t); });
        QObject::connect(proof, &AxisProof::ready, ctx.runner(),
                         [&ctx, lines, proof](const QString &plan) {
                             askThen(ctx, lines, plan, [proof] { proof->proceed(); });
                         });
        QObject::connect(
            proof, &AxisProof::finished, ctx.runner(), [&ctx](const LostStepResult &r) {
                int code = exitForOutcome(r.outcome);
                if (code == CtlRunner::Ok && r.verdict != LostStepResult::Verdict::Kept)
                    code = CtlRunner::DeviceError; // lost, or not known
                report(ctx, r.toJson(), r.text, code);
            });
        stopOnSignal(proof);
        AxisProof::Options o = options;
        o.askFirst = true;
        proof->start(o);
    });
}

} // namespace

void runLostSteps(CtlContext &ctx)
{
    const int motor = motorArgument(ctx);
    if (!motor)
        return;
    const auto distance = distanceOption(ctx, 10);
    if (!distance)
        return;
    AxisProof::Options o;
    o.motor = motor;
    o.distance = *distance;
    o.cycles = ctx.options.cyclesGiven ? ctx.options.cycles : 3;
    startLostSteps(ctx, o);
}

void runMargin(CtlContext &ctx)
{
    const int motor = motorArgument(ctx);
    if (!motor)
        return;
    MarginFinder::Options o;
    o.motor = motor;
    o.accel = ctx.options.accel;
    const auto distance = distanceOption(ctx, 10);
    if (!distance || !wholeOption(ctx, "from", ctx.options.from, &o.from) ||
        !wholeOption(ctx, "to", ctx.options.to, &o.to) ||
        !wholeOption(ctx, "step", ctx.options.step, &o.step))
        return;
    o.distance = *distance;
    o.cycles = ctx.options.cyclesGiven ? ctx.options.cycles : 2;
    o.askFirst = true;
    ctx.connectThen([&ctx, o] {
        auto *lines = new ConsoleLines(ctx.runner());
        auto *finder = new MarginFinder(ctx.session, ctx.runner());
        QObject::connect(finder, &MarginFinder::progress, ctx.runner(),
                         [&ctx](const QString &t) { sayProgress(ctx, t); });
        QObject::connect(finder, &MarginFinder::ready, ctx.runner(),
                         [&ctx, lines, finder](const QString &plan) {
                             askThen(ctx, lines, plan, [finder] { finder->proceed(); });
                         });
        QObject::connect(
            finder, &MarginFinder::finished, ctx.runner(), [&ctx](const MarginResult &r) {
                const int code = exitForOutcome(r.outcome);
                if (code != CtlRunner::Ok || !ctx.options.apply) {
                    report(ctx, r.toJson(), r.text, code);
                    return;
                }
                if (!r.recommended) {
                    report(ctx, r.toJson(),
                           proofSentences(r.text, CtlRunner::tr("--apply: nothing kept its "
                                                                "steps, nothing was written")),
                           CtlRunner::DeviceError);
                    return;
                }
                // The recommendation through the write's own review and verify.
                ctx.result = r.toJson();
                ctx.out << r.text << Qt::endl;
                const Parameter *p = ctx.map.blockParameter(
                    kMotorBlock, r.motor,
                    r.accel ? QStringLiteral("accel_frequency") : QStringLiteral("speed"));
                const QList<ParameterWrite> writes{{p, *r.recommended}};
                const QJsonObject margin = r.toJson();
                reviewThen(ctx, writes, [&ctx, writes, margin] {
                    for (auto it = margin.begin(); it != margin.end(); ++it)
                        ctx.result.insert(it.key(), it.value());
                    writeThenReport(ctx, writes);
                });
            });
        stopOnSignal(finder);
        finder->start(o);
    });
}

void runBacklash(CtlContext &ctx)
{
    const int motor = motorArgument(ctx);
    if (!motor)
        return;
    const auto distance = distanceOption(ctx, 1);
    if (!distance)
        return;
    BacklashTest::Options o;
    o.motor = motor;
    o.distance = *distance;
    o.cycles = ctx.options.cyclesGiven ? ctx.options.cycles : 3;
    o.askFirst = true;
    ctx.connectThen([&ctx, o] {
        auto *lines = new ConsoleLines(ctx.runner());
        auto *test = new BacklashTest(ctx.session, ctx.runner());
        QObject::connect(test, &BacklashTest::progress, ctx.runner(),
                         [&ctx](const QString &t) { sayProgress(ctx, t); });
        QObject::connect(test, &BacklashTest::ready, ctx.runner(),
                         [&ctx, lines, test](const QString &plan) {
                             askThen(ctx, lines, plan, [test] { test->proceed(); });
                         });
        // Each reading asked for on standard error; a line that is not a number is asked again,
        // the end of standard input stops the test.
        auto ask = std::make_shared<std::function<void(const QString &)>>();
        *ask = [&ctx, lines, test, ask](const QString &where) {
            QTextStream err(stderr);
            err << CtlRunner::tr("%1, %2: gauge (mm)? ").arg(ctx.options.arguments.first(), where)
                << Qt::flush;
            lines->next([&ctx, test, ask, where](std::optional<QString> line) {
                if (!line) {
                    test->stop();
                    return;
                }
                bool ok = false;
                const double v =
                    line->trimmed().replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
                if (!ok || !std::isfinite(v)) {
                    QTextStream(stderr)
                        << CtlRunner::tr("'%1' is not a number: type the gauge's reading")
                               .arg(line->trimmed())
                        << Qt::endl;
                    (*ask)(where);
                    return;
                }
                test->giveReading(v);
            });
        };
        QObject::connect(test, &BacklashTest::readingWanted, ctx.runner(),
                         [ask](int, const QString &where) { (*ask)(where); });
        QObject::connect(test, &BacklashTest::finished, ctx.runner(),
                         [&ctx, ask](const BacklashResult &r) {
                             *ask = {}; // the lambda held itself
                             report(ctx, r.toJson(), r.text, exitForOutcome(r.outcome));
                         });
        stopOnSignal(test);
        test->start(o);
    });
}

} // namespace stepcom
