// stepcomctl dump, diff and report: the profile commands of one controller (docs/profiles.md).
#include "../ctlcontext.h"
#include "ctlcommands.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include "profile/busdump.h"
#include "profile/profilecomparison.h"
#include "profile/profilediff.h"
#include "profile/profilefile.h"
#include "report/commissioningreport.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QLocale>

namespace stepcom {

bool loadProfile(CtlContext &ctx, const QString &path, Profile *out)
{
    // A profile of another map (a firmware variant, a model with more axes) opens with what
    // this map knows; the commands list the rest before they act.
    const ProfileParseResult r = ProfileFile::load(path, ctx.map, ProfileFile::OtherMaps::Accept);
    if (!r.ok()) {
        for (const QString &e : CtlContext::condensed(r.errors))
            ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        return false;
    }
    *out = *r.profile;
    return true;
}

bool loadProfileArgument(CtlContext &ctx, const QString &command, Profile *out)
{
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("%1 needs exactly one profile file").arg(command));
        return false;
    }
    if (!loadProfile(ctx, ctx.options.arguments.first(), out)) {
        ctx.err << QStringLiteral("stepcomctl: ") << CtlRunner::tr("nothing was written")
                << Qt::endl;
        ctx.finish(CtlRunner::UsageError);
        return false;
    }
    return true;
}

void printLeftOut(CtlContext &ctx, const Profile &profile, const QString &heading)
{
    const ProfileVariance &v = profile.variance;
    if (!v.isVariant() && v.isEmpty())
        return;
    if (v.isVariant())
        ctx.out << v.describeMaps() << Qt::endl;
    const QStringList lines = v.describe(ctx.map, ctx.options.language);
    if (lines.isEmpty())
        return;
    ctx.out << heading << Qt::endl;
    for (const QString &line : lines)
        ctx.out << QStringLiteral("  ") << line << Qt::endl;
}

int noteUnsupported(CtlContext &ctx, const ReadOutcome &read, Profile *profile)
{
    if (read.unsupported.isEmpty())
        return 0;
    QStringList keys = read.unsupported;
    keys.sort();
    ctx.out << CtlRunner::tr("not supported by this controller (left out): %1")
                   .arg(keys.join(QLatin1String(", ")))
            << Qt::endl;
    int taken = 0;
    if (profile) {
        for (const QString &key : std::as_const(keys)) {
            taken += int(profile->values.remove(key));
            // A file saved from this controller lacks them too: nothing is missing there.
            profile->variance.missing.removeAll(key);
        }
    }
    return taken;
}

