#include "ctloptions.h"
#include "ctlrunner.h"

#include "session/idlist.h"

#include <QCoreApplication>

namespace stepcom {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::CtlOptions", text);
}

bool toInt(const QString &text, int *out)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (ok)
        *out = v;
    return ok;
}

} // namespace

void CtlOptions::addOptions(QCommandLineParser &parser)
{
    parser.addOptions({
        {QStringLiteral("port"), tr("Serial port of the controller (e.g. /dev/ttyUSB0, COM3)."),
         tr("path")},
        {QStringLiteral("tcp"), tr("Modbus TCP gateway or simulator, HOST[:PORT] (port 502)."),
         tr("host:port")},
        {QStringLiteral("rtu-tcp"),
         tr("RS-485/Ethernet converter in transparent mode: Modbus RTU frames over TCP, "
            "HOST:PORT."),
         tr("host:port")},
        {QStringLiteral("sim"),
         tr("Use the built-in simulated controller (it keeps what it saved to flash between "
            "runs).")},
        {QStringLiteral("sim-reset"),
         tr("Start the built-in simulator from the factory again (id 1, 9600 baud): forget "
            "what it saved to flash. Alone, or before a --sim command.")},
        {QStringLiteral("echo"),
         tr("The adapter echoes what it sends (half-duplex USB-RS485 adapters without echo "
            "suppression): skip the request's own bytes from the first request on (without it "
            "the echo is found by the first read and skipped from then on).")},
        {QStringLiteral("answer-delay"),
         tr("How long the controller may take to answer: the least an adapted timeout allows "
            "(default 35, the manual's). Answers are judged by what they say, whenever they "
            "come."),
         tr("ms"), QStringLiteral("35")},
        {QStringLiteral("fixed-timeout"),
         tr("Always wait --timeout for an answer, instead of fitting the timeout to the "
            "controller's measured answers (4x the median, at most --timeout).")},
        {QStringLiteral("turnaround"),
         tr("Extra silence after an answer before the next request, for converters that need "
            "it (default 0)."),
         tr("ms"), QStringLiteral("0")},
        {QStringLiteral("baud"), tr("Baud rate: 4800, 9600, 19200 or 38400 (default 9600)."),
         tr("rate"), QStringLiteral("9600")},
        {QStringLiteral("parity"),
         tr("Parity: none, even or odd (default none); scan: several, e.g. none,even,odd."),
         tr("parity"), QStringLiteral("none")},
        {QStringLiteral("bauds"),
         tr("scan: the baud rates to try, e.g. 9600,19200 (default all four, 9600 first); not "
            "over --tcp or --rtu-tcp, where the converter's line has its own."),
         tr("list")},
        {QStringLiteral("ids"),
         tr("scan: the device ids to try, e.g. 1-32 or 1,5,7 (default 1-247)."), tr("range")},
        {QStringLiteral("probe-timeout"),
         tr("scan: wait this long for each id's answer (default: fitted to the baud, 67 ms at "
            "9600); more for controllers that answer slowly."),
         tr("ms")},
        {QStringLiteral("stop-bits"), tr("Stop bits: 1 or 2 (default 1)."), tr("n"),
         QStringLiteral("1")},
        {QStringLiteral("id"),
         tr("Device id 1-255 (default 1); several (1,2,3 or 1-3) for read, monitor, diff, apply, "
            "dump, report and command: each in turn on the one line, output keyed by id (report: "
            "one document)."),
         tr("id"), QStringLiteral("1")},
        {QStringLiteral("timeout"), tr("Answer timeout in ms (default 500)."), tr("ms"),
         QStringLiteral("500")},
        {QStringLiteral("retries"), tr("Retries after a timeout (default 2)."), tr("n"),
         QStringLiteral("2")},
        {QStringLiteral("map"), tr("Register map file to use instead of the built-in one."),
         tr("file")},
        {QStringLiteral("json"),
         tr("Machine-readable JSON: one object, exit, result and errors, for every command and "
            "usage error (monitor, listen: its last line).")},
        {QStringLiteral("verbose"), tr("Show the Modbus traffic on standard error.")},
        {QStringLiteral("yes"), tr("Do not ask: needed for commands that destroy settings.")},
        {QStringLiteral("save-to-flash"), tr("After writing, save the parameters to flash.")},
        {QStringLiteral("wait"),
         tr("command: wait until a motion command ends and print how it ended (exit 0 only "
            "when done or referenced).")},
        {QStringLiteral("include-link"),
         tr("dump, apply: include the device id and baud (apply writes them only with this).")},
        {QStringLiteral("no-backup"),
         tr("apply, command factory_reset/save_to_flash, write device.id/device.baud: do not "
            "save a backup of the controller's settings first.")},
        {QStringLiteral("by"), tr("move: a step of this many axis units (+ or -)."),
         tr("distance")},
        {QStringLiteral("to"),
         tr("move: to this position (axis units); assign-id: the new device id 1-255."),
         tr("value")},
        {QStringLiteral("name"), tr("dump, report: name of the profile or the machine."),
         tr("text")},
        {QStringLiteral("notes"), tr("dump, report: notes to record."), tr("text")},
        {QStringLiteral("from"),
         tr("report: make the report from this profile file, not from a controller."),
         tr("profile")},
        {QStringLiteral("log"),
         tr("Append the session log of this run (every frame, with its time) to this file; "
            "stepcomctl replay reads it."),
         tr("file")},
        {QStringLiteral("events"), tr("replay: list what happened (time, device, what).")},
        {QStringLiteral("at"),
         tr("replay: the state of every device at TIME: seconds from the log's start or a "
            "clock time hh:mm:ss[.mmm]."),
         tr("time")},
        {QStringLiteral("diff"),
         tr("replay: what changed from T1 to the time after it (--diff T1 T2)."), tr("T1")},
        {QStringLiteral("entry"),
         tr("replay of a support bundle: the log inside to replay (default: the newest)."),
         tr("name")},
        {QStringLiteral("days"), tr("bundle: the session logs of the last N days (default 7)."),
         tr("n"), QStringLiteral("7")},
        {QStringLiteral("profile"), tr("bundle: the profile (and its checklist) to add."),
         tr("file")},
        {QStringLiteral("count"), tr("monitor: number of samples (default: until stopped)."),
         tr("n")},
        {QStringLiteral("seconds"), tr("listen: stop after N seconds (default: until Ctrl-C)."),
         tr("n")},
        {QStringLiteral("cycles"),
         tr("run: how many times the whole step list runs (default 1); lost-steps, backlash: "
            "back-and-forth moves (default 3); margin: at each value (default 2)."),
         tr("n")},
        {QStringLiteral("distance"),
         tr("lost-steps, margin: each move of the test (default 10 axis units); backlash: each "
            "move (default 1)."),
         tr("d")},
        {QStringLiteral("step"), tr("margin: the step between the values tested."), tr("n")},
        {QStringLiteral("accel"),
         tr("margin: search the acceleration register at the motor's own speed.")},
        {QStringLiteral("apply"),
         tr("margin: write the recommended value, reviewed as write reviews it.")},
        {QStringLiteral("check-steps"),
         tr("run: after the cycles, the lost-step test on every axis the sequence moved.")},
        {QStringLiteral("rs485"),
         tr("Who switches an RS-485 adapter's direction: auto (the adapter itself, default), "
            "kernel (the driver's RS-485 mode, RTS on send) or rts (StepCom raises RTS for "
            "each request)."),
         tr("mode"), QStringLiteral("auto")},
        {QStringLiteral("rs485-delays"),
         tr("--rs485 kernel: the delays before and after sending, in us (default 0,0)."),
         tr("before,after"), QStringLiteral("0,0")},
        {QStringLiteral("interval"),
         tr("monitor: ms between samples (default: as fast as the "
            "link allows)."),
         tr("ms")},
    });
}

