// stepcomctl replay and bundle, and --log FILE: a session log written by this run,
// replayed without a controller, and the support bundle a technician sends.
#include "../ctlrunner.h"

#include "report/machinereport.h"
#include "session/sessionlog.h"
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

} // namespace

void CtlRunner::startLog()
{
    if (m_options.logFile.isEmpty())
        return;
    SessionLog *log = m_session->log();
    log->setFile(m_options.logFile);
    connect(log, &SessionLog::failed, this, [this](const QString &reason) {
        m_err << QStringLiteral("stepcomctl: ") << reason << Qt::endl;
    });
}

void CtlRunner::runReplay()
{
    const int modes =
        int(m_options.events) + int(!m_options.at.isEmpty()) + int(!m_options.diffFrom.isEmpty());
    const int wanted = m_options.diffFrom.isEmpty() ? 1 : 2; // --diff T1 T2: T2 is an argument
    if (modes != 1 || m_options.arguments.size() != wanted) {
        fail(UsageError, tr("replay needs a log and one of --events, --at TIME or --diff T1 T2"));
        return;
    }
    QString path = m_options.arguments.first();
    // A support bundle: one of its logs, copied out for the replay's seeks.
    QTemporaryDir temporary;
    QFile probe(path);
    if (probe.open(QIODevice::ReadOnly) && probe.read(4) == QByteArrayLiteral("PK\x03\x04")) {
        QString error;
        const QStringList logs = SupportBundle::logs(path, &error);
        if (logs.isEmpty()) {
            fail(UsageError, error);
            return;
        }
        QString entry = logs.last();
        if (!m_options.entry.isEmpty()) {
            const auto named = std::find_if(logs.cbegin(), logs.cend(), [this](const QString &l) {
                return l == m_options.entry || QFileInfo(l).fileName() == m_options.entry;
            });
            if (named == logs.cend()) {
                fail(UsageError, tr("--entry: the bundle holds no log %1 (it holds: %2)")
                                     .arg(m_options.entry, logs.join(QStringLiteral(", "))));
                return;
            }
            entry = *named;
        }
        m_err << QStringLiteral("stepcomctl: ")
              << tr("replaying %1 (logs in the bundle: %2; --entry NAME for another)")
                     .arg(entry)
                     .arg(logs.size())
              << Qt::endl;
        path = SupportBundle::extract(path, entry, temporary.path(), &error);
        if (path.isEmpty()) {
            fail(UsageError, error);
            return;
        }
    }
    ReplayLog log(m_map);
    if (!log.open(path)) {
        fail(UsageError, log.errorString());
        return;
    }
    for (const QString &w : log.warnings())
        m_err << QStringLiteral("stepcomctl: ") << tr("warning: %1").arg(w) << Qt::endl;

    if (m_options.events) {
        QJsonArray array;
        for (const ReplayEvent &e : log.events()) {
            if (m_options.json) {
                array.append(QJsonObject{{QStringLiteral("t_s"), double(e.ms) / 1000.0},
                                         {QStringLiteral("device"), e.device},
                                         {QStringLiteral("kind"), ReplayEvent::kindName(e.kind)},
                                         {QStringLiteral("text"), e.text},
                                         {QStringLiteral("line"), double(e.line)}});
                continue;
            }
            m_out << QStringLiteral("%1  %2  %3  %4")
                         .arg(log.momentText(e.ms), -26)
                         .arg(deviceText(e.device), -6)
                         .arg(ReplayEvent::kindName(e.kind), -11)
                         .arg(e.text)
                  << Qt::endl;
        }
        if (m_options.json)
            m_out << QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Indented));
        finish(Ok);
        return;
    }
    QString error;
    const auto first =
        log.parseTime(m_options.diffFrom.isEmpty() ? m_options.at : m_options.diffFrom, &error);
    if (!first) {
        fail(UsageError, error);
        return;
    }
    if (!m_options.at.isEmpty()) {
        const ReplayState state = log.stateAt(*first);
        if (m_options.json) {
            QJsonObject o = state.toJson(m_map);
            o.insert(QStringLiteral("clock"), log.momentText(state.ms));
            m_out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            finish(Ok);
            return;
        }
        m_out << tr("at %1, link %2")
                     .arg(log.momentText(state.ms), state.linkUp ? tr("up") : tr("down"))
              << Qt::endl;
        for (auto it = state.devices.cbegin(); it != state.devices.cend(); ++it) {
            const QHash<QString, qint64> values = it->values(m_map);
            const QHash<QString, qint64> written = it->writtenValues(m_map);
            m_out << QStringLiteral("id %1: ").arg(it.key())
                  << (it->answering ? tr("answering") : tr("not answering"));
            if (!it->lastError.isEmpty())
                m_out << QStringLiteral("; ")
                      << tr("last error at %1: %2")
                             .arg(log.momentText(it->lastErrorMs), it->lastError);
            m_out << Qt::endl;
            for (const Parameter *p : m_map.holdings()) {
                if (values.contains(p->key))
                    m_out << QStringLiteral("  %1 = %2%3")
                                 .arg(p->key, valueText(*p, values.value(p->key)),
                                      written.contains(p->key)
                                          ? QStringLiteral("  ") +
                                                tr("(last written: %1)")
                                                    .arg(valueText(*p, written.value(p->key)))
                                          : QString())
                          << Qt::endl;
            }
        }
        finish(Ok);
        return;
    }
    const auto second = log.parseTime(m_options.arguments.at(1), &error);
    if (!second) {
        fail(UsageError, error);
        return;
    }
    const ReplayState from = log.stateAt(*first);
    const ReplayState to = log.stateAt(*second);
    const QStringList changes = to.diff(from, m_map);
    if (m_options.json) {
        m_out << QString::fromUtf8(
            QJsonDocument(
                QJsonObject{{QStringLiteral("from_s"), double(from.ms) / 1000.0},
                            {QStringLiteral("to_s"), double(to.ms) / 1000.0},
                            {QStringLiteral("changes"), QJsonArray::fromStringList(changes)}})
                .toJson(QJsonDocument::Indented));
    } else {
        m_out << tr("from %1 to %2, changes: %3")
                     .arg(log.momentText(from.ms), log.momentText(to.ms))
                     .arg(changes.size())
              << Qt::endl;
        for (const QString &line : changes)
            m_out << QStringLiteral("  ") << line << Qt::endl;
    }
    finish(Ok);
}

