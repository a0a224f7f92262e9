// stepcomctl --id 1,2,3: one command for several controllers on one line, in turn.
#include "ctlcontext.h"
#include "ctlrunner.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include "commands/ctlcommands.h"

#include <QDir>
#include <QFileInfo>
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
        runMachineReport(*m_ctx);
        return;
    }
    if (QLatin1String(m_chosen->name) == QLatin1String("bundle")) {
        m_chosen = nullptr; // one bundle, its report of the whole line
        runBundle(*m_ctx);
        return;
    }
    if (!runsPerId(*m_chosen)) {
        const CtlCommand *chosen = std::exchange(m_chosen, nullptr); // a usage error, not per id
        m_ctx->fail(UsageError,
                    tr("%1: give one device id; several ids work with read, monitor, diff, "
                       "apply, dump, report, bundle and command (without --wait)")
                        .arg(QLatin1String(chosen->name)));
        return;
    }
    if (QLatin1String(m_chosen->name) == QLatin1String("dump") &&
        m_ctx->options.arguments.size() == 1 && !isFolderArgument(m_ctx->options.arguments.first()))
        m_multiArgument = m_ctx->options.arguments.first();
    m_ctx->idIndex = 0;
    runForCurrentId();
}

void CtlRunner::runForCurrentId()
{
    const int id = m_ctx->options.ids.at(m_ctx->idIndex);
    m_ctx->outBuffer.clear();
    m_ctx->out.setString(&m_ctx->outBuffer); // collected, then printed keyed by id
    m_ctx->errBuffer.clear();
    m_ctx->err.setString(&m_ctx->errBuffer);
    if (!m_multiArgument.isEmpty()) {
        // One profile file per controller: NAME-id2.json beside the name asked for.
        const QFileInfo info(m_multiArgument);
        const QString suffix =
            info.completeSuffix().isEmpty() ? QString() : QLatin1Char('.') + info.completeSuffix();
        m_ctx->options.arguments[0] = info.dir().filePath(
            QStringLiteral("%1-id%2%3").arg(info.baseName()).arg(id).arg(suffix));
    }
    if (m_ctx->session && m_ctx->session->connection()->isConnected())
        m_ctx->session->line()->showDevice(id);
    m_chosen->run(*m_ctx);
}

bool CtlRunner::nextId(int code)
{
    m_ctx->out.flush();
    m_ctx->err.flush();
    m_idCodes << code;
    m_idOutputs << m_ctx->outBuffer;
    // Every message names the id it is about.
    const QString prefix = QStringLiteral("stepcomctl: ");
    QStringList errors;
    QTextStream err(stderr);
    for (QString line : m_ctx->errBuffer.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        if (line.startsWith(prefix))
            line = line.mid(prefix.size());
        errors << line;
        err << prefix << tr("id %1: %2").arg(m_ctx->options.ids.at(m_ctx->idIndex)).arg(line)
            << Qt::endl;
    }
    m_idErrors << errors;
    m_idResults << std::exchange(m_ctx->result, {});
    if (m_ctx->idIndex + 1 >= m_ctx->options.ids.size())
        return false;
    ++m_ctx->idIndex;
    // After the stack of the id that just ended has unwound.
    QTimer::singleShot(0, this, &CtlRunner::runForCurrentId);
    return true;
}

int CtlRunner::worstCode() const
{
    return m_idCodes.isEmpty() ? int(Ok) : *std::max_element(m_idCodes.begin(), m_idCodes.end());
}

} // namespace stepcom