QString CtlOptions::fromParser(const QCommandLineParser &parser, CtlOptions *out)
{
    CtlOptions o;
    const int targets =
        int(parser.isSet(QStringLiteral("port"))) + int(parser.isSet(QStringLiteral("tcp"))) +
        int(parser.isSet(QStringLiteral("rtu-tcp"))) + int(parser.isSet(QStringLiteral("sim")));
    if (targets > 1)
        return tr("give only one of --port, --tcp, --rtu-tcp and --sim");
    if (parser.isSet(QStringLiteral("port"))) {
        o.target = Target::Port;
        o.link.transport = LinkSettings::Transport::Rtu;
        o.link.portName = parser.value(QStringLiteral("port"));
    } else if (parser.isSet(QStringLiteral("tcp"))) {
        o.target = Target::Tcp;
        o.link.transport = LinkSettings::Transport::Tcp;
        const QString value = parser.value(QStringLiteral("tcp"));
        if (!LinkSettings::parseHostPort(value, 502, &o.link.host, &o.link.tcpPort))
            return tr("--tcp: '%1' is not HOST[:PORT]").arg(value);
    } else if (parser.isSet(QStringLiteral("rtu-tcp"))) {
        // Reached like a Modbus TCP gateway (a host, no baud of ours), framed as RTU.
        o.target = Target::Tcp;
        o.link.transport = LinkSettings::Transport::RtuTcp;
        const QString value = parser.value(QStringLiteral("rtu-tcp"));
        if (!LinkSettings::parseHostPort(value, 0, &o.link.host, &o.link.tcpPort))
            return tr("--rtu-tcp: '%1' is not HOST:PORT (converters have no standard port: "
                      "see its settings page)")
                .arg(value);
    } else if (parser.isSet(QStringLiteral("sim"))) {
        o.target = Target::Sim;
    }
    if (!toInt(parser.value(QStringLiteral("baud")), &o.link.baud))
        return tr("--baud: '%1' is not a number").arg(parser.value(QStringLiteral("baud")));
    const QStringList positional = parser.positionalArguments();
    const bool scan = !positional.isEmpty() && positional.first() == QLatin1String("scan");
    for (const QString &name : {QStringLiteral("parity"), QStringLiteral("bauds")}) {
        // A converter's serial side is set on the converter: nothing of ours to try.
        if (scan && o.link.isNetwork() && parser.isSet(name))
            return tr("--%1: over --tcp and --rtu-tcp the converter's serial line has its own "
                      "baud and parity (set on the converter); the scan tries only ids there")
                .arg(name);
    }
    for (const QString &part : parser.value(QStringLiteral("parity")).split(QLatin1Char(','))) {
        QSerialPort::Parity parity = QSerialPort::NoParity;
        if (!LinkSettings::parseParity(part.trimmed(), &parity))
            return tr("--parity: '%1' is not none, even or odd").arg(part);
        if (o.scanParities.contains(parity))
            return tr("--parity: '%1' is given twice").arg(part);
        o.scanParities << parity;
    }
    o.link.parity = o.scanParities.first();
    if (o.scanParities.size() > 1 && !scan)
        return tr("--parity: give one parity; several are for scan");
    for (const QString &name :
         {QStringLiteral("bauds"), QStringLiteral("ids"), QStringLiteral("probe-timeout")}) {
        if (!scan && parser.isSet(name))
            return tr("--%1 is an option of scan").arg(name);
    }
    if (parser.isSet(QStringLiteral("bauds"))) {
        for (const QString &part : parser.value(QStringLiteral("bauds")).split(QLatin1Char(','))) {
            int baud = 0;
            QStringList supported;
            for (const int b : LinkSettings::supportedBauds())
                supported << QString::number(b);
            if (!toInt(part.trimmed(), &baud) || !LinkSettings::supportedBauds().contains(baud))
                return tr("--bauds: '%1' is not one of %2")
                    .arg(part, supported.join(QStringLiteral(", ")));
            if (o.scanBauds.contains(baud))
                return tr("--bauds: %1 is given twice").arg(baud);
            o.scanBauds << baud;
        }
    } else {
        // The factory setting first: most controllers found are still at it.
        o.scanBauds = {9600, 19200, 38400, 4800};
    }
    if (parser.isSet(QStringLiteral("ids"))) {
        QString problem;
        const auto ids = IdList::parse(parser.value(QStringLiteral("ids")), &problem);
        if (!ids)
            return tr("--ids: %1").arg(problem);
        o.scanIds = *ids;
    } else {
        for (int id = 1; id <= 247; ++id)
            o.scanIds << id;
    }
    if (parser.isSet(QStringLiteral("probe-timeout")) &&
        (!toInt(parser.value(QStringLiteral("probe-timeout")), &o.probeTimeoutMs) ||
         o.probeTimeoutMs < 1 || o.probeTimeoutMs > 10000))
        return tr("--probe-timeout: '%1' is not a number of ms from 1 to 10000")
            .arg(parser.value(QStringLiteral("probe-timeout")));
    const QString stop = parser.value(QStringLiteral("stop-bits"));
    if (stop == QLatin1String("1"))
        o.link.stopBits = QSerialPort::OneStop;
    else if (stop == QLatin1String("2"))
        o.link.stopBits = QSerialPort::TwoStop;
    else
        return tr("--stop-bits: '%1' is not 1 or 2").arg(stop);
    QString idProblem;
    const auto ids = IdList::parse(parser.value(QStringLiteral("id")), &idProblem);
    if (!ids)
        return tr("--id: %1").arg(idProblem);
    o.ids = *ids;
    o.link.deviceId = ids->first();
    if (!toInt(parser.value(QStringLiteral("timeout")), &o.link.timeoutMs))
        return tr("--timeout: '%1' is not a number").arg(parser.value(QStringLiteral("timeout")));
    if (!toInt(parser.value(QStringLiteral("retries")), &o.link.retries))
        return tr("--retries: '%1' is not a number").arg(parser.value(QStringLiteral("retries")));
    if (!toInt(parser.value(QStringLiteral("answer-delay")), &o.link.answerDelayMs))
        return tr("--answer-delay: '%1' is not a number of ms")
            .arg(parser.value(QStringLiteral("answer-delay")));
    if (!toInt(parser.value(QStringLiteral("turnaround")), &o.link.turnaroundMs))
        return tr("--turnaround: '%1' is not a number of ms")
            .arg(parser.value(QStringLiteral("turnaround")));
    o.link.echo = parser.isSet(QStringLiteral("echo"));
    o.link.adaptTimeout = !parser.isSet(QStringLiteral("fixed-timeout"));
    if (o.link.echo && o.target == Target::Tcp && o.link.transport == LinkSettings::Transport::Tcp)
        return tr("--echo: Modbus TCP has no echo; it applies to --port and --rtu-tcp");
    if (parser.isSet(QStringLiteral("count")) &&
        (!toInt(parser.value(QStringLiteral("count")), &o.count) || o.count < 1))
        return tr("--count: '%1' is not a positive number")
            .arg(parser.value(QStringLiteral("count")));
    if (parser.isSet(QStringLiteral("interval")) &&
        (!toInt(parser.value(QStringLiteral("interval")), &o.intervalMs) || o.intervalMs < 0))
        return tr("--interval: '%1' is not a number of ms")
            .arg(parser.value(QStringLiteral("interval")));
    if (!LinkSettings::parseRs485(parser.value(QStringLiteral("rs485")), &o.link.rs485))
        return tr("--rs485: '%1' is not auto, kernel or rts")
            .arg(parser.value(QStringLiteral("rs485")));
    {
        const QStringList delays = parser.value(QStringLiteral("rs485-delays")).split(u',');
        if (delays.size() != 2 || !toInt(delays.at(0), &o.link.rs485DelayBeforeUs) ||
            !toInt(delays.at(1), &o.link.rs485DelayAfterUs) || o.link.rs485DelayBeforeUs < 0 ||
            o.link.rs485DelayAfterUs < 0)
            return tr("--rs485-delays: '%1' is not BEFORE,AFTER in us (e.g. 0,500)")
                .arg(parser.value(QStringLiteral("rs485-delays")));
    }
    if (parser.isSet(QStringLiteral("seconds")) &&
        (!toInt(parser.value(QStringLiteral("seconds")), &o.seconds) || o.seconds < 1))
        return tr("--seconds: '%1' is not a positive number of seconds")
            .arg(parser.value(QStringLiteral("seconds")));
    if (parser.isSet(QStringLiteral("cycles")) &&
        (!toInt(parser.value(QStringLiteral("cycles")), &o.cycles) || o.cycles < 1))
        return tr("--cycles: '%1' is not a positive number")
            .arg(parser.value(QStringLiteral("cycles")));
    o.cyclesGiven = parser.isSet(QStringLiteral("cycles"));
    o.distance = parser.value(QStringLiteral("distance"));
    o.step = parser.value(QStringLiteral("step"));
    o.accel = parser.isSet(QStringLiteral("accel"));
    o.apply = parser.isSet(QStringLiteral("apply"));
    o.checkSteps = parser.isSet(QStringLiteral("check-steps"));
    if (!toInt(parser.value(QStringLiteral("days")), &o.days) || o.days < 0)
        return tr("--days: '%1' is not a number of days").arg(parser.value(QStringLiteral("days")));
    o.logFile = parser.value(QStringLiteral("log"));
    o.events = parser.isSet(QStringLiteral("events"));
    o.at = parser.value(QStringLiteral("at"));
    o.diffFrom = parser.value(QStringLiteral("diff"));
    o.entry = parser.value(QStringLiteral("entry"));
    o.profile = parser.value(QStringLiteral("profile"));
    o.mapFile = parser.value(QStringLiteral("map"));
    o.json = parser.isSet(QStringLiteral("json"));
    o.verbose = parser.isSet(QStringLiteral("verbose"));
    o.yes = parser.isSet(QStringLiteral("yes"));
    o.saveToFlash = parser.isSet(QStringLiteral("save-to-flash"));
    o.wait = parser.isSet(QStringLiteral("wait"));
    o.includeLink = parser.isSet(QStringLiteral("include-link"));
    o.noBackup = parser.isSet(QStringLiteral("no-backup"));
    o.name = parser.value(QStringLiteral("name"));
    o.notes = parser.value(QStringLiteral("notes"));
    o.from = parser.value(QStringLiteral("from"));
    o.by = parser.value(QStringLiteral("by"));
    o.to = parser.value(QStringLiteral("to"));
    o.simReset = parser.isSet(QStringLiteral("sim-reset"));
    if (positional.isEmpty() && o.simReset) {
        *out = o; // --sim-reset alone: nothing else to do
        return {};
    }
    if (positional.isEmpty())
        return tr("no command given (%1)").arg(CtlRunner::commandNames());
    o.command = positional.first();
    o.arguments = positional.mid(1);
    // --to is a position for move and a device id for assign-id.
    if (o.command == QLatin1String("assign-id") && parser.isSet(QStringLiteral("to")) &&
        (!toInt(parser.value(QStringLiteral("to")), &o.assignTo) || o.assignTo < 1 ||
         o.assignTo > 255))
        return tr("--to: '%1' is not a device id 1-255").arg(parser.value(QStringLiteral("to")));
    if (o.target != Target::None) {
        if (o.target != Target::Sim) {
            if (const QString problem = o.link.validate(); !problem.isEmpty())
                return problem;
        } else if (!LinkSettings::supportedBauds().contains(o.link.baud)) {
            return tr("--baud: '%1' is not 4800, 9600, 19200 or 38400").arg(o.link.baud);
        }
    }
    *out = o;
    return {};
}

} // namespace stepcom