namespace {

// diff A.json B.json: two files, no controller.
void runDiffFiles(CtlContext &ctx)
{
    const QString pathA = ctx.options.arguments.at(0);
    const QString pathB = ctx.options.arguments.at(1);
    Profile a;
    Profile b;
    const bool okA = loadProfile(ctx, pathA, &a);
    const bool okB = loadProfile(ctx, pathB, &b); // both files' problems, at once
    if (!okA || !okB) {
        ctx.fail(CtlRunner::UsageError, CtlRunner::tr("nothing was compared"));
        return;
    }
    const QString nameA = QFileInfo(pathA).fileName();
    const QString nameB = QFileInfo(pathB).fileName();
    auto mapOf = [&ctx](const Profile &p) {
        return p.variance.isVariant() ? p.variance.fileMap : ctx.map.identity();
    };
    ctx.out << CtlRunner::tr("A = %1: \"%2\", register map %3").arg(nameA, a.name, mapOf(a))
            << Qt::endl;
    ctx.out << CtlRunner::tr("B = %1: \"%2\", register map %3").arg(nameB, b.name, mapOf(b))
            << Qt::endl;
    const ProfileComparison c = ProfileComparison::compare(ctx.map, a, b);
    auto value = [&ctx](const ProfileDifference &row, bool left) {
        return ctx.valueText(*row.parameter, left ? *row.device : *row.profile);
    };
    const auto differing = c.differing();
    if (!differing.isEmpty()) {
        ctx.out << CtlRunner::tr("differ (A -> B):") << Qt::endl;
        for (const ProfileDifference &d : differing)
            ctx.out << QStringLiteral("  %1: %2 -> %3")
                           .arg(d.parameter->key, value(d, true), value(d, false))
                    << Qt::endl;
    }
    const auto onlyA = c.onlyInA();
    const auto onlyB = c.onlyInB();
    for (const auto &[rows, heading, left] :
         {std::tuple{onlyA, CtlRunner::tr("only in A (%1):").arg(nameA), true},
          std::tuple{onlyB, CtlRunner::tr("only in B (%1):").arg(nameB), false}}) {
        if (rows.isEmpty())
            continue;
        ctx.out << heading << Qt::endl;
        for (const ProfileDifference &d : rows)
            ctx.out << QStringLiteral("  %1 = %2").arg(d.parameter->key, value(d, left))
                    << Qt::endl;
    }
    const auto foreign = c.foreignDiffering();
    if (!foreign.isEmpty()) {
        ctx.out << CtlRunner::tr(
                       "not settings of register map %1, or out of its range (as the files hold "
                       "them, A -> B):")
                       .arg(ctx.map.identity())
                << Qt::endl;
        auto number = [](const std::optional<double> &v) {
            return v ? QString::number(*v, 'g', QLocale::FloatingPointShortest)
                     : CtlRunner::tr("(none)");
        };
        for (const ProfileForeignRow &f : foreign)
            ctx.out << QStringLiteral("  %1: %2 -> %3  (%4)")
                           .arg(f.key, number(f.a), number(f.b), f.reason)
                    << Qt::endl;
    }
    QJsonArray rows;
    for (const ProfileDifference &d : differing)
        rows.append(QJsonObject{
            {QStringLiteral("key"), d.parameter->key},
            {QStringLiteral("a"),
             d.device ? CtlContext::jsonValue(*d.parameter, *d.device) : QJsonValue()},
            {QStringLiteral("b"),
             d.profile ? CtlContext::jsonValue(*d.parameter, *d.profile) : QJsonValue()}});
    ctx.result = QJsonObject{{QStringLiteral("same"), c.identical()},
                             {QStringLiteral("differences"), rows},
                             {QStringLiteral("only_in_a"), int(onlyA.size())},
                             {QStringLiteral("only_in_b"), int(onlyB.size())},
                             {QStringLiteral("outside_map"), int(foreign.size())}};
    if (c.identical()) {
        ctx.out << CtlRunner::tr("the two profiles hold the same values") << Qt::endl;
        ctx.finish(0);
        return;
    }
    ctx.out << CtlRunner::tr("%1 differ, %2 only in A, %3 only in B, %4 outside this map")
                   .arg(differing.size())
                   .arg(onlyA.size())
                   .arg(onlyB.size())
                   .arg(foreign.size())
            << Qt::endl;
    ctx.finish(1);
}

// report --from PROFILE: from a profile file and its checklist, no controller.
void runReportFromFile(CtlContext &ctx, const QString &path)
{
    Profile profile;
    if (!loadProfile(ctx, ctx.options.from, &profile)) {
        ctx.fail(
            CtlRunner::UsageError,
            CtlRunner::tr("no report: %1 is not a profile StepCom can read").arg(ctx.options.from));
        return;
    }
    ReportInput input =
        ReportInput::fromProfile(ctx.map, profile, ctx.options.from, ctx.options.language);
    if (!input.checklistErrors.isEmpty()) { // a certificate never silently loses its results
        for (const QString &e : std::as_const(input.checklistErrors))
            ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("no report: the checklist beside the profile cannot be read"));
        return;
    }
    if (!ctx.options.name.isEmpty())
        input.title = ctx.options.name;
    if (!ctx.options.notes.isEmpty())
        input.notes = ctx.options.notes;
    if (const QString e = CommissioningReport(input).write(path); !e.isEmpty()) {
        ctx.fail(CtlRunner::UsageError, e);
        return;
    }
    printLeftOut(ctx, profile, CtlRunner::tr("not in the report:"));
    ctx.result =
        QJsonObject{{QStringLiteral("file"), path}, {QStringLiteral("from"), ctx.options.from}};
    ctx.out << CtlRunner::tr(
                   "report written to %1, made from the profile file %2 (no controller was read)")
                   .arg(path, ctx.options.from)
            << Qt::endl;
    if (input.checklist)
        ctx.out << CtlRunner::tr("with the commissioning checklist %1: %2")
                       .arg(input.checklistFile, input.checklist->summary())
                << Qt::endl;
    ctx.finish(CtlRunner::Ok);
}

} // namespace

