// stepcomctl --id 1,2,3: one command for several controllers on one line, in turn.
#include "ctllinkadvice.h"
#include "ctlrunner.h"
#include "ctlscan.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include "line/idchange.h"
#include "sim/host/builtinsimulator.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>
#include <cstdio>

namespace stepcom {

namespace {

// The commands that make sense for each controller of a line in turn.
bool runsPerId(const CtlCommand &command)
{
    static const QStringList names{QStringLiteral("read"), QStringLiteral("diff"),
                                   QStringLiteral("apply"), QStringLiteral("dump"),
                                   QStringLiteral("command")};
    return names.contains(QLatin1String(command.name)) && !command.when;
}

// dump DIR/ or dump DIR (an existing folder): one file per device inside it.
bool isFolderArgument(const QString &path)
{
    return path.endsWith(QLatin1Char('/')) || QFileInfo(path).isDir();
}

} // namespace

void CtlRunner::startMulti()
{
    if (QLatin1String(m_chosen->name) == QLatin1String("report")) {
        m_chosen = nullptr; // one document for the whole line, not one run per id
        runMachineReport();
        return;
    }
    if (QLatin1String(m_chosen->name) == QLatin1String("bundle")) {
        m_chosen = nullptr; // one bundle, its report of the whole line
        runBundle();
        return;
    }
    if (!runsPerId(*m_chosen)) {
        const CtlCommand *chosen = std::exchange(m_chosen, nullptr); // a usage error, not per id
        fail(UsageError, tr("%1: give one device id; several ids work with read, monitor, diff, "
                            "apply, dump, report, bundle and command (without --wait)")
                             .arg(QLatin1String(chosen->name)));
        return;
    }
    if (QLatin1String(m_chosen->name) == QLatin1String("dump") && m_options.arguments.size() == 1 &&
        !isFolderArgument(m_options.arguments.first()))
        m_multiArgument = m_options.arguments.first();
    m_idIndex = 0;
    runForCurrentId();
}

void CtlRunner::runForCurrentId()
{
    const int id = m_options.ids.at(m_idIndex);
    m_buffer.clear();
    m_out.setString(&m_buffer); // collected, then printed keyed by id
    m_errBuffer.clear();
    m_err.setString(&m_errBuffer);
    if (!m_multiArgument.isEmpty()) {
        // One profile file per controller: NAME-id2.json beside the name asked for.
        const QFileInfo info(m_multiArgument);
        const QString suffix =
            info.completeSuffix().isEmpty() ? QString() : QLatin1Char('.') + info.completeSuffix();
        m_options.arguments[0] = info.dir().filePath(
            QStringLiteral("%1-id%2%3").arg(info.baseName()).arg(id).arg(suffix));
    }
    if (m_session && m_session->connection()->isConnected())
        m_session->line()->showDevice(id);
    (this->*m_chosen->run)();
}

bool CtlRunner::nextId(int code)
{
    m_out.flush();
    m_err.flush();
    m_idCodes << code;
    m_idOutputs << m_buffer;
    // Every message names the id it is about.
    const QString prefix = QStringLiteral("stepcomctl: ");
    QStringList errors;
    QTextStream err(stderr);
    for (QString line : m_errBuffer.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        if (line.startsWith(prefix))
            line = line.mid(prefix.size());
        errors << line;
        err << prefix << tr("id %1: %2").arg(m_options.ids.at(m_idIndex)).arg(line) << Qt::endl;
    }
    m_idErrors << errors;
    m_idResults << std::exchange(m_result, {});
    if (m_idIndex + 1 >= m_options.ids.size())
        return false;
    ++m_idIndex;
    // After the stack of the id that just ended has unwound.
    QTimer::singleShot(0, this, &CtlRunner::runForCurrentId);
    return true;
}

int CtlRunner::worstCode() const
{
    return m_idCodes.isEmpty() ? int(Ok) : *std::max_element(m_idCodes.begin(), m_idCodes.end());
}

void CtlRunner::runAssignId()
{
    const int from = m_options.link.deviceId;
    const int to = m_options.assignTo;
    if (isMulti() || to == 0) {
        fail(UsageError, tr("assign-id: give the new id with --to N, and one --id (the id the "
                            "controller answers at now, 1 from the factory)"));
        return;
    }
    if (to == from) {
        fail(UsageError, tr("assign-id: the controller already has id %1").arg(to));
        return;
    }
    connectThen([this, from, to] {
        // The same steps as the window's id assistant: core/line/idchange.
        auto *change = new IdChange(m_session, this);
        change->setSaveToFlash(m_options.saveToFlash);
        connect(
            change, &IdChange::finished, this, [this, change, to](bool ok, const QString &text) {
                change->deleteLater();
                if (!ok) {
                    // Answering at the new id but not saved: say how to reach it anyway.
                    if (change->problem() == IdChange::Problem::NotSaved)
                        m_err << QStringLiteral("stepcomctl: ")
                              << tr("next commands: stepcomctl %1 ...")
                                     .arg(CtlLinkAdvice::nextOptions(m_options, to,
                                                                     m_options.link.baud))
                              << Qt::endl;
                    fail(change->problem() == IdChange::Problem::Refused ? UsageError : DeviceError,
                         text);
                    return;
                }
                m_result =
                    QJsonObject{{QStringLiteral("from"), m_options.link.deviceId},
                                {QStringLiteral("to"), to},
                                {QStringLiteral("saved"), m_options.saveToFlash},
                                {QStringLiteral("next"),
                                 CtlLinkAdvice::nextOptions(m_options, to, m_options.link.baud)}};
                m_out << text << Qt::endl;
                if (!m_options.saveToFlash)
                    m_out << tr("id %1 lasts until the power is switched off, then the "
                                "controller answers at the id in its flash again (id 1 from "
                                "the factory); add --save-to-flash to keep it")
                                 .arg(to)
                          << Qt::endl;
                m_out << tr("next commands: stepcomctl %1 ...")
                             .arg(CtlLinkAdvice::nextOptions(m_options, to, m_options.link.baud))
                      << Qt::endl;
                finish(Ok);
            });
        change->start(from, to);
    });
}

void CtlRunner::runScan()
{
    if (m_options.target == CtlOptions::Target::None) {
        fail(UsageError, tr("scan: give the line to scan: --port, --rtu-tcp, --tcp or --sim"));
        return;
    }
    if (!m_options.arguments.isEmpty()) {
        fail(UsageError, tr("scan takes no arguments ('%1'): give --bauds, --parity and --ids")
                             .arg(m_options.arguments.first()));
        return;
    }
    BusScanner::Plan plan;
    plan.base = m_options.link;
    plan.bauds = m_options.scanBauds;
    plan.parities = m_options.scanParities;
    plan.ids = m_options.scanIds;
    plan.probeTimeoutMs = m_options.probeTimeoutMs;
    if (m_options.target == CtlOptions::Target::Sim) {
        // Its pty, whatever id and baud it saved to flash: finding them is what a scan is for.
        auto sim = std::make_unique<BuiltinSimulator>();
        sim->setFlashPath(BuiltinSimulator::defaultFlashPath());
        QString error;
        const std::optional<LinkSettings> link = sim->start(m_map, &error);
        if (!link || link->transport != LinkSettings::Transport::Rtu) {
            fail(CtlScan::LinkError, tr("cannot start the built-in simulator: %1")
                                         .arg(link ? tr("it has no serial line here") : error));
            return;
        }
        plan.base.portName = link->portName;
        m_scanSim = std::move(sim);
    }
    auto *scan = new CtlScan(plan, m_map, m_options.json, m_out, m_err, this);
    connect(scan, &CtlScan::finished, this, &CtlRunner::finish);
    scan->start();
}

} // namespace stepcom
