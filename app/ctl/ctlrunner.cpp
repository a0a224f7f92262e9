#include "ctlrunner.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include "ctlbusmonitor.h"
#include "ctllinkadvice.h"
#include "ctlmonitor.h"
#include "ctlmotionwait.h"

#include "i18n/translators.h"
#include "motion/motionjudge.h"
#include "session/simulatorstarter.h"
#include "sim/host/builtinsimulator.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cstdio>

namespace stepcom {

namespace {

QString accessName(const Parameter &p)
{
    switch (p.access) {
    case Access::ReadOnly:
        return QStringLiteral("r");
    case Access::ReadWrite:
        return QStringLiteral("rw");
    case Access::Command:
        return QStringLiteral("w");
    }
    return {};
}

QString commandName(CommandClass c)
{
    switch (c) {
    case CommandClass::Emergency:
        return QStringLiteral("emergency");
    case CommandClass::Motion:
        return QStringLiteral("motion");
    case CommandClass::Output:
        return QStringLiteral("output");
    case CommandClass::Setting:
        return QStringLiteral("setting");
    case CommandClass::Destructive:
        return QStringLiteral("destructive");
    case CommandClass::None:
        break;
    }
    return {};
}

} // namespace

CtlRunner::CtlRunner(const CtlOptions &options, const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_options(options)
    , m_map(map)
    , m_out(stdout)
    , m_err(stderr)
{}

const QList<CtlCommand> &CtlRunner::commands()
{
    static const QList<CtlCommand> table{
        {"params", "params",
         QT_TRANSLATE_NOOP("stepcomctl", "list every parameter and command of the register map"),
         &CtlRunner::runParams},
        {"read", "read [KEY...]",
         QT_TRANSLATE_NOOP("stepcomctl", "read parameters (all when none are named)"),
         &CtlRunner::runRead},
        {"write", "write KEY=VALUE...",
         QT_TRANSLATE_NOOP("stepcomctl", "write parameters in engineering units, then verify"),
         &CtlRunner::runWrite},
        {"command", "command NAME",
         QT_TRANSLATE_NOOP("stepcomctl", "pulse a command coil (e.g. motor1.stop, estop)"),
         &CtlRunner::runCommand},
        {"command", "command NAME --wait",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "pulse a motion command and wait until it ends; print\n"
                           "how it ended (--json), exit 0 only when done or referenced"),
         &CtlRunner::runCommandWait, &CtlOptions::wait},
        {"move", "move MOTOR --by D|--to X",
         QT_TRANSLATE_NOOP("stepcomctl", "move motorN by D or to X (axis units) with its single\n"
                                         "move; its own distance and direction are put back and\n"
                                         "verified; exit 0 only when it arrived"),
         &CtlRunner::runMove},
        {"monitor", "monitor",
         QT_TRANSLATE_NOOP("stepcomctl", "print the live status as one JSON object per line,\n"
                                         "until --count samples or Ctrl-C (--interval MS);\n"
                                         "with --id 1,2,3 each device in turn, one line a\n"
                                         "sample keyed by its id (--json for JSON)"),
         &CtlRunner::runMonitor},
        {"listen", "listen",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "hear a line another master (a PLC, an HMI) drives, never\n"
                           "sending a byte: each request paired with its answer and\n"
                           "decoded by the map, a line each as heard (--json), until\n"
                           "Ctrl-C or --seconds N; a summary of frames, pairs, CRC\n"
                           "errors and answer times on stderr (--port, --baud,\n"
                           "--parity; --log FILE keeps it as a session log)"),
         &CtlRunner::runListen},
        {"dump", "dump FILE|FOLDER/",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "read every setting and save it as a profile file\n"
                           "(--name, --notes; --include-link adds id and baud);\n"
                           "into a folder: one file per --id, \"id2 NAME DATE.json\""),
         &CtlRunner::runDump},
        {"diff", "diff FILE",
         QT_TRANSLATE_NOOP("stepcomctl", "compare the controller with a profile (exit 0 the\n"
                                         "same, 1 different, 3 link or device error)"),
         &CtlRunner::runDiff},
        {"diff", "diff A.json B.json",
         QT_TRANSLATE_NOOP("stepcomctl", "compare two profiles, no controller needed; exit 0\n"
                                         "same, 1 different, 2 bad file"),
         &CtlRunner::runDiff},
        {"apply", "apply FILE",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "write the profile's values that differ, after showing\n"
                           "them and asking (--yes skips the question), then verify;\n"
                           "--include-link also writes device id and baud,\n"
                           "--save-to-flash saves afterwards; the settings it\n"
                           "replaces are saved as a backup first (--no-backup)"),
         &CtlRunner::runApply},
        {"assign-id", "assign-id --to N",
         QT_TRANSLATE_NOOP("stepcomctl", "give the one controller at --id (default 1, as it\n"
                                         "leaves the factory) the device id N and check it\n"
                                         "answers there; refuses when N is taken or two\n"
                                         "controllers answer at --id"),
         &CtlRunner::runAssignId},
        {"scan", "scan",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "find every controller on the line (--port, --rtu-tcp or\n"
                           "--sim; --tcp: ids only) at --bauds, --parity and --ids; a table\n"
                           "(or --json) of id, baud, parity and what answered;\n"
                           "--probe-timeout MS for slow controllers; exit 0 found,\n"
                           "1 none, 2 usage, 3 link error"),
         &CtlRunner::runScan},
        {"ports", "ports",
         QT_TRANSLATE_NOOP("stepcomctl", "list the serial ports: stable by-id name, adapter\n"
                                         "(vendor, product, serial number) and whether another\n"
                                         "program holds it; no controller needed"),
         &CtlRunner::runPorts},
        {"report", "report FILE.pdf|.html",
         QT_TRANSLATE_NOOP("stepcomctl", "write the commissioning report (--name, --notes,\n"
                                         "--lang en|zh_CN; --from PROFILE: from a profile\n"
                                         "file and its checklist, no controller needed;\n"
                                         "--id 1,2,3: every controller in one document)"),
         &CtlRunner::runReport},
        {"replay", "replay LOG|BUNDLE.zip",
         QT_TRANSLATE_NOOP("stepcomctl", "replay a session log (--log FILE or the window's):\n"
                                         "--events, --at TIME [--json], --diff T1 T2; no\n"
                                         "controller needed"),
         &CtlRunner::runReplay},
        {"bundle", "bundle OUT.zip",
         QT_TRANSLATE_NOOP("stepcomctl", "make a support bundle: the session logs of the last\n"
                                         "--days N, --profile FILE, the settings, versions, OS\n"
                                         "and serial adapters, the machine report (of the\n"
                                         "profile, and of the controllers given with --port,\n"
                                         "--tcp or --sim and --id), with a README inside"),
         &CtlRunner::runBundle},
    };
    return table;
}

