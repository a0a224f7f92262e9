// stepcomctl dump, diff, apply and report: CtlRunner's profile commands (docs/profiles.md).
#include "../ctllinkadvice.h"
#include "../ctlrunner.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include "consolereader.h"

#include "profile/busdump.h"
#include "profile/profileapply.h"
#include "profile/profilecomparison.h"
#include "profile/profilediff.h"
#include "profile/profilefile.h"
#include "report/commissioningreport.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QLocale>

namespace stepcom {

bool CtlRunner::loadProfile(const QString &path, Profile *out)
{
    // A profile of another map (a firmware variant, a model with more axes) opens with what
    // this map knows; the commands list the rest before they act.
    const ProfileParseResult r = ProfileFile::load(path, m_map, ProfileFile::OtherMaps::Accept);
    if (!r.ok()) {
        for (const QString &e : condensed(r.errors))
            m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        return false;
    }
    *out = *r.profile;
    return true;
}

bool CtlRunner::loadProfileArgument(const QString &command, Profile *out)
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("%1 needs exactly one profile file").arg(command));
        return false;
    }
    if (!loadProfile(m_options.arguments.first(), out)) {
        m_err << QStringLiteral("stepcomctl: ") << tr("nothing was written") << Qt::endl;
        finish(UsageError);
        return false;
    }
    return true;
}

void CtlRunner::printLeftOut(const Profile &profile, const QString &heading)
{
    const ProfileVariance &v = profile.variance;
    if (!v.isVariant() && v.isEmpty())
        return;
    if (v.isVariant())
        m_out << v.describeMaps() << Qt::endl;
    const QStringList lines = v.describe(m_map, m_options.language);
    if (lines.isEmpty())
        return;
    m_out << heading << Qt::endl;
    for (const QString &line : lines)
        m_out << QStringLiteral("  ") << line << Qt::endl;
}

int CtlRunner::noteUnsupported(const ReadOutcome &read, Profile *profile)
{
    if (read.unsupported.isEmpty())
        return 0;
    QStringList keys = read.unsupported;
    keys.sort();
    m_out
        << tr("not supported by this controller (left out): %1").arg(keys.join(QLatin1String(", ")))
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

void CtlRunner::runDump()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("dump needs exactly one file to write the profile to"));
        return;
    }
    const QString path = m_options.arguments.first();
    if (path.endsWith(QLatin1Char('/')) || QFileInfo(path).isDir()) {
        if (const QString problem = BusDump::checkDirectory(path); !problem.isEmpty()) {
            fail(UsageError, tr("nothing was saved: %1").arg(problem));
            return;
        }
        connectThen([this, path] {
            m_session->parameters()->read(
                Profile::profileParameters(m_map, true), [this, path](const ReadOutcome &r) {
                    if (!r.ok) {
                        for (const QString &e : condensed(r.errors))
                            m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                        fail(DeviceError, tr("nothing was saved: the controller "
                                             "could not be read completely"));
                        return;
                    }
                    dumpIntoFolder(path, r.values);
                });
        });
        return;
    }
    connectThen([this, path] {
        m_session->parameters()->read(
            Profile::profileParameters(m_map, true), [this, path](const ReadOutcome &r) {
                if (!r.ok) {
                    for (const QString &e : condensed(r.errors))
                        m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    fail(DeviceError, tr("nothing was saved: the controller could "
                                         "not be read completely"));
                    return;
                }
                noteUnsupported(r);
                Profile profile = Profile::fromValues(m_map, r.values, m_options.includeLink);
                profile.unsupported = r.unsupported;
                profile.unsupported.sort();
                profile.name =
                    m_options.name.isEmpty() ? QFileInfo(path).completeBaseName() : m_options.name;
                profile.notes = m_options.notes;
                profile.deviceId = m_session->connection()->settings().deviceId;
                profile.fromSimulator = m_session->connection()->isSimulator();
                if (const QString e = ProfileFile::save(path, profile, m_map); !e.isEmpty()) {
                    fail(DeviceError, e); // not done: the file could not be written
                    return;
                }
                m_result = QJsonObject{{QStringLiteral("file"), path},
                                       {QStringLiteral("parameters"), int(profile.values.size())}};
                m_out << tr("saved %n parameter(s) of %1 to %2", nullptr,
                            int(profile.values.size()))
                             .arg(m_session->connection()->settings().describe(), path)
                      << Qt::endl;
                finish(Ok);
            });
    });
}

