// stepcomctl --id 1,2,3: one command for several controllers on one line, in turn.
#include "ctlrunner.h"
#include "ctlscan.h"

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

} // namespace

void CtlRunner::startMulti()
{
    if (!runsPerId(*m_chosen)) {
        const CtlCommand *chosen = std::exchange(m_chosen, nullptr); // a usage error, not per id
        fail(UsageError, tr("%1: give one device id; several ids work with read, diff, apply, "
                            "dump and command (without --wait)")
                             .arg(QLatin1String(chosen->name)));
        return;
    }
    if (QLatin1String(m_chosen->name) == QLatin1String("dump") && m_options.arguments.size() == 1)
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
    m_beforeApply.clear();
    if (!m_multiArgument.isEmpty()) {
        // One profile file per controller: NAME-id2.json beside the name asked for.
        const QFileInfo info(m_multiArgument);
        const QString suffix =
            info.completeSuffix().isEmpty() ? QString() : QLatin1Char('.') + info.completeSuffix();
        m_options.arguments[0] = info.dir().filePath(
            QStringLiteral("%1-id%2%3").arg(info.baseName()).arg(id).arg(suffix));
    }
    if (m_session && m_session->isConnected())
        m_session->showDevice(id);
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

void CtlRunner::printMulti()
{
    QTextStream out(stdout);
    if (m_options.json) {
        QJsonObject all;
        for (qsizetype i = 0; i < m_idOutputs.size(); ++i) {
            QJsonObject one{{QStringLiteral("exit"), m_idCodes.at(i)}};
            if (!m_idErrors.at(i).isEmpty())
                one.insert(QStringLiteral("errors"), QJsonArray::fromStringList(m_idErrors.at(i)));
            const QJsonDocument doc = QJsonDocument::fromJson(m_idOutputs.at(i).toUtf8());
            if (doc.isObject())
                one.insert(QStringLiteral("result"), doc.object());
            else if (doc.isArray())
                one.insert(QStringLiteral("result"), doc.array());
            else if (!m_idOutputs.at(i).trimmed().isEmpty())
                one.insert(QStringLiteral("output"), m_idOutputs.at(i).trimmed());
            all.insert(QString::number(m_options.ids.at(i)), one);
        }
        out << QString::fromUtf8(QJsonDocument(all).toJson(QJsonDocument::Indented));
    } else {
        for (qsizetype i = 0; i < m_idOutputs.size(); ++i) {
            out << tr("== device id %1 ==").arg(m_options.ids.at(i)) << Qt::endl;
            const QString text = m_idOutputs.at(i);
            out << text;
            if (!text.isEmpty() && !text.endsWith(QLatin1Char('\n')))
                out << Qt::endl;
        }
    }
    out.flush();
    m_out.setDevice(nullptr);
    m_err.setDevice(nullptr);
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
    const Parameter *idParam = m_map.find(QStringLiteral("device.id"));
    if (!idParam) {
        fail(UsageError, tr("assign-id: the register map has no device.id"));
        return;
    }
    connectThen([this, from, to, idParam] {
        m_session->setDeviceIds({from, to});
        const quint64 crcBefore = m_session->linkStats().crcErrors;
        m_session->read({idParam}, [this, from, to, idParam, crcBefore](const ReadOutcome &r) {
            if (!r.ok) {
                // Two controllers answering at once garble each other's answers.
                if (m_session->linkStats().crcErrors > crcBefore)
                    fail(DeviceError,
                         tr("garbled answers at id %1: two or more controllers answer there. "
                            "Connect only the controller that is to get id %2, then try again")
                             .arg(from)
                             .arg(to));
                else
                    fail(DeviceError, tr("no controller answers at id %1: %2")
                                          .arg(from)
                                          .arg(r.errors.join(QLatin1String("; "))));
                return;
            }
            // Nobody may be at the new id already: two controllers at one id collide.
            m_session->showDevice(to);
            m_session->read({idParam}, [this, from, to](const ReadOutcome &taken) {
                m_session->showDevice(from);
                if (taken.ok) {
                    fail(DeviceError, tr("id %1 is taken: a controller answers there already. "
                                         "Choose a free id")
                                          .arg(to));
                    return;
                }
                connect(m_session, &DeviceSession::linkChanged, this,
                        [this, from, to](const LinkSettings &) {
                            m_out << tr("device id %1 → %2: the controller answers at id %2")
                                         .arg(from)
                                         .arg(to)
                                  << Qt::endl;
                            finish(Ok);
                        });
                connect(
                    m_session, &DeviceSession::linkChangeFailed, this,
                    [this, to](const LinkSettings &, const QString &reason) {
                        fail(DeviceError,
                             tr("the controller does not answer at id %1: %2").arg(to).arg(reason));
                    });
                m_session->changeLink(to, m_session->settings().baud);
            });
        });
    });
}

void CtlRunner::runScan()
{
    if (m_options.target == CtlOptions::Target::None ||
        m_options.target == CtlOptions::Target::Sim) {
        fail(UsageError, tr("scan: give the line to scan: --port, --rtu-tcp or --tcp (the "
                            "built-in simulator is one controller at a known id; scan "
                            "stepcom-sim --pty instead)"));
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
    auto *scan = new CtlScan(plan, m_map, m_options.json, this);
    connect(scan, &CtlScan::finished, this, &CtlRunner::finish);
    scan->start();
}

} // namespace stepcom