QJsonValue CtlRunner::jsonValue(const Parameter &p, qint64 raw)
{
    if (p.scale == 1)
        return QJsonValue(double(raw));
    return QJsonValue(p.formatRaw(raw).toDouble());
}

QStringList CtlRunner::condensed(const QStringList &errors)
{
    QStringList out;
    QList<int> more;
    QHash<QString, qsizetype> first; // the answer after "read block n/m [address]: "
    for (const QString &e : errors) {
        const qsizetype at = e.indexOf(QLatin1String("]: "));
        const QString answer = at < 0 ? e : e.mid(at + 3);
        if (const auto it = first.constFind(answer); it != first.cend()) {
            ++more[*it];
            continue;
        }
        first.insert(answer, out.size());
        out << e;
        more << 0;
    }
    for (qsizetype i = 0; i < out.size(); ++i) {
        if (more.at(i) > 0)
            out[i] += QLatin1Char(' ') +
                      tr("(the same for %n more read(s) of this command)", nullptr, more.at(i));
    }
    return out;
}

QString CtlRunner::commandNames()
{
    QStringList names;
    for (const CtlCommand &c : commands())
        names << QLatin1String(c.name);
    names.removeDuplicates(); // a command may have several usages (diff)
    return Translators::joinList(names);
}

QString CtlRunner::unknownCommandMessage(const QString &name)
{
    return tr("unknown command '%1' (%2)").arg(name, commandNames());
}