void CtlRunner::runDiff()
{
    if (m_options.arguments.size() == 2) {
        runDiffFiles(); // two files: no controller needed
        return;
    }
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("diff needs one profile file (compared with the controller) or two "
                            "(compared with each other)"));
        return;
    }
    Profile profile;
    if (!loadProfileArgument(QStringLiteral("diff"), &profile))
        return;
    m_linkError = LinkError; // 1 means "different" here
    connectThen([this, profile] {
        m_session->parameters()->read(
            Profile::profileParameters(m_map, true), [this, profile](const ReadOutcome &r) {
                if (!r.ok) {
                    for (const QString &e : condensed(r.errors))
                        m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    finish(m_linkError);
                    return;
                }
                Profile compared = profile;
                const int unsupported = noteUnsupported(r, &compared);
                const auto diffs =
                    ProfileDiff::differences(ProfileDiff::compare(m_map, compared, r.values));
                QJsonArray rows;
                for (const ProfileDifference &d : diffs) {
                    m_out << ProfileDiff::describe(d) << Qt::endl;
                    const auto value = [&d](const std::optional<qint64> &raw) {
                        return raw ? jsonValue(*d.parameter, *raw) : QJsonValue();
                    };
                    rows.append(QJsonObject{{QStringLiteral("key"), d.parameter->key},
                                            {QStringLiteral("controller"), value(d.device)},
                                            {QStringLiteral("profile"), value(d.profile)}});
                }
                m_result.insert(QStringLiteral("differences"), rows);
                printLeftOut(compared, tr("left out of the comparison:"));
                const ProfileVariance &v = compared.variance;
                const int leftOut =
                    int(v.unknown.size() + v.rejected.size() + v.missing.size()) + unsupported;
                if (diffs.isEmpty() && leftOut == 0)
                    m_out << tr("the controller holds every value of the profile") << Qt::endl;
                else if (diffs.isEmpty())
                    m_out << tr("the controller holds every value both maps have; %n left out",
                                nullptr, leftOut)
                          << Qt::endl;
                else
                    m_out << tr("%n value(s) differ (controller -> profile)", nullptr,
                                int(diffs.size()))
                          << Qt::endl;
                m_result.insert(QStringLiteral("left_out"), leftOut);
                m_result.insert(QStringLiteral("same"), diffs.isEmpty() && leftOut == 0);
                // A comparison that had to leave values out is not "the same".
                finish(diffs.isEmpty() && leftOut == 0 ? 0 : 1);
            });
    });
}

void CtlRunner::runDiffFiles()
{
    const QString pathA = m_options.arguments.at(0);
    const QString pathB = m_options.arguments.at(1);
    Profile a;
    Profile b;
    const bool okA = loadProfile(pathA, &a);
    const bool okB = loadProfile(pathB, &b); // both files' problems, at once
    if (!okA || !okB) {
        fail(UsageError, tr("nothing was compared"));
        return;
    }
    const QString nameA = QFileInfo(pathA).fileName();
    const QString nameB = QFileInfo(pathB).fileName();
    auto mapOf = [this](const Profile &p) {
        return p.variance.isVariant() ? p.variance.fileMap : m_map.identity();
    };
    m_out << tr("A = %1: \"%2\", register map %3").arg(nameA, a.name, mapOf(a)) << Qt::endl;
    m_out << tr("B = %1: \"%2\", register map %3").arg(nameB, b.name, mapOf(b)) << Qt::endl;
    const ProfileComparison c = ProfileComparison::compare(m_map, a, b);
    auto value = [this](const ProfileDifference &row, bool left) {
        return valueText(*row.parameter, left ? *row.device : *row.profile);
    };
    const auto differing = c.differing();
    if (!differing.isEmpty()) {
        m_out << tr("differ (A -> B):") << Qt::endl;
        for (const ProfileDifference &d : differing)
            m_out << QStringLiteral("  %1: %2 -> %3")
                         .arg(d.parameter->key, value(d, true), value(d, false))
                  << Qt::endl;
    }
    const auto onlyA = c.onlyInA();
    const auto onlyB = c.onlyInB();
    for (const auto &[rows, heading, left] :
         {std::tuple{onlyA, tr("only in A (%1):").arg(nameA), true},
          std::tuple{onlyB, tr("only in B (%1):").arg(nameB), false}}) {
        if (rows.isEmpty())
            continue;
        m_out << heading << Qt::endl;
        for (const ProfileDifference &d : rows)
            m_out << QStringLiteral("  %1 = %2").arg(d.parameter->key, value(d, left)) << Qt::endl;
    }
    const auto foreign = c.foreignDiffering();
    if (!foreign.isEmpty()) {
        m_out << tr("not settings of register map %1, or out of its range (as the files hold "
                    "them, A -> B):")
                     .arg(m_map.identity())
              << Qt::endl;
        auto number = [](const std::optional<double> &v) {
            return v ? QString::number(*v, 'g', QLocale::FloatingPointShortest) : tr("(none)");
        };
        for (const ProfileForeignRow &f : foreign)
            m_out << QStringLiteral("  %1: %2 -> %3  (%4)")
                         .arg(f.key, number(f.a), number(f.b), f.reason)
                  << Qt::endl;
    }
    QJsonArray rows;
    for (const ProfileDifference &d : differing)
        rows.append(QJsonObject{
            {QStringLiteral("key"), d.parameter->key},
            {QStringLiteral("a"), d.device ? jsonValue(*d.parameter, *d.device) : QJsonValue()},
            {QStringLiteral("b"), d.profile ? jsonValue(*d.parameter, *d.profile) : QJsonValue()}});
    m_result = QJsonObject{{QStringLiteral("same"), c.identical()},
                           {QStringLiteral("differences"), rows},
                           {QStringLiteral("only_in_a"), int(onlyA.size())},
                           {QStringLiteral("only_in_b"), int(onlyB.size())},
                           {QStringLiteral("outside_map"), int(foreign.size())}};
    if (c.identical()) {
        m_out << tr("the two profiles hold the same values") << Qt::endl;
        finish(0);
        return;
    }
    m_out << tr("%1 differ, %2 only in A, %3 only in B, %4 outside this map")
                 .arg(differing.size())
                 .arg(onlyA.size())
                 .arg(onlyB.size())
                 .arg(foreign.size())
          << Qt::endl;
    finish(1);
}

