#include "ctlrunner.h"
#include "ctlcontext.h"
#include "session/parts/sessionconnection.h"

#include "commands/ctlcommands.h"
#include "i18n/translators.h"

#include <QTimer>

#include <cstdio>

namespace stepcom {

CtlRunner::CtlRunner(const CtlOptions &options, const RegisterMap &map, QObject *parent)
    : QObject(parent)
    , m_ctx(std::make_unique<CtlContext>(this, options, map))
{}

CtlRunner::~CtlRunner() = default;

const QList<CtlCommand> &CtlRunner::commands()
{
    static const QList<CtlCommand> table{
        {"params", "params",
         QT_TRANSLATE_NOOP("stepcomctl", "list every parameter and command of the register map"),
         &runParams},
        {"read", "read [KEY...]",
         QT_TRANSLATE_NOOP("stepcomctl", "read parameters (all when none are named)"), &runRead},
        {"write", "write KEY=VALUE...",
         QT_TRANSLATE_NOOP("stepcomctl", "write parameters in engineering units, then verify"),
         &runWrite},
        {"command", "command NAME",
         QT_TRANSLATE_NOOP("stepcomctl", "pulse a command coil (e.g. motor1.stop, estop)"),
         &runCommand},
        {"command", "command NAME --wait",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "pulse a motion command and wait until it ends; print\n"
                           "how it ended (--json), exit 0 only when done or referenced"),
         &runCommandWait, &CtlOptions::wait},
        {"move", "move MOTOR --by D|--to X",
         QT_TRANSLATE_NOOP("stepcomctl", "move motorN by D or to X (axis units) with its single\n"
                                         "move; its own distance and direction are put back and\n"
                                         "verified; exit 0 only when it arrived"),
         &runMove},
        {"run", "run FILE",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "run a machine cycle (a .stepseq file: home, moves, waits\n"
                           "for inputs, outputs, dwells, repeats; docs/sequence.md)\n"
                           "--cycles N times, after showing it and asking (--yes);\n"
                           "each step a line on stderr (--json: JSON lines); Ctrl-C\n"
                           "stops the motors; --check-steps: then the lost-step test\n"
                           "on every axis it moved; exit 0 done (and kept), 1\n"
                           "stopped by the machine (timeout, limit, E-STOP), Ctrl-C\n"
                           "or steps lost, 2 bad file, 3 link, restart or device"),
         &runRun},
        {"lost-steps", "lost-steps motorN",
         QT_TRANSLATE_NOOP("stepcomctl", "prove the axis keeps its steps: the count against the\n"
                                         "home switch before and after --cycles K moves of\n"
                                         "--distance D out fast and back slowly, and the other\n"
                                         "way (docs/proving.md); shown and asked first (--yes);\n"
                                         "exit 0 kept, 1 lost, not known or stopped, 2 refused,\n"
                                         "3 link, restart or device"),
         &runLostSteps},
        {"margin", "margin motorN",
         QT_TRANSLATE_NOOP("stepcomctl", "the lost-step test at each speed --from .. --to in\n"
                                         "--step (--accel: the acceleration), lowest first, up\n"
                                         "to the first loss; recommends 75 % of the highest kept\n"
                                         "and writes it only with --apply; exit 0 searched, 1\n"
                                         "stopped or nothing kept to apply, 2 refused, 3 link"),
         &runMargin},
        {"backlash", "backlash motorN",
         QT_TRANSLATE_NOOP("stepcomctl", "the lost motion on reversal with a dial gauge: moves of\n"
                                         "--distance D, each followed by 'gauge (mm)?' on stderr\n"
                                         "and a reading from stdin; exit 0 measured, 1 stopped\n"
                                         "(end of input), 2 refused, 3 link"),
         &runBacklash},
        {"monitor", "monitor",
         QT_TRANSLATE_NOOP("stepcomctl", "print the live status as one JSON object per line,\n"
                                         "until --count samples or Ctrl-C (--interval MS);\n"
                                         "with --id 1,2,3 each device in turn, one line a\n"
                                         "sample keyed by its id (--json for JSON)"),
         &runMonitor},
        {"listen", "listen",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "hear a line another master (a PLC, an HMI) drives, never\n"
                           "sending a byte: each request paired with its answer and\n"
                           "decoded by the map, a line each as heard (--json), until\n"
                           "Ctrl-C or --seconds N; a summary of frames, pairs, CRC\n"
                           "errors and answer times on stderr (--port, --baud,\n"
                           "--parity; --log FILE keeps it as a session log)"),
         &runListen},
        {"dump", "dump FILE|FOLDER/",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "read every setting and save it as a profile file\n"
                           "(--name, --notes; --include-link adds id and baud);\n"
                           "into a folder: one file per --id, \"id2 NAME DATE.json\""),
         &runDump},
        {"diff", "diff FILE",
         QT_TRANSLATE_NOOP("stepcomctl", "compare the controller with a profile (exit 0 the\n"
                                         "same, 1 different, 3 link or device error)"),
         &runDiff},
        {"diff", "diff A.json B.json",
         QT_TRANSLATE_NOOP("stepcomctl", "compare two profiles, no controller needed; exit 0\n"
                                         "same, 1 different, 2 bad file"),
         &runDiff},
        {"apply", "apply FILE",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "write the profile's values that differ, after showing\n"
                           "them and asking (--yes skips the question), then verify;\n"
                           "--include-link also writes device id and baud,\n"
                           "--save-to-flash saves afterwards; the settings it\n"
                           "replaces are saved as a backup first (--no-backup)"),
         &runApply},
        {"assign-id", "assign-id --to N",
         QT_TRANSLATE_NOOP("stepcomctl", "give the one controller at --id (default 1, as it\n"
                                         "leaves the factory) the device id N and check it\n"
                                         "answers there; refuses when N is taken or two\n"
                                         "controllers answer at --id"),
         &runAssignId},
        {"scan", "scan",
         QT_TRANSLATE_NOOP("stepcomctl",
                           "find every controller on the line (--port, --rtu-tcp or\n"
                           "--sim; --tcp: ids only) at --bauds, --parity and --ids; a table\n"
                           "(or --json) of id, baud, parity and what answered;\n"
                           "--probe-timeout MS for slow controllers; exit 0 found,\n"
                           "1 none, 2 usage, 3 link error"),
         &runScan},
        {"ports", "ports",
         QT_TRANSLATE_NOOP("stepcomctl", "list the serial ports: stable by-id name, adapter\n"
                                         "(vendor, product, serial number) and whether another\n"
                                         "program holds it; no controller needed"),
         &runPorts},
        {"report", "report FILE.pdf|.html",
         QT_TRANSLATE_NOOP("stepcomctl", "write the commissioning report (--name, --notes,\n"
                                         "--lang en|zh_CN; --from PROFILE: from a profile\n"
                                         "file and its checklist, no controller needed;\n"
                                         "--id 1,2,3: every controller in one document)"),
         &runReport},
        {"replay", "replay LOG|BUNDLE.zip",
         QT_TRANSLATE_NOOP("stepcomctl", "replay a session log (--log FILE or the window's):\n"
                                         "--events, --at TIME [--json], --diff T1 T2; no\n"
                                         "controller needed"),
         &runReplay},
        {"bundle", "bundle OUT.zip",
         QT_TRANSLATE_NOOP("stepcomctl", "make a support bundle: the session logs of the last\n"
                                         "--days N, --profile FILE, the settings, versions, OS\n"
                                         "and serial adapters, the machine report (of the\n"
                                         "profile, and of the controllers given with --port,\n"
                                         "--tcp or --sim and --id), with a README inside"),
         &runBundle},
    };
    return table;
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
        if (m_ctx->options.command != QLatin1String(c.name))
            continue;
        if (c.when && m_ctx->options.*c.when) {
            chosen = &c;
            break;
        }
        if (!c.when && !chosen)
            chosen = &c;
    }
    if (m_ctx->isEnveloped())
        captureOutput(); // kept for the JSON object at the end, an unknown command's too
    if (chosen) {
        m_chosen = chosen;
        if (isPerId())
            startMulti();
        else
            chosen->run(*m_ctx);
        return;
    }
    m_ctx->fail(UsageError, unknownCommandMessage(m_ctx->options.command));
}

bool CtlRunner::isPerId() const
{
    return m_ctx->isMulti() && m_chosen &&
           QLatin1String(m_chosen->name) != QLatin1String("monitor") &&
           QLatin1String(m_chosen->name) != QLatin1String("listen");
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
    } else if (m_ctx->isEnveloped()) {
        printEnvelope(code);
    }
    m_finished = true;
    // The line's health and the timeout it suggests, for whoever tunes the link (monitor runs
    // long enough to say something; other commands with --verbose). Never one of the errors.
    if (m_ctx->session &&
        (m_ctx->options.verbose || m_ctx->options.command == QLatin1String("monitor")))
        QTextStream(stderr) << tr("link: %1")
                                   .arg(m_ctx->session->connection()->linkStats().summary(
                                       m_ctx->session->connection()->settings().timeoutMs))
                            << Qt::endl;
    m_ctx->out.flush();
    m_ctx->err.flush();
    if (m_ctx->session &&
        m_ctx->session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
        m_ctx->session->connection()->disconnectFrom(tr("done"));
    QTimer::singleShot(0, this, [this, code] { Q_EMIT finished(code); });
}

} // namespace stepcom
