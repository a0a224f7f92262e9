// stepcomctl apply: a profile's values that differ, shown, asked about (--yes skips the
// question), written through ProfileApply and verified (docs/profiles.md).
#include "../ctlcontext.h"
#include "../ctllinkadvice.h"
#include "ctlcommands.h"

#include "consolereader.h"

#include "profile/profileapply.h"
#include "profile/profilediff.h"

#include <QJsonArray>
#include <QJsonObject>

#include <memory>

namespace stepcom {

namespace {

// Prints what ProfileApply came to: each value written and verified, what was not and why;
// `writes` are what was confirmed.
void reportApplied(CtlContext &ctx, const ProfileApplyResult &result,
                   const QList<ParameterWrite> &writes)
{
    QJsonObject written;
    for (const AppliedKey &k : result.keys) {
        if (k.state != AppliedKey::State::Verified)
            continue;
        written.insert(k.key, CtlContext::jsonValue(*k.parameter, k.wanted));
        ctx.out << k.key << QStringLiteral(" = ") << ctx.valueText(*k.parameter, k.wanted)
                << QStringLiteral("  ") << CtlRunner::tr("(written, verified)") << Qt::endl;
    }
    const QStringList notWritten =
        result.keysIn(AppliedKey::State::NotWritten) + result.keysIn(AppliedKey::State::Refused);
    if (!result.keys.isEmpty() || !written.isEmpty()) {
        ctx.result.insert(QStringLiteral("written"), written);
        ctx.result.insert(QStringLiteral("not_written"), QJsonArray::fromStringList(notWritten));
    }
    for (const QString &e : result.writeErrors)
        ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
    // Past what the write said: each key not verified, and why (not known is never guessed).
    for (const AppliedKey &k : result.keys) {
        if (k.state == AppliedKey::State::Refused || k.state == AppliedKey::State::NotKnown ||
            k.state == AppliedKey::State::Lost)
            ctx.err << QStringLiteral("stepcomctl: ") << ProfileApplyResult::describe(k)
                    << Qt::endl;
    }
    if (!notWritten.isEmpty())
        ctx.err << QStringLiteral("stepcomctl: ")
                << CtlRunner::tr("not written: %1").arg(notWritten.join(QLatin1String(", ")))
                << Qt::endl;
    const bool allHeld = std::all_of(result.keys.cbegin(), result.keys.cend(), [](const auto &k) {
        return k.state == AppliedKey::State::Verified || k.state == AppliedKey::State::Unchanged;
    });
    if (result.end != ProfileApplyResult::End::Done || !allHeld) {
        if (result.error.isEmpty())
            ctx.finish(CtlRunner::DeviceError);
        else
            ctx.fail(CtlRunner::DeviceError, result.error);
        return;
    }
    // --include-link: how the next command reaches a new id or baud (the flash is said below).
    for (const QString &note : CtlLinkAdvice::notes(ctx.options, writes, true))
        ctx.out << note << Qt::endl;
    if (result.flashAsked) {
        if (result.savedToFlash != true) {
            ctx.fail(CtlRunner::DeviceError, result.flashError);
            return;
        }
        ctx.out << CtlRunner::tr("saved to flash") << Qt::endl;
        ctx.finish(CtlRunner::Ok);
        return;
    }
    ctx.out << CtlRunner::tr("not saved to flash: the controller forgets these values at power-off "
                             "(use --save-to-flash)")
            << Qt::endl;
    ctx.finish(CtlRunner::Ok);
}

void applyWrites(CtlContext &ctx, ProfileApply *applier, const QList<ParameterWrite> &writes)
{
    QStringList keys;
    for (const ParameterWrite &w : writes)
        keys << w.parameter->key;
    // `finished` follows apply() only: the writes confirmed are what its report names.
    QObject::connect(
        applier, &ProfileApply::finished, ctx.runner(),
        [&ctx, writes](const ProfileApplyResult &result) { reportApplied(ctx, result, writes); });
    applier->apply(keys);
}

void confirmThenApply(CtlContext &ctx, ProfileApply *applier, const QList<ParameterWrite> &writes)
{
    if (ctx.options.yes) {
        applyWrites(ctx, applier, writes);
        return;
    }
    const QString question =
        ctx.isMulti()
            ? CtlRunner::tr("Write these %n value(s) to id %1? [y/N] ", nullptr, int(writes.size()))
                  .arg(ctx.options.ids.at(ctx.idIndex))
            : CtlRunner::tr("Write these %n value(s) to the controller? [y/N] ", nullptr,
                            int(writes.size()));
    confirmThen(ctx, QString(), question,
                {CtlRunner::tr("not confirmed: nothing was written"),
                 CtlRunner::tr("no answer on standard input: nothing was written (use --yes)")},
                [&ctx, applier, writes] { applyWrites(ctx, applier, writes); });
}

} // namespace

void confirmThen(CtlContext &ctx, const QString &shown, const QString &question,
                 const ConfirmRefusals &refusals, std::function<void()> yes)
{
    if (ctx.isMulti() || ctx.isEnveloped()) {
        // With several ids the output is keyed by id at the end; what the question is about
        // must be seen before it is answered (on standard error with --json, which stays JSON).
        ctx.out.flush();
        QTextStream console(ctx.options.json ? stderr : stdout);
        if (ctx.isMulti())
            console << CtlRunner::tr("== device id %1 ==").arg(ctx.options.ids.at(ctx.idIndex))
                    << Qt::endl;
        console << ctx.outBuffer << shown << question << Qt::flush;
        if (ctx.isMulti()) { // shown now; one id's messages stay in its JSON object
            ctx.outBuffer.clear();
            ctx.out.setString(&ctx.outBuffer);
        }
    } else {
        ctx.out << shown << question << Qt::flush;
    }
    // Standard input is read through the event loop, so the link stays served meanwhile.
    auto *console = new ConsoleReader(ctx.runner());
    auto answered = std::make_shared<bool>(false);
    QObject::connect(console, &ConsoleReader::lineRead, ctx.runner(),
                     [&ctx, yes, refusals, console, answered](const QString &line) {
                         if (*answered)
                             return;
                         *answered = true;
                         console->deleteLater();
                         const QString a = line.trimmed().toLower();
                         if (a == QLatin1String("y") || a == QLatin1String("yes")) {
                             yes();
                             return;
                         }
                         ctx.fail(CtlRunner::UsageError, refusals.notConfirmed);
                     });
    QObject::connect(console, &ConsoleReader::endOfInput, ctx.runner(),
                     [&ctx, refusals, console, answered] {
                         if (*answered)
                             return;
                         *answered = true;
                         console->deleteLater();
                         ctx.fail(CtlRunner::UsageError, refusals.noAnswer);
                     });
}

void runApply(CtlContext &ctx)
{
    Profile profile;
    if (!loadProfileArgument(ctx, QStringLiteral("apply"), &profile))
        return;
    if (profile.values.isEmpty()) { // another map's profile with nothing this map can take
        printLeftOut(ctx, profile, CtlRunner::tr("not applied:"));
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("the profile holds no setting of this map: nothing to apply"));
        return;
    }
    if (ctx.options.includeLink && ctx.options.target == CtlOptions::Target::Tcp &&
        profile.values.contains(QStringLiteral("device.baud"))) {
        ctx.err << QStringLiteral("stepcomctl: ")
                << CtlRunner::tr("note: device.baud changes the controller's serial side only")
                << Qt::endl;
    }
    ctx.connectThen([&ctx, profile] {
        // ProfileApply reads, compares, backs up (the session's risk guard), writes, verifies.
        // This id's own: a run of several ids makes one for each.
        auto *applier = new ProfileApply(ctx.session, profile, 0, ctx.runner());
        applier->setIncludeLink(ctx.options.includeLink);
        applier->setSaveToFlash(ctx.options.saveToFlash);
        QObject::connect(
            applier, &ProfileApply::compared, ctx.runner(), [&ctx, applier, profile](bool ok) {
                if (!ok) {
                    for (const QString &e : CtlContext::condensed(applier->readErrors()))
                        ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    ctx.fail(CtlRunner::DeviceError, CtlRunner::tr("nothing was written"));
                    return;
                }
                ReadOutcome r;
                r.values = applier->before();
                r.unsupported = applier->unsupported();
                Profile applied = profile;
                noteUnsupported(ctx, r, &applied); // never written: the controller lacks them
                QStringList keys;
                for (const ProfileDifference &d :
                     ProfileDiff::differences(ProfileDiff::compare(ctx.map, applied, r.values))) {
                    if (d.linkSetting && !ctx.options.includeLink) {
                        ctx.out << CtlRunner::tr("not applied (needs --include-link): %1")
                                       .arg(ProfileDiff::describe(d))
                                << Qt::endl;
                        continue;
                    }
                    keys << d.parameter->key;
                    ctx.out << CtlRunner::tr("will write %1").arg(ProfileDiff::describe(d))
                            << Qt::endl;
                }
                ctx.result.insert(QStringLiteral("to_write"), QJsonArray::fromStringList(keys));
                // Said before asking, and with --yes too: what of the profile is not applied.
                printLeftOut(ctx, applied, CtlRunner::tr("not applied:"));
                QStringList errors;
                const QList<ParameterWrite> writes = ProfileDiff::writesFor(
                    ctx.map, applied, keys, ctx.options.includeLink, &errors);
                if (!errors.isEmpty()) {
                    ctx.fail(CtlRunner::UsageError, errors.join(QLatin1String("; ")));
                    return;
                }
                if (writes.isEmpty()) {
                    ctx.out << (profile.variance.isVariant()
                                    ? CtlRunner::tr(
                                          "the controller already holds every value both maps have")
                                    : CtlRunner::tr(
                                          "the controller already holds the profile's values"))
                            << Qt::endl;
                    if (ctx.options.saveToFlash)
                        applyWrites(ctx, applier, {}); // nothing to write: only the save to flash
                    else
                        ctx.finish(CtlRunner::Ok);
                    return;
                }
                // What the window's write dialog asks, said before the question (and with --yes).
                for (const QString &q : applier->questions(keys))
                    ctx.out << CtlRunner::tr("check: %1").arg(q) << Qt::endl;
                confirmThenApply(ctx, applier, writes);
            });
        applier->compare();
    });
}

} // namespace stepcom