void CtlRunner::runApply()
{
    Profile profile;
    if (!loadProfileArgument(QStringLiteral("apply"), &profile))
        return;
    if (profile.values.isEmpty()) { // another map's profile with nothing this map can take
        printLeftOut(profile, tr("not applied:"));
        fail(UsageError, tr("the profile holds no setting of this map: nothing to apply"));
        return;
    }
    if (m_options.includeLink && m_options.target == CtlOptions::Target::Tcp &&
        profile.values.contains(QStringLiteral("device.baud"))) {
        m_err << QStringLiteral("stepcomctl: ")
              << tr("note: device.baud changes the controller's serial side only") << Qt::endl;
    }
    connectThen([this, profile] {
        // ProfileApply reads, compares, backs up (the session's risk guard), writes, verifies.
        delete m_applier;
        m_applier = new ProfileApply(m_session, profile, 0, this);
        m_applier->setIncludeLink(m_options.includeLink);
        m_applier->setSaveToFlash(m_options.saveToFlash);
        connect(m_applier, &ProfileApply::finished, this, &CtlRunner::reportApplied);
        connect(m_applier, &ProfileApply::compared, this, [this, profile](bool ok) {
            if (!ok) {
                for (const QString &e : condensed(m_applier->readErrors()))
                    m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                fail(DeviceError, tr("nothing was written"));
                return;
            }
            ReadOutcome r;
            r.values = m_applier->before();
            r.unsupported = m_applier->unsupported();
            Profile applied = profile;
            noteUnsupported(r, &applied); // never written: the controller lacks them
            QStringList keys;
            for (const ProfileDifference &d :
                 ProfileDiff::differences(ProfileDiff::compare(m_map, applied, r.values))) {
                if (d.linkSetting && !m_options.includeLink) {
                    m_out << tr("not applied (needs --include-link): %1")
                                 .arg(ProfileDiff::describe(d))
                          << Qt::endl;
                    continue;
                }
                keys << d.parameter->key;
                m_out << tr("will write %1").arg(ProfileDiff::describe(d)) << Qt::endl;
            }
            m_result.insert(QStringLiteral("to_write"), QJsonArray::fromStringList(keys));
            // Said before asking, and with --yes too: what of the profile is not applied.
            printLeftOut(applied, tr("not applied:"));
            QStringList errors;
            const QList<ParameterWrite> writes =
                ProfileDiff::writesFor(m_map, applied, keys, m_options.includeLink, &errors);
            if (!errors.isEmpty()) {
                fail(UsageError, errors.join(QLatin1String("; ")));
                return;
            }
            if (writes.isEmpty()) {
                m_out << (profile.variance.isVariant()
                              ? tr("the controller already holds every value both maps have")
                              : tr("the controller already holds the profile's values"))
                      << Qt::endl;
                if (m_options.saveToFlash)
                    applyWrites({}); // nothing to write: only the save to flash
                else
                    finish(Ok);
                return;
            }
            // What the window's write dialog asks, said before the question (and with --yes).
            for (const QString &q : m_applier->questions(keys))
                m_out << tr("check: %1").arg(q) << Qt::endl;
            confirmThenApply(writes);
        });
        m_applier->compare();
    });
}