void CtlRunner::start()
{
    // A row that needs an option (command NAME --wait) is taken over the plain one when set.
    const CtlCommand *chosen = nullptr;
    for (const CtlCommand &c : commands()) {
        if (m_options.command != QLatin1String(c.name))
            continue;
        if (c.when && m_options.*c.when) {
            chosen = &c;
            break;
        }
        if (!c.when && !chosen)
            chosen = &c;
    }
    if (isEnveloped())
        captureOutput(); // kept for the JSON object at the end, an unknown command's too
    if (chosen) {
        m_chosen = chosen;
        if (isPerId())
            startMulti();
        else
            (this->*chosen->run)();
        return;
    }
    fail(UsageError, unknownCommandMessage(m_options.command));
}

void CtlRunner::fail(int code, const QString &message)
{
    m_err << QStringLiteral("stepcomctl: ") << message << Qt::endl;
    finish(code);
}

void CtlRunner::finish(int code)
{
    if (m_finished)
        return;
    if (isPerId()) {
        if (nextId(code))
            return;
        code = worstCode();
        printMulti();
    } else if (isEnveloped()) {
        printEnvelope(code);
    }
    m_finished = true;
    // The line's health and the timeout it suggests, for whoever tunes the link (monitor runs
    // long enough to say something; other commands with --verbose). Never one of the errors.
    if (m_session && (m_options.verbose || m_options.command == QLatin1String("monitor")))
        QTextStream(stderr) << tr("link: %1")
                                   .arg(m_session->connection()->linkStats().summary(
                                       m_session->connection()->settings().timeoutMs))
                            << Qt::endl;
    m_out.flush();
    m_err.flush();
    if (m_session &&
        m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
        m_session->connection()->disconnectFrom(tr("done"));
    QTimer::singleShot(0, this, [this, code] { Q_EMIT finished(code); });
}

QString CtlRunner::valueText(const Parameter &p, qint64 raw) const
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

void CtlRunner::connectThen(std::function<void()> next)
{
    if (m_options.target == CtlOptions::Target::None) {
        fail(UsageError, tr("no controller given: use --port PATH, --tcp HOST[:PORT] or --sim"));
        return;
    }
    if (m_session && m_session->connection()->isConnected()) {
        next(); // --id with several: the next id on the link that is already open
        return;
    }
    if (m_session)
        m_session->deleteLater(); // a link that could not be opened for the last id
    // One-shot: no read-all after connecting, no status poll; each command reads what it names.
    m_session = new DeviceSession(m_map, this);
    m_session->setLive(false);
    installRiskGuard();
    startLog();
    SessionConnection::setLinkDiagnosticsShown(m_options.verbose);
    // Said once, in words: what this controller refuses to read, and that the work goes on.
    connect(m_session->connection(), &SessionConnection::readLimitsLearned, this,
            [this](const QString &text) {
                m_err << QStringLiteral("stepcomctl: ") << tr("note: %1").arg(text) << Qt::endl;
            });
    if (isMulti())
        m_session->line()->setDeviceIds(m_options.ids);
    if (m_options.verbose) {
        connect(m_session->connection()->traffic(), &TrafficLog::entryAdded, this,
                [](const TrafficEntry &e) {
                    // Straight to standard error: never one of the JSON object's errors.
                    QTextStream(stderr) << TrafficLog::format(e) << Qt::endl;
                });
    }
    // Only the first opening runs the command: a write of device.baud reopens the link at the
    // new baud, and that must not start the command a second time.
    connect(
        m_session->connection(), &SessionConnection::connected, this,
        [this, next](bool ok, const QString &reason) {
            if (!ok) {
                const bool simDown =
                    m_session->simulatorStarter() && !m_session->simulatorStarter()->isRunning();
                fail(m_linkError,
                     simDown ? tr("cannot start the built-in simulator: %1").arg(reason)
                             : tr("cannot connect to %1: %2")
                                   .arg(m_session->connection()->settings().describe(), reason));
                return;
            }
            next();
        },
        Qt::SingleShotConnection);
    if (m_options.target == CtlOptions::Target::Sim) {
        // The built-in controller runs in this process; on Unix it is reached over a
        // pseudo-terminal, so --sim takes the same RTU path as a real adapter (and --echo
        // rehearses an echoing adapter on it).
        auto sim = std::make_unique<BuiltinSimulator>();
        sim->setEcho(m_options.link.echo);
        // As a real controller: silent at another id or baud, what it saved kept between runs.
        sim->setClientLink(m_options.link.deviceId, m_options.link.baud);
        sim->setClientTiming(m_options.link); // --timeout and --retries in force here too
        sim->setFlashPath(BuiltinSimulator::defaultFlashPath());
        if (isMulti())
            sim->setIds(m_options.ids); // one simulated controller per id, on one line
        m_session->setSimulator(std::move(sim));
        m_session->connection()->connectSimulator();
    } else {
        m_session->connection()->connectTo(m_options.link);
    }
}

void CtlRunner::runParams()
{
    if (m_options.json) {
        QJsonArray array;
        for (const Parameter &p : m_map.parameters()) {
            QJsonObject o{{QStringLiteral("key"), p.key},
                          {QStringLiteral("kind"),
                           p.isHolding() ? QStringLiteral("holding") : QStringLiteral("coil")},
                          {QStringLiteral("plc"), p.plc},
                          {QStringLiteral("address"), p.address},
                          {QStringLiteral("words"), p.isHolding() ? p.words : 1},
                          {QStringLiteral("signed"), p.isSigned},
                          {QStringLiteral("scale"), p.scale},
                          {QStringLiteral("unit"), p.unit},
                          {QStringLiteral("access"), accessName(p)},
                          {QStringLiteral("group"), p.group},
                          {QStringLiteral("label"), p.label.en},
                          {QStringLiteral("label_zh_CN"), p.label.zh},
                          {QStringLiteral("help"), p.help.en}};
            if (p.isHolding()) {
                o.insert(QStringLiteral("min"), jsonValue(p, p.rawMin));
                o.insert(QStringLiteral("max"), jsonValue(p, p.rawMax));
                if (!p.values.isEmpty()) {
                    QJsonArray values;
                    for (const EnumValue &v : p.values)
                        values.append(QJsonObject{{QStringLiteral("value"), double(v.value)},
                                                  {QStringLiteral("label"), v.label.en}});
                    o.insert(QStringLiteral("values"), values);
                }
            } else {
                o.insert(QStringLiteral("min"), QJsonValue());
                o.insert(QStringLiteral("max"), QJsonValue());
                o.insert(QStringLiteral("command"), commandName(p.command));
            }
            array.append(o);
        }
        m_out << QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Indented));
    } else {
        for (const Parameter &p : m_map.parameters()) {
            const QString range = p.isHolding() ? p.rangeText() : commandName(p.command);
            m_out << QStringLiteral("%1  %2  %3  %4  %5")
                         .arg(p.key, -26)
                         .arg(p.registerName(), -15)
                         .arg(accessName(p), -2)
                         .arg(p.label.en, -32)
                         .arg(range)
                  << Qt::endl;
        }
    }
    finish(Ok);
}

