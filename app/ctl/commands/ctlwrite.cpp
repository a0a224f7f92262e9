// stepcomctl write: parsed and checked, reviewed as the window reviews it (WriteReview), then
// written and verified.
#include "../ctlcontext.h"
#include "../ctllinkadvice.h"
#include "ctlcommands.h"
#include "session/parts/sessionparameters.h"

#include "device/writereview.h"

#include <QJsonArray>
#include <QJsonObject>

namespace stepcom {

namespace {

// Prints each value written and verified, and what was not, into the output and the JSON
// result ("written", "not_written").
void reportWritten(CtlContext &ctx, const QList<ParameterWrite> &writes, const WriteOutcome &w)
{
    QJsonObject written;
    for (const ParameterWrite &pw : writes) {
        if (!w.verified(pw.parameter->key))
            continue;
        written.insert(pw.parameter->key, CtlContext::jsonValue(*pw.parameter, pw.raw));
        ctx.out << pw.parameter->key << QStringLiteral(" = ")
                << ctx.valueText(*pw.parameter, pw.raw) << QStringLiteral("  ")
                << CtlRunner::tr("(written, verified)") << Qt::endl;
    }
    ctx.result.insert(QStringLiteral("written"), written);
    ctx.result.insert(QStringLiteral("not_written"), QJsonArray::fromStringList(w.notWritten));
    for (const QString &e : w.errors)
        ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
    if (!w.notWritten.isEmpty())
        ctx.err << QStringLiteral("stepcomctl: ")
                << CtlRunner::tr("not written: %1").arg(w.notWritten.join(QLatin1String(", ")))
                << Qt::endl;
}

// --save-to-flash after the write.
void saveToFlashThenFinish(CtlContext &ctx)
{
    const Parameter *save = ctx.map.find(QStringLiteral("save_to_flash"));
    if (!save) {
        ctx.fail(CtlRunner::DeviceError, CtlRunner::tr("this map has no save_to_flash command"));
        return;
    }
    ctx.session->command(*save, [&ctx](const Result &r) {
        if (!r.ok) {
            ctx.fail(CtlRunner::DeviceError, r.errorText);
            return;
        }
        ctx.out << CtlRunner::tr("saved to flash") << Qt::endl;
        ctx.finish(CtlRunner::Ok);
    });
}

} // namespace

void writeThenReport(CtlContext &ctx, const QList<ParameterWrite> &writes)
{
    ctx.session->parameters()->write(writes, [&ctx, writes](const WriteOutcome &w) {
        reportWritten(ctx, writes, w);
        if (!w.ok) {
            ctx.finish(CtlRunner::DeviceError);
            return;
        }
        for (const QString &note :
             CtlLinkAdvice::notes(ctx.options, writes, ctx.options.saveToFlash))
            ctx.out << note << Qt::endl;
        if (!ctx.options.saveToFlash) {
            ctx.finish(CtlRunner::Ok);
            return;
        }
        saveToFlashThenFinish(ctx);
    });
}

void reviewThen(CtlContext &ctx, const QList<ParameterWrite> &writes, std::function<void()> next)
{
    const auto judge = [&ctx, writes, next](const QHash<QString, qint64> &held) {
        const QStringList problems = WriteReview::problems(
            ctx.map,
            [&held](const QString &key) {
                const auto it = held.constFind(key);
                return it == held.cend() ? std::nullopt : std::optional<qint64>(*it);
            },
            writes);
        for (const QString &p : problems)
            ctx.err << QStringLiteral("stepcomctl: ") << CtlRunner::tr("check: %1").arg(p)
                    << Qt::endl;
        if (!problems.isEmpty())
            ctx.result.insert(QStringLiteral("questions"), QJsonArray::fromStringList(problems));
        if (!problems.isEmpty() && !ctx.options.yes) {
            ctx.fail(CtlRunner::UsageError,
                     CtlRunner::tr("nothing was written: the window asks before writing these "
                                   "values; add --yes to write them anyway"));
            return;
        }
        next();
    };
    // What the review judges besides the values written: the wiring, the mode, the path.
    QList<const Parameter *> params;
    for (const QString &k : WriteReview::keysRead(ctx.map, writes))
        params << ctx.map.find(k);
    if (params.isEmpty()) {
        judge({});
        return;
    }
    ctx.session->parameters()->read(params, [&ctx, judge](const ReadOutcome &r) {
        if (!r.ok) {
            for (const QString &e : CtlContext::condensed(r.errors))
                ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
            ctx.fail(CtlRunner::DeviceError,
                     CtlRunner::tr("what the values are checked against could not be read: "
                                   "nothing was written"));
            return;
        }
        judge(r.values);
    });
}

void runWrite(CtlContext &ctx)
{
    if (ctx.options.arguments.isEmpty()) {
        ctx.fail(CtlRunner::UsageError, CtlRunner::tr("write needs KEY=VALUE arguments"));
        return;
    }
    QList<ParameterWrite> writes;
    QStringList problems;
    for (const QString &arg : std::as_const(ctx.options.arguments)) {
        const qsizetype eq = arg.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            problems << CtlRunner::tr("'%1' is not KEY=VALUE").arg(arg);
            continue;
        }
        const QString key = arg.left(eq).trimmed();
        const Parameter *p = ctx.map.find(key);
        if (!p) {
            problems << CtlRunner::tr("unknown parameter '%1' (see: stepcomctl params)").arg(key);
            continue;
        }
        if (!p->writable()) {
            problems
                << (p->isCoil()
                        ? CtlRunner::tr("%1 is a command: use 'stepcomctl command %1'").arg(key)
                        : CtlRunner::tr("%1 is read-only").arg(key));
            continue;
        }
        QString error;
        const auto raw = p->parse(arg.mid(eq + 1), &error);
        if (!raw) {
            problems << error;
            continue;
        }
        writes.append({p, *raw});
    }
    if (problems.isEmpty())
        problems = DeviceClient::validate(writes); // duplicates, as the device client checks
    if (!problems.isEmpty()) {
        for (const QString &p : std::as_const(problems))
            ctx.err << QStringLiteral("stepcomctl: ") << p << Qt::endl;
        ctx.err << QStringLiteral("stepcomctl: ") << CtlRunner::tr("nothing was written")
                << Qt::endl;
        ctx.finish(CtlRunner::UsageError);
        return;
    }
    // A new id or baud, or a save to flash after the write: the settings before it are backed up.
    std::optional<DeviceSession::Risk> risk;
    for (const ParameterWrite &w : std::as_const(writes)) {
        if (w.parameter->key == QLatin1String("device.id"))
            risk = DeviceSession::Risk::DeviceId;
        else if (w.parameter->key == QLatin1String("device.baud") && !risk)
            risk = DeviceSession::Risk::Baud;
    }
    if (!risk && ctx.options.saveToFlash)
        risk = DeviceSession::Risk::SaveToFlash;
    ctx.connectThen([&ctx, writes, risk] {
        reviewThen(ctx, writes, [&ctx, writes, risk] {
            if (risk) {
                ctx.guardThen(*risk, [&ctx, writes] { writeThenReport(ctx, writes); });
                return;
            }
            writeThenReport(ctx, writes);
        });
    });
}

} // namespace stepcom