void CtlRunner::confirmThenApply(const QList<ParameterWrite> &writes)
{
    if (m_options.yes) {
        applyWrites(writes);
        return;
    }
    if (isMulti() || isEnveloped()) {
        // With several ids the output is keyed by id at the end; what the question is about
        // must be seen before it is answered (on standard error with --json, which stays JSON).
        m_out.flush();
        QTextStream console(m_options.json ? stderr : stdout);
        if (isMulti())
            console << tr("== device id %1 ==").arg(m_options.ids.at(m_idIndex)) << Qt::endl;
        console << m_buffer
                << (isMulti() ? tr("Write these %n value(s) to id %1? [y/N] ", nullptr,
                                   int(writes.size()))
                                    .arg(m_options.ids.at(m_idIndex))
                              : tr("Write these %n value(s) to the controller? [y/N] ", nullptr,
                                   int(writes.size())))
                << Qt::flush;
        if (isMulti()) { // shown now; one id's messages stay in its JSON object
            m_buffer.clear();
            m_out.setString(&m_buffer);
        }
    } else {
        m_out << tr("Write these %n value(s) to the controller? [y/N] ", nullptr,
                    int(writes.size()))
              << Qt::flush;
    }
    // Standard input is read through the event loop, so the link stays served meanwhile.
    auto *console = new ConsoleReader(this);
    auto answered = std::make_shared<bool>(false);
    connect(console, &ConsoleReader::lineRead, this,
            [this, writes, console, answered](const QString &line) {
                if (*answered)
                    return;
                *answered = true;
                console->deleteLater();
                const QString a = line.trimmed().toLower();
                if (a == QLatin1String("y") || a == QLatin1String("yes")) {
                    applyWrites(writes);
                    return;
                }
                fail(UsageError, tr("not confirmed: nothing was written"));
            });
    connect(console, &ConsoleReader::endOfInput, this, [this, console, answered] {
        if (*answered)
            return;
        *answered = true;
        console->deleteLater();
        fail(UsageError, tr("no answer on standard input: nothing was written (use --yes)"));
    });
}

void CtlRunner::applyWrites(const QList<ParameterWrite> &writes)
{
    QStringList keys;
    for (const ParameterWrite &w : writes)
        keys << w.parameter->key;
    m_appliedWrites = writes;
    m_applier->apply(keys);
}

void CtlRunner::reportApplied(const ProfileApplyResult &result)
{
    QJsonObject written;
    for (const AppliedKey &k : result.keys) {
        if (k.state != AppliedKey::State::Verified)
            continue;
        written.insert(k.key, jsonValue(*k.parameter, k.wanted));
        m_out << k.key << QStringLiteral(" = ") << valueText(*k.parameter, k.wanted)
              << QStringLiteral("  ") << tr("(written, verified)") << Qt::endl;
    }
    const QStringList notWritten =
        result.keysIn(AppliedKey::State::NotWritten) + result.keysIn(AppliedKey::State::Refused);
    if (!result.keys.isEmpty() || !written.isEmpty()) {
        m_result.insert(QStringLiteral("written"), written);
        m_result.insert(QStringLiteral("not_written"), QJsonArray::fromStringList(notWritten));
    }
    for (const QString &e : result.writeErrors)
        m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
    // Past what the write said: each key not verified, and why (not known is never guessed).
    for (const AppliedKey &k : result.keys) {
        if (k.state == AppliedKey::State::Refused || k.state == AppliedKey::State::NotKnown ||
            k.state == AppliedKey::State::Lost)
            m_err << QStringLiteral("stepcomctl: ") << ProfileApplyResult::describe(k) << Qt::endl;
    }
    if (!notWritten.isEmpty())
        m_err << QStringLiteral("stepcomctl: ")
              << tr("not written: %1").arg(notWritten.join(QLatin1String(", "))) << Qt::endl;
    const bool allHeld = std::all_of(result.keys.cbegin(), result.keys.cend(), [](const auto &k) {
        return k.state == AppliedKey::State::Verified || k.state == AppliedKey::State::Unchanged;
    });
    if (result.end != ProfileApplyResult::End::Done || !allHeld) {
        if (result.error.isEmpty())
            finish(DeviceError);
        else
            fail(DeviceError, result.error);
        return;
    }
    // --include-link: how the next command reaches a new id or baud (the flash is said below).
    for (const QString &note : CtlLinkAdvice::notes(m_options, m_appliedWrites, true))
        m_out << note << Qt::endl;
    if (result.flashAsked) {
        if (result.savedToFlash != true) {
            fail(DeviceError, result.flashError);
            return;
        }
        m_out << tr("saved to flash") << Qt::endl;
        finish(Ok);
        return;
    }
    m_out << tr("not saved to flash: the controller forgets these values at power-off "
                "(use --save-to-flash)")
          << Qt::endl;
    finish(Ok);
}

