// stepcomctl replay and bundle: a session log (--log FILE or the window's) replayed without a
// controller, and the support bundle a technician sends.
#include "../ctlcontext.h"
#include "ctlcommands.h"

#include "report/machinereport.h"
#include "support/replaylog.h"
#include "support/supportbundle.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QTemporaryDir>

namespace stepcom {

namespace {

QString deviceText(int id)
{
    return id == 0 ? QStringLiteral("line") : QStringLiteral("id %1").arg(id);
}

// The bundle with the machine report of `sheets` (none: `input.noReport` says why).
void writeBundle(CtlContext &ctx, BundleInput input, const QList<ReportInput> &sheets)
{
    if (!sheets.isEmpty()) {
        const MachineReport report(sheets, ctx.options.name, ctx.options.notes,
                                   ctx.options.language);
        input.reportHtml = report.selfContainedHtml().toUtf8();
        input.reportSheets = report.sheetLines();
    } else if (input.noReport.isEmpty()) {
        input.noReport = QStringLiteral("no controller was read (--port, --tcp or --sim) and no "
                                        "profile was given (--profile)");
    }
    QStringList contents;
    QString error;
    const QString out = ctx.options.arguments.first();
    if (!SupportBundle::create(out, input, &contents, &error)) {
        ctx.fail(CtlRunner::DeviceError, error); // not done: the file could not be written
        return;
    }
    ctx.result = QJsonObject{{QStringLiteral("file"), out},
                             {QStringLiteral("contents"), QJsonArray::fromStringList(contents)},
                             {QStringLiteral("report"), !input.reportHtml.isEmpty()}};
    ctx.out << CtlRunner::tr("wrote %1 (%2):")
                   .arg(out, QLocale::c().formattedDataSize(QFileInfo(out).size()))
            << Qt::endl;
    for (const QString &name : std::as_const(contents))
        ctx.out << QStringLiteral("  ") << name << Qt::endl;
    if (input.reportHtml.isEmpty() && ctx.options.profile.isEmpty()) // else said above
        ctx.out << CtlRunner::tr(
                       "no machine report: no controller was read (--port, --tcp or --sim) and no "
                       "profile was given (--profile)")
                << Qt::endl;
    ctx.finish(CtlRunner::Ok);
}

} // namespace

void runReplay(CtlContext &ctx)
{
    const int modes = int(ctx.options.events) + int(!ctx.options.at.isEmpty()) +
                      int(!ctx.options.diffFrom.isEmpty());
    const int wanted = ctx.options.diffFrom.isEmpty() ? 1 : 2; // --diff T1 T2: T2 is an argument
    if (modes != 1 || ctx.options.arguments.size() != wanted) {
        ctx.fail(
            CtlRunner::UsageError,
            CtlRunner::tr("replay needs a log and one of --events, --at TIME or --diff T1 T2"));
        return;
    }
    QString path = ctx.options.arguments.first();
    // A support bundle: one of its logs, copied out for the replay's seeks.
    QTemporaryDir temporary;
    QFile probe(path);
    if (probe.open(QIODevice::ReadOnly) && probe.read(4) == QByteArrayLiteral("PK\x03\x04")) {
        QString error;
        const QStringList logs = SupportBundle::logs(path, &error);
        if (logs.isEmpty()) {
            ctx.fail(CtlRunner::UsageError, error);
            return;
        }
        QString entry = logs.last();
        if (!ctx.options.entry.isEmpty()) {
            const auto named = std::find_if(logs.cbegin(), logs.cend(), [&ctx](const QString &l) {
                return l == ctx.options.entry || QFileInfo(l).fileName() == ctx.options.entry;
            });
            if (named == logs.cend()) {
                ctx.fail(CtlRunner::UsageError,
                         CtlRunner::tr("--entry: the bundle holds no log %1 (it holds: %2)")
                             .arg(ctx.options.entry, logs.join(QStringLiteral(", "))));
                return;
            }
            entry = *named;
        }
        ctx.err << QStringLiteral("stepcomctl: ")
                << CtlRunner::tr("replaying %1 (logs in the bundle: %2; --entry NAME for another)")
                       .arg(entry)
                       .arg(logs.size())
                << Qt::endl;
        path = SupportBundle::extract(path, entry, temporary.path(), &error);
        if (path.isEmpty()) {
            ctx.fail(CtlRunner::UsageError, error);
            return;
        }
    }
    ReplayLog log(ctx.map);
    if (!log.open(path)) {
        ctx.fail(CtlRunner::UsageError, log.errorString());
        return;
    }
    for (const QString &w : log.warnings())
        ctx.err << QStringLiteral("stepcomctl: ") << CtlRunner::tr("warning: %1").arg(w)
                << Qt::endl;

    if (ctx.options.events) {
        QJsonArray array;
        for (const ReplayEvent &e : log.events()) {
            if (ctx.options.json) {
                array.append(QJsonObject{{QStringLiteral("t_s"), double(e.ms) / 1000.0},
                                         {QStringLiteral("device"), e.device},
                                         {QStringLiteral("kind"), ReplayEvent::kindName(e.kind)},
                                         {QStringLiteral("text"), e.text},
                                         {QStringLiteral("line"), double(e.line)}});
                continue;
            }
            ctx.out << QStringLiteral("%1  %2  %3  %4")
                           .arg(log.momentText(e.ms), -26)
                           .arg(deviceText(e.device), -6)
                           .arg(ReplayEvent::kindName(e.kind), -11)
                           .arg(e.text)
                    << Qt::endl;
        }
        if (ctx.options.json)
            ctx.out << QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Indented));
        ctx.finish(CtlRunner::Ok);
        return;
    }
    QString error;
    const auto first = log.parseTime(
        ctx.options.diffFrom.isEmpty() ? ctx.options.at : ctx.options.diffFrom, &error);
    if (!first) {
        ctx.fail(CtlRunner::UsageError, error);
        return;
    }
    if (!ctx.options.at.isEmpty()) {
        const ReplayState state = log.stateAt(*first);
        if (ctx.options.json) {
            QJsonObject o = state.toJson(ctx.map);
            o.insert(QStringLiteral("clock"), log.momentText(state.ms));
            ctx.out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            ctx.finish(CtlRunner::Ok);
            return;
        }
        ctx.out << CtlRunner::tr("at %1, link %2")
                       .arg(log.momentText(state.ms),
                            state.linkUp ? CtlRunner::tr("up") : CtlRunner::tr("down"))
                << Qt::endl;
        for (auto it = state.devices.cbegin(); it != state.devices.cend(); ++it) {
            const QHash<QString, qint64> values = it->values(ctx.map);
            const QHash<QString, qint64> written = it->writtenValues(ctx.map);
            ctx.out << QStringLiteral("id %1: ").arg(it.key())
                    << (it->answering ? CtlRunner::tr("answering")
                                      : CtlRunner::tr("not answering"));
            if (!it->lastError.isEmpty())
                ctx.out << QStringLiteral("; ")
                        << CtlRunner::tr("last error at %1: %2")
                               .arg(log.momentText(it->lastErrorMs), it->lastError);
            ctx.out << Qt::endl;
            for (const Parameter *p : ctx.map.holdings()) {
                if (values.contains(p->key))
                    ctx.out << QStringLiteral("  %1 = %2%3")
                                   .arg(p->key, ctx.valueText(*p, values.value(p->key)),
                                        written.contains(p->key)
                                            ? QStringLiteral("  ") +
                                                  CtlRunner::tr("(last written: %1)")
                                                      .arg(ctx.valueText(*p, written.value(p->key)))
                                            : QString())
                            << Qt::endl;
            }
        }
        ctx.finish(CtlRunner::Ok);
        return;
    }
    const auto second = log.parseTime(ctx.options.arguments.at(1), &error);
    if (!second) {
        ctx.fail(CtlRunner::UsageError, error);
        return;
    }
    const ReplayState from = log.stateAt(*first);
    const ReplayState to = log.stateAt(*second);
    const QStringList changes = to.diff(from, ctx.map);
    if (ctx.options.json) {
        ctx.out << QString::fromUtf8(
            QJsonDocument(
                QJsonObject{{QStringLiteral("from_s"), double(from.ms) / 1000.0},
                            {QStringLiteral("to_s"), double(to.ms) / 1000.0},
                            {QStringLiteral("changes"), QJsonArray::fromStringList(changes)}})
                .toJson(QJsonDocument::Indented));
    } else {
        ctx.out << CtlRunner::tr("from %1 to %2, changes: %3")
                       .arg(log.momentText(from.ms), log.momentText(to.ms))
                       .arg(changes.size())
                << Qt::endl;
        for (const QString &line : changes)
            ctx.out << QStringLiteral("  ") << line << Qt::endl;
    }
    ctx.finish(CtlRunner::Ok);
}