void runDump(CtlContext &ctx)
{
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("dump needs exactly one file to write the profile to"));
        return;
    }
    const QString path = ctx.options.arguments.first();
    const bool intoFolder = path.endsWith(QLatin1Char('/')) || QFileInfo(path).isDir();
    if (intoFolder) {
        if (const QString problem = BusDump::checkDirectory(path); !problem.isEmpty()) {
            ctx.fail(CtlRunner::UsageError, CtlRunner::tr("nothing was saved: %1").arg(problem));
            return;
        }
    }
    ctx.connectThen([&ctx, path, intoFolder] {
        ctx.session->parameters()->read(
            Profile::profileParameters(ctx.map, true),
            [&ctx, path, intoFolder](const ReadOutcome &r) {
                if (!r.ok) {
                    for (const QString &e : CtlContext::condensed(r.errors))
                        ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    ctx.fail(CtlRunner::DeviceError,
                             CtlRunner::tr("nothing was saved: the controller could "
                                           "not be read completely"));
                    return;
                }
                if (intoFolder) {
                    dumpIntoFolder(ctx, path, r.values);
                    return;
                }
                noteUnsupported(ctx, r);
                Profile profile = Profile::fromValues(ctx.map, r.values, ctx.options.includeLink);
                profile.unsupported = r.unsupported;
                profile.unsupported.sort();
                profile.name = ctx.options.name.isEmpty() ? QFileInfo(path).completeBaseName()
                                                          : ctx.options.name;
                profile.notes = ctx.options.notes;
                profile.deviceId = ctx.session->connection()->settings().deviceId;
                profile.fromSimulator = ctx.session->connection()->isSimulator();
                if (const QString e = ProfileFile::save(path, profile, ctx.map); !e.isEmpty()) {
                    ctx.fail(CtlRunner::DeviceError, e); // not done: the file could not be written
                    return;
                }
                ctx.result =
                    QJsonObject{{QStringLiteral("file"), path},
                                {QStringLiteral("parameters"), int(profile.values.size())}};
                ctx.out << CtlRunner::tr("saved %n parameter(s) of %1 to %2", nullptr,
                                         int(profile.values.size()))
                               .arg(ctx.session->connection()->settings().describe(), path)
                        << Qt::endl;
                ctx.finish(CtlRunner::Ok);
            });
    });
}