void CtlRunner::runBundle()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("bundle needs the name of the zip file to write"));
        return;
    }
    if (!m_options.profile.isEmpty() && !QFileInfo::exists(m_options.profile)) {
        fail(UsageError, tr("--profile: %1 does not exist").arg(m_options.profile));
        return;
    }
    BundleInput input;
    input.logDirectory = SupportBundle::defaultLogDirectory();
    input.days = m_options.days;
    input.profilePath = m_options.profile;
    input.settingsFiles = SupportBundle::defaultSettingsFiles();
    // The machine report: the controllers given (--port, --tcp or --sim, with --id), read now,
    // and the profile's sheet.
    QList<ReportInput> sheets;
    if (!m_options.profile.isEmpty()) {
        QStringList problems;
        if (const auto sheet = ReportInput::fromProfileFile(m_map, m_options.profile,
                                                            m_options.language, &problems)) {
            sheets << *sheet;
        } else {
            for (const QString &e : std::as_const(problems))
                m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
            m_err << QStringLiteral("stepcomctl: ")
                  << tr("the profile goes into the bundle as it is, but not into the report")
                  << Qt::endl;
            input.noReport = QStringLiteral("the profile %1 could not be read (%2)")
                                 .arg(QFileInfo(m_options.profile).fileName(),
                                      problems.join(QStringLiteral("; ")));
        }
    }
    if (m_options.target == CtlOptions::Target::None) {
        writeBundle(input, sheets);
        return;
    }
    connectThen([this, input, sheets] {
        readMachine(tr("no bundle: not every controller could be read completely (without "
                       "--port, --tcp or --sim the bundle has no controller in its report)"),
                    [this, input, sheets](const QList<ReportInput> &read) {
                        writeBundle(input, read + sheets);
                    });
    });
}

void CtlRunner::writeBundle(BundleInput input, const QList<ReportInput> &sheets)
{
    if (!sheets.isEmpty()) {
        const MachineReport report(sheets, m_options.name, m_options.notes, m_options.language);
        input.reportHtml = report.selfContainedHtml().toUtf8();
        input.reportSheets = report.sheetLines();
    } else if (input.noReport.isEmpty()) {
        input.noReport = QStringLiteral("no controller was read (--port, --tcp or --sim) and no "
                                        "profile was given (--profile)");
    }
    QStringList contents;
    QString error;
    const QString out = m_options.arguments.first();
    if (!SupportBundle::create(out, input, &contents, &error)) {
        fail(DeviceError, error); // not done: the file could not be written
        return;
    }
    m_result = QJsonObject{{QStringLiteral("file"), out},
                           {QStringLiteral("contents"), QJsonArray::fromStringList(contents)},
                           {QStringLiteral("report"), !input.reportHtml.isEmpty()}};
    m_out << tr("wrote %1 (%2):").arg(out, QLocale::c().formattedDataSize(QFileInfo(out).size()))
          << Qt::endl;
    for (const QString &name : std::as_const(contents))
        m_out << QStringLiteral("  ") << name << Qt::endl;
    if (input.reportHtml.isEmpty() && m_options.profile.isEmpty()) // else said above
        m_out << tr("no machine report: no controller was read (--port, --tcp or --sim) and no "
                    "profile was given (--profile)")
              << Qt::endl;
    finish(Ok);
}

} // namespace stepcom