void CtlRunner::runRead()
{
    QList<const Parameter *> params;
    for (const QString &key : std::as_const(m_options.arguments)) {
        const Parameter *p = m_map.find(key);
        if (!p) {
            fail(UsageError, tr("unknown parameter '%1' (see: stepcomctl params)").arg(key));
            return;
        }
        if (!p->readable()) {
            fail(UsageError, tr("%1 is a command and cannot be read").arg(key));
            return;
        }
        params << p;
    }
    if (params.isEmpty())
        params = m_map.holdings();
    connectThen([this, params] {
        m_session->parameters()->read(params, [this, params](const ReadOutcome &r) {
            if (m_options.json) {
                QJsonObject o;
                for (const Parameter *p : params) {
                    if (r.values.contains(p->key))
                        o.insert(p->key, jsonValue(*p, r.values.value(p->key)));
                }
                m_out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            } else {
                for (const Parameter *p : params) {
                    if (r.values.contains(p->key))
                        m_out << p->key << QStringLiteral(" = ")
                              << valueText(*p, r.values.value(p->key)) << Qt::endl;
                }
            }
            for (const QString &key : r.unsupported)
                m_err << QStringLiteral("stepcomctl: ")
                      << tr("%1 is not supported by this controller").arg(key) << Qt::endl;
            if (!r.ok) {
                for (const QString &e : condensed(r.errors))
                    m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                finish(DeviceError);
                return;
            }
            finish(Ok);
        });
    });
}