void runDiff(CtlContext &ctx)
{
    if (ctx.options.arguments.size() == 2) {
        runDiffFiles(ctx); // two files: no controller needed
        return;
    }
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("diff needs one profile file (compared with the controller) or two "
                               "(compared with each other)"));
        return;
    }
    Profile profile;
    if (!loadProfileArgument(ctx, QStringLiteral("diff"), &profile))
        return;
    ctx.linkError = CtlRunner::LinkError; // 1 means "different" here
    ctx.connectThen([&ctx, profile] {
        ctx.session->parameters()->read(
            Profile::profileParameters(ctx.map, true), [&ctx, profile](const ReadOutcome &r) {
                if (!r.ok) {
                    for (const QString &e : CtlContext::condensed(r.errors))
                        ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    ctx.finish(ctx.linkError);
                    return;
                }
                Profile compared = profile;
                const int unsupported = noteUnsupported(ctx, r, &compared);
                const auto diffs =
                    ProfileDiff::differences(ProfileDiff::compare(ctx.map, compared, r.values));
                QJsonArray rows;
                for (const ProfileDifference &d : diffs) {
                    ctx.out << ProfileDiff::describe(d) << Qt::endl;
                    const auto value = [&d](const std::optional<qint64> &raw) {
                        return raw ? CtlContext::jsonValue(*d.parameter, *raw) : QJsonValue();
                    };
                    rows.append(QJsonObject{{QStringLiteral("key"), d.parameter->key},
                                            {QStringLiteral("controller"), value(d.device)},
                                            {QStringLiteral("profile"), value(d.profile)}});
                }
                ctx.result.insert(QStringLiteral("differences"), rows);
                printLeftOut(ctx, compared, CtlRunner::tr("left out of the comparison:"));
                const ProfileVariance &v = compared.variance;
                const int leftOut =
                    int(v.unknown.size() + v.rejected.size() + v.missing.size()) + unsupported;
                if (diffs.isEmpty() && leftOut == 0)
                    ctx.out << CtlRunner::tr("the controller holds every value of the profile")
                            << Qt::endl;
                else if (diffs.isEmpty())
                    ctx.out << CtlRunner::tr(
                                   "the controller holds every value both maps have; %n left out",
                                   nullptr, leftOut)
                            << Qt::endl;
                else
                    ctx.out << CtlRunner::tr("%n value(s) differ (controller -> profile)", nullptr,
                                             int(diffs.size()))
                            << Qt::endl;
                ctx.result.insert(QStringLiteral("left_out"), leftOut);
                ctx.result.insert(QStringLiteral("same"), diffs.isEmpty() && leftOut == 0);
                // A comparison that had to leave values out is not "the same".
                ctx.finish(diffs.isEmpty() && leftOut == 0 ? 0 : 1);
            });
    });
}

QString reportPath(CtlContext &ctx)
{
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("report needs exactly one file (.pdf or .html)"));
        return QString();
    }
    const QString path = ctx.options.arguments.first();
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("pdf") && suffix != QLatin1String("html") &&
        suffix != QLatin1String("htm")) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("%1: the report is written as .pdf or .html").arg(path));
        return QString();
    }
    return path;
}

void runReport(CtlContext &ctx)
{
    const QString path = reportPath(ctx);
    if (path.isEmpty())
        return;
    if (!ctx.options.from.isEmpty()) {
        runReportFromFile(ctx, path); // no controller
        return;
    }
    // The report speaks the program's language (--lang or the environment), installed in main().
    ctx.connectThen([&ctx, path] {
        ctx.session->parameters()->readAll([&ctx, path](const ReadOutcome &r) {
            if (!r.ok) {
                for (const QString &e : CtlContext::condensed(r.errors))
                    ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                ctx.fail(CtlRunner::DeviceError,
                         CtlRunner::tr("no report: the controller could not be read completely"));
                return;
            }
            noteUnsupported(ctx, r);
            // A one-shot session: the flash state is not known.
            ReportInput input =
                ReportInput::fromSession(*ctx.session, ctx.session->line()->deviceInView(),
                                         r.values, QDateTime::currentDateTime());
            input.unsupported = r.unsupported;
            input.title = ctx.options.name;
            input.notes = ctx.options.notes;
            input.locale = ctx.options.language;
            if (const QString e = CommissioningReport(input).write(path); !e.isEmpty()) {
                ctx.fail(CtlRunner::UsageError, e);
                return;
            }
            ctx.result = QJsonObject{{QStringLiteral("file"), path}};
            ctx.out << CtlRunner::tr("report written to %1").arg(path) << Qt::endl;
            ctx.finish(CtlRunner::Ok);
        });
    });
}

} // namespace stepcom
