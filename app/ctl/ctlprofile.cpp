// stepcomctl dump, diff, apply and report: CtlRunner's profile commands (docs/profiles.md).
#include "ctlrunner.h"

#include "consolereader.h"

#include "profile/profilediff.h"
#include "profile/profilefile.h"
#include "report/commissioningreport.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace stepcom {

bool CtlRunner::loadProfileArgument(const QString &command, Profile *out)
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("%1 needs exactly one profile file").arg(command));
        return false;
    }
    const ProfileParseResult r = ProfileFile::load(m_options.arguments.first(), m_map);
    if (!r.ok()) {
        for (const QString &e : r.errors)
            m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        m_err << QStringLiteral("stepcomctl: ") << tr("nothing was written") << Qt::endl;
        finish(UsageError);
        return false;
    }
    *out = *r.profile;
    return true;
}

void CtlRunner::runDump()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("dump needs exactly one file to write the profile to"));
        return;
    }
    const QString path = m_options.arguments.first();
    connectThen([this, path] {
        m_session->read(Profile::profileParameters(m_map, true), [this,
                                                                  path](const ReadOutcome &r) {
            if (!r.ok) {
                for (const QString &e : r.errors)
                    m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                fail(DeviceError, tr("nothing was saved: the controller could "
                                     "not be read completely"));
                return;
            }
            Profile profile = Profile::fromValues(m_map, r.values, m_options.includeLink);
            profile.name =
                m_options.name.isEmpty() ? QFileInfo(path).completeBaseName() : m_options.name;
            profile.notes = m_options.notes;
            profile.deviceId = m_session->settings().deviceId;
            if (const QString e = ProfileFile::save(path, profile, m_map); !e.isEmpty()) {
                fail(UsageError, e);
                return;
            }
            m_out << tr("saved %n parameter(s) of %1 to %2", nullptr, int(profile.values.size()))
                         .arg(m_session->settings().describe(), path)
                  << Qt::endl;
            finish(Ok);
        });
    });
}

void CtlRunner::runDiff()
{
    Profile profile;
    if (!loadProfileArgument(QStringLiteral("diff"), &profile))
        return;
    m_linkError = 3; // 1 means "different" here
    connectThen([this, profile] {
        m_session->read(
            Profile::profileParameters(m_map, true), [this, profile](const ReadOutcome &r) {
                if (!r.ok) {
                    for (const QString &e : r.errors)
                        m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    finish(m_linkError);
                    return;
                }
                const auto diffs =
                    ProfileDiff::differences(ProfileDiff::compare(m_map, profile, r.values));
                for (const ProfileDifference &d : diffs)
                    m_out << ProfileDiff::describe(d) << Qt::endl;
                if (diffs.isEmpty())
                    m_out << tr("the controller holds every value of the profile") << Qt::endl;
                else
                    m_out << tr("%n value(s) differ (controller -> profile)", nullptr,
                                int(diffs.size()))
                          << Qt::endl;
                finish(diffs.isEmpty() ? 0 : 1);
            });
    });
}

void CtlRunner::runApply()
{
    Profile profile;
    if (!loadProfileArgument(QStringLiteral("apply"), &profile))
        return;
    if (m_options.includeLink && m_options.target == CtlOptions::Target::Tcp &&
        profile.values.contains(QStringLiteral("device.baud"))) {
        m_err << QStringLiteral("stepcomctl: ")
              << tr("note: device.baud changes the controller's serial side only") << Qt::endl;
    }
    connectThen([this, profile] {
        m_session->read(
            Profile::profileParameters(m_map, true), [this, profile](const ReadOutcome &r) {
                if (!r.ok) {
                    for (const QString &e : r.errors)
                        m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                    fail(DeviceError, tr("nothing was written"));
                    return;
                }
                QStringList keys;
                for (const ProfileDifference &d :
                     ProfileDiff::differences(ProfileDiff::compare(m_map, profile, r.values))) {
                    if (d.linkSetting && !m_options.includeLink) {
                        m_out << tr("not applied (needs --include-link): %1")
                                     .arg(ProfileDiff::describe(d))
                              << Qt::endl;
                        continue;
                    }
                    keys << d.parameter->key;
                    m_out << tr("will write %1").arg(ProfileDiff::describe(d)) << Qt::endl;
                }
                QStringList errors;
                const QList<ParameterWrite> writes =
                    ProfileDiff::writesFor(m_map, profile, keys, m_options.includeLink, &errors);
                if (!errors.isEmpty()) {
                    fail(UsageError, errors.join(QLatin1String("; ")));
                    return;
                }
                if (writes.isEmpty()) {
                    m_out << tr("the controller already holds the profile's values") << Qt::endl;
                    if (m_options.saveToFlash)
                        saveToFlashThenFinish();
                    else
                        finish(Ok);
                    return;
                }
                confirmThenApply(writes);
            });
    });
}

void CtlRunner::confirmThenApply(const QList<ParameterWrite> &writes)
{
    if (m_options.yes) {
        applyWrites(writes);
        return;
    }
    m_out << tr("Write these %n value(s) to the controller? [y/N] ", nullptr, int(writes.size()))
          << Qt::flush;
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
    m_session->write(writes, [this, writes](const WriteOutcome &w) {
        for (const ParameterWrite &pw : writes) {
            const bool verified =
                w.written.contains(pw.parameter->key) &&
                std::none_of(w.mismatches.cbegin(), w.mismatches.cend(),
                             [&](const WriteMismatch &m) { return m.key == pw.parameter->key; });
            if (verified)
                m_out << pw.parameter->key << QStringLiteral(" = ")
                      << valueText(*pw.parameter, pw.raw) << QStringLiteral("  ")
                      << tr("(written, verified)") << Qt::endl;
        }
        for (const QString &e : w.errors)
            m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
        if (!w.notWritten.isEmpty())
            m_err << QStringLiteral("stepcomctl: ")
                  << tr("not written: %1").arg(w.notWritten.join(QLatin1String(", "))) << Qt::endl;
        if (!w.ok) {
            finish(DeviceError);
            return;
        }
        if (m_options.saveToFlash)
            saveToFlashThenFinish();
        else {
            m_out << tr("not saved to flash: the controller forgets these values at power-off "
                        "(use --save-to-flash)")
                  << Qt::endl;
            finish(Ok);
        }
    });
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
    // The report speaks the program's language (--lang or the environment), installed in main().
    connectThen([this, path] {
        m_session->readAll([this, path](const ReadOutcome &r) {
            if (!r.ok) {
                for (const QString &e : r.errors)
                    m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                fail(DeviceError, tr("no report: the controller could not be read completely"));
                return;
            }
            ReportInput input;
            input.map = m_map;
            input.values = r.values;
            input.link = m_session->settings().describe();
            input.deviceId = m_session->settings().deviceId;
            input.title = m_options.name;
            input.notes = m_options.notes;
            input.date = QDateTime::currentDateTime();
            input.locale = m_options.language;
            if (const QString e = CommissioningReport(input).write(path); !e.isEmpty()) {
                fail(UsageError, e);
                return;
            }
            m_out << tr("report written to %1").arg(path) << Qt::endl;
            finish(Ok);
        });
    });
}

} // namespace stepcom