void CtlRunner::saveToFlashThenFinish()
{
    const Parameter *save = m_map.find(QStringLiteral("save_to_flash"));
    if (!save) {
        fail(DeviceError, tr("this map has no save_to_flash command"));
        return;
    }
    m_session->command(*save, [this](const Result &r) {
        if (!r.ok) {
            fail(DeviceError, r.errorText);
            return;
        }
        m_out << tr("saved to flash") << Qt::endl;
        finish(Ok);
    });
}

void CtlRunner::runReport()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("report needs exactly one file (.pdf or .html)"));
        return;
    }
    const QString path = m_options.arguments.first();
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("pdf") && suffix != QLatin1String("html") &&
        suffix != QLatin1String("htm")) {
        fail(UsageError, tr("%1: the report is written as .pdf or .html").arg(path));
        return;
    }
    if (!m_options.from.isEmpty()) {
        runReportFromFile(path); // no controller
        return;
    }
    // The report speaks the program's language (--lang or the environment), installed in main().
    connectThen([this, path] {
        m_session->parameters()->readAll([this, path](const ReadOutcome &r) {
            if (!r.ok) {
                for (const QString &e : condensed(r.errors))
                    m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                fail(DeviceError, tr("no report: the controller could not be read completely"));
                return;
            }
            noteUnsupported(r);
            ReportInput input;
            input.map = m_map;
            input.values = r.values;
            input.unsupported = r.unsupported;
            input.link = m_session->connection()->settings().describe();
            input.simulator = m_session->connection()->isSimulator();
            input.line =
                m_session->connection()->linkStats().lineText(m_session->line()->deviceInView());
            input.deviceId = m_session->connection()->settings().deviceId;
            input.title = m_options.name;
            input.notes = m_options.notes;
            input.date = QDateTime::currentDateTime();
            input.lastRead = input.date; // a one-shot session: the flash state is not known
            input.locale = m_options.language;
            if (const QString e = CommissioningReport(input).write(path); !e.isEmpty()) {
                fail(UsageError, e);
                return;
            }
            m_result = QJsonObject{{QStringLiteral("file"), path}};
            m_out << tr("report written to %1").arg(path) << Qt::endl;
            finish(Ok);
        });
    });
}

void CtlRunner::runReportFromFile(const QString &path)
{
    Profile profile;
    if (!loadProfile(m_options.from, &profile)) {
        fail(UsageError, tr("no report: %1 is not a profile StepCom can read").arg(m_options.from));
        return;
    }
    ReportInput input =
        ReportInput::fromProfile(m_map, profile, m_options.from, m_options.language);
    if (!input.checklistErrors.isEmpty()) { // a certificate never silently loses its results
        for (const QString &e : std::as_const(input.checklistErrors))
            m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        fail(UsageError, tr("no report: the checklist beside the profile cannot be read"));
        return;
    }
    if (!m_options.name.isEmpty())
        input.title = m_options.name;
    if (!m_options.notes.isEmpty())
        input.notes = m_options.notes;
    if (const QString e = CommissioningReport(input).write(path); !e.isEmpty()) {
        fail(UsageError, e);
        return;
    }
    printLeftOut(profile, tr("not in the report:"));
    m_result =
        QJsonObject{{QStringLiteral("file"), path}, {QStringLiteral("from"), m_options.from}};
    m_out << tr("report written to %1, made from the profile file %2 (no controller was read)")
                 .arg(path, m_options.from)
          << Qt::endl;
    if (input.checklist)
        m_out << tr("with the commissioning checklist %1: %2")
                     .arg(input.checklistFile, input.checklist->summary())
              << Qt::endl;
    finish(Ok);
}

} // namespace stepcom