const Parameter *CtlRunner::commandArgument()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("command needs exactly one command name (see: stepcomctl params)"));
        return nullptr;
    }
    const QString key = m_options.arguments.first();
    const Parameter *p = m_map.find(key);
    if (!p || !p->isCoil()) {
        fail(UsageError, p ? tr("%1 is a parameter, not a command: use read or write").arg(key)
                           : tr("unknown command '%1' (see: stepcomctl params)").arg(key));
        return nullptr;
    }
    if (p->command == CommandClass::Destructive && !m_options.yes) {
        fail(UsageError,
             tr("%1 destroys settings (%2); add --yes if you mean it").arg(key, p->help.en));
        return nullptr;
    }
    return p;
}

void CtlRunner::runCommand()
{
    const Parameter *p = commandArgument();
    if (!p)
        return;
    connectThen([this, p] {
        const bool risky =
            p->key == QLatin1String("factory_reset") || p->key == QLatin1String("save_to_flash");
        const auto risk = p->key == QLatin1String("factory_reset")
                              ? DeviceSession::Risk::FactoryReset
                              : DeviceSession::Risk::SaveToFlash;
        const auto send = [this, p] {
            m_session->command(*p, [this, p](const Result &r) {
                if (!r.ok) {
                    fail(DeviceError, r.errorText);
                    return;
                }
                m_result = QJsonObject{{QStringLiteral("command"), p->key},
                                       {QStringLiteral("state"), p->command == CommandClass::Motion
                                                                     ? QStringLiteral("sent")
                                                                     : QStringLiteral("done")}};
                // A moving command is only acknowledged: its end is known with --wait.
                m_out << (p->command == CommandClass::Motion
                              ? tr("%1: sent (add --wait to wait for how it ends)").arg(p->key)
                              : tr("%1: done").arg(p->key))
                      << Qt::endl;
                finish(Ok);
            });
        };
        if (risky)
            guardThen(risk, send);
        else
            send();
    });
}

void CtlRunner::runCommandWait()
{
    const Parameter *p = commandArgument();
    if (!p)
        return;
    if (!MotionJudge::kindOf(m_map, p->key)) {
        fail(UsageError, tr("--wait: %1 has no end to wait for (single move, home, home in "
                            "order, return to data zero, arc and line have one)")
                             .arg(p->key));
        return;
    }
    connectThen([this, p] {
        auto *wait = new CtlMotionWait(m_session, *p, m_options.json, m_out, m_err, this);
        connect(wait, &CtlMotionWait::finished, this, &CtlRunner::finish);
        wait->start();
    });
}

void CtlRunner::runMonitor()
{
    if (!m_options.arguments.isEmpty()) {
        fail(UsageError, tr("monitor takes no arguments, only --count and --interval"));
        return;
    }
    connectThen([this] {
        if (isMulti()) {
            // Several ids: one status read per device in turn, each line keyed by its id.
            auto *bus = new CtlBusMonitor(m_session, m_options.ids, m_options.count,
                                          m_options.intervalMs, m_options.json, this);
            connect(bus, &CtlBusMonitor::finished, this, [this, bus](int code) {
                m_result = bus->summary();
                m_liveErrors = bus->errors();
                finish(code);
            });
            bus->start();
            return;
        }
        auto *monitor =
            new CtlMonitor(m_session, m_options.count, m_options.intervalMs, m_options.json, this);
        connect(monitor, &CtlMonitor::finished, this, [this, monitor](int code) {
            m_result = monitor->summary();
            m_liveErrors = monitor->errors();
            finish(code);
        });
        monitor->start();
    });
}

} // namespace stepcom
