#include "ctlcontext.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include "profile/sessionbackup.h"
#include "session/sessionlog.h"
#include "session/simulatorstarter.h"
#include "sim/host/builtinsimulator.h"

#include <QHash>

namespace stepcom {

CtlContext::CtlContext(CtlRunner *owner, const CtlOptions &runOptions, const RegisterMap &runMap)
    : options(runOptions)
    , map(runMap)
    , out(stdout)
    , err(stderr)
    , m_runner(owner)
{}

QObject *CtlContext::runner() const
{
    return m_runner;
}

void CtlContext::fail(int code, const QString &message)
{
    err << QStringLiteral("stepcomctl: ") << message << Qt::endl;
    finish(code);
}

void CtlContext::finish(int code)
{
    m_runner->finish(code);
}

QString CtlContext::valueText(const Parameter &p, qint64 raw) const
{
    QString text = p.formatRaw(raw);
    if (!p.values.isEmpty()) {
        const QString label = p.displayRaw(raw);
        if (label != text)
            text += QStringLiteral(" (%1)").arg(label);
    } else if (!p.unit.isEmpty()) {
        text += QLatin1Char(' ') + p.unit;
    }
    return text;
}

QJsonValue CtlContext::jsonValue(const Parameter &p, qint64 raw)
{
    if (p.scale == 1)
        return QJsonValue(double(raw));
    return QJsonValue(p.formatRaw(raw).toDouble());
}

QStringList CtlContext::condensed(const QStringList &errors)
{
    QStringList said;
    QList<int> more;
    QHash<QString, qsizetype> first; // the answer after "read block n/m [address]: "
    for (const QString &e : errors) {
        const qsizetype at = e.indexOf(QLatin1String("]: "));
        const QString answer = at < 0 ? e : e.mid(at + 3);
        if (const auto it = first.constFind(answer); it != first.cend()) {
            ++more[*it];
            continue;
        }
        first.insert(answer, said.size());
        said << e;
        more << 0;
    }
    for (qsizetype i = 0; i < said.size(); ++i) {
        if (more.at(i) > 0)
            said[i] +=
                QLatin1Char(' ') + CtlRunner::tr("(the same for %n more read(s) of this command)",
                                                 nullptr, more.at(i));
    }
    return said;
}

void CtlContext::connectThen(std::function<void()> next)
{
    if (options.target == CtlOptions::Target::None) {
        fail(CtlRunner::UsageError,
             CtlRunner::tr("no controller given: use --port PATH, --tcp HOST[:PORT] or --sim"));
        return;
    }
    if (session && session->connection()->isConnected()) {
        next(); // --id with several: the next id on the link that is already open
        return;
    }
    if (session)
        session->deleteLater(); // a link that could not be opened for the last id
    // One-shot: no read-all after connecting, no status poll; each command reads what it names.
    session = new DeviceSession(map, m_runner);
    session->setLive(false);
    installRiskGuard();
    startLog();
    SessionConnection::setLinkDiagnosticsShown(options.verbose);
    // Said once, in words: what this controller refuses to read, and that the work goes on.
    QObject::connect(session->connection(), &SessionConnection::readLimitsLearned, m_runner,
                     [this](const QString &text) {
                         err << QStringLiteral("stepcomctl: ")
                             << CtlRunner::tr("note: %1").arg(text) << Qt::endl;
                     });
    if (isMulti())
        session->line()->setDeviceIds(options.ids);
    if (options.verbose) {
        QObject::connect(session->connection()->traffic(), &TrafficLog::entryAdded, m_runner,
                         [](const TrafficEntry &e) {
                             // Straight to standard error: never one of the JSON object's errors.
                             QTextStream(stderr) << TrafficLog::format(e) << Qt::endl;
                         });
    }
    // Only the first opening runs the command: a write of device.baud reopens the link at the
    // new baud, and that must not start the command a second time.
    QObject::connect(
        session->connection(), &SessionConnection::connected, m_runner,
        [this, next](bool ok, const QString &reason) {
            if (!ok) {
                const bool simDown =
                    session->simulatorStarter() && !session->simulatorStarter()->isRunning();
                fail(linkError,
                     simDown ? CtlRunner::tr("cannot start the built-in simulator: %1").arg(reason)
                             : CtlRunner::tr("cannot connect to %1: %2")
                                   .arg(session->connection()->settings().describe(), reason));
                return;
            }
            next();
        },
        Qt::SingleShotConnection);
    if (options.target == CtlOptions::Target::Sim) {
        // The built-in controller runs in this process; on Unix it is reached over a
        // pseudo-terminal, so --sim takes the same RTU path as a real adapter (and --echo
        // rehearses an echoing adapter on it).
        auto sim = std::make_unique<BuiltinSimulator>();
        sim->setEcho(options.link.echo);
        // As a real controller: silent at another id or baud, what it saved kept between runs.
        sim->setClientLink(options.link.deviceId, options.link.baud);
        sim->setClientTiming(options.link); // --timeout and --retries in force here too
        sim->setFlashPath(BuiltinSimulator::defaultFlashPath());
        if (isMulti())
            sim->setIds(options.ids); // one simulated controller per id, on one line
        session->setSimulator(std::move(sim));
        session->connection()->connectSimulator();
    } else {
        session->connection()->connectTo(options.link);
    }
}

void CtlContext::installRiskGuard()
{
    // The session is the runner's child: it never outlives this context.
    session->risks()->setGuard([this](DeviceSession::Risk risk, int id,
                                      DeviceSession::Proceed proceed) {
        if (options.noBackup) {
            proceed(QString());
            return;
        }
        SessionBackup::save(
            session, BackupStore(), risk, id,
            [this, risk, proceed](const BackupStore::Saved &saved) {
                if (!saved.ok()) {
                    proceed(risk == DeviceSession::Risk::Apply
                                ? CtlRunner::tr("no backup of the controller's settings could be "
                                                "saved (%1): nothing was written (--no-backup "
                                                "applies without one)")
                                      .arg(saved.error)
                                : CtlRunner::tr("no backup of the controller's settings could be "
                                                "saved (%1): nothing was done (--no-backup goes "
                                                "on without one)")
                                      .arg(saved.error));
                    return;
                }
                out << CtlRunner::tr("backup of the controller's settings: %1").arg(saved.path)
                    << Qt::endl;
                proceed(QString());
            });
    });
}

void CtlContext::guardThen(DeviceSession::Risk risk, std::function<void()> next)
{
    session->risks()->guard(risk, [this, next](const QString &refusal) {
        if (!refusal.isEmpty()) {
            fail(CtlRunner::DeviceError, refusal);
            return;
        }
        next();
    });
}

void CtlContext::startLog()
{
    if (options.logFile.isEmpty())
        return;
    SessionLog *log = session->log();
    log->setFile(options.logFile);
    QObject::connect(log, &SessionLog::failed, m_runner, [this](const QString &reason) {
        err << QStringLiteral("stepcomctl: ") << reason << Qt::endl;
    });
}

} // namespace stepcom