void runBundle(CtlContext &ctx)
{
    if (ctx.options.arguments.size() != 1) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("bundle needs the name of the zip file to write"));
        return;
    }
    if (!ctx.options.profile.isEmpty() && !QFileInfo::exists(ctx.options.profile)) {
        ctx.fail(CtlRunner::UsageError,
                 CtlRunner::tr("--profile: %1 does not exist").arg(ctx.options.profile));
        return;
    }
    BundleInput input;
    input.logDirectory = SupportBundle::defaultLogDirectory();
    input.days = ctx.options.days;
    input.profilePath = ctx.options.profile;
    input.settingsFiles = SupportBundle::defaultSettingsFiles();
    // The machine report: the controllers given (--port, --tcp or --sim, with --id), read now,
    // and the profile's sheet.
    QList<ReportInput> sheets;
    if (!ctx.options.profile.isEmpty()) {
        QStringList problems;
        if (const auto sheet = ReportInput::fromProfileFile(ctx.map, ctx.options.profile,
                                                            ctx.options.language, &problems)) {
            sheets << *sheet;
        } else {
            for (const QString &e : std::as_const(problems))
                ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
            ctx.err << QStringLiteral("stepcomctl: ")
                    << CtlRunner::tr(
                           "the profile goes into the bundle as it is, but not into the report")
                    << Qt::endl;
            input.noReport = QStringLiteral("the profile %1 could not be read (%2)")
                                 .arg(QFileInfo(ctx.options.profile).fileName(),
                                      problems.join(QStringLiteral("; ")));
        }
    }
    if (ctx.options.target == CtlOptions::Target::None) {
        writeBundle(ctx, input, sheets);
        return;
    }
    ctx.connectThen([&ctx, input, sheets] {
        readMachine(
            ctx,
            CtlRunner::tr("no bundle: not every controller could be read completely (without "
                          "--port, --tcp or --sim the bundle has no controller in its report)"),
            [&ctx, input, sheets](const QList<ReportInput> &read) {
                writeBundle(ctx, input, read + sheets);
            });
    });
}

} // namespace stepcom
