#include "sim/host/simcommandline.h"

#include "session/idlist.h"
#include "sim/model/machinefile.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>

namespace stepcom {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::SimCommandLine", text);
}

bool toInt(const QString &text, int min, int max, int *out)
{
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok || v < min || v > max)
        return false;
    *out = v;
    return true;
}

} // namespace

void SimCommandLine::addOptions(QCommandLineParser &p)
{
    const QString n = tr("N");
    const QString ms = tr("MS");
    const QString share = tr("SHARE");
    p.addOption({QStringLiteral("pty"), tr("Serve Modbus RTU on a new pseudo-terminal (Unix).")});
    p.addOption(
        {QStringLiteral("link"), tr("Make PATH a symlink to the pseudo-terminal."), tr("PATH")});
    p.addOption({QStringLiteral("serial"),
                 tr("Serve Modbus RTU on the serial PORT (e.g. COM10, one end of a com0com "
                    "pair, or /dev/ttyUSB1) at the device's baud rate, 8N1."),
                 tr("PORT")});
    p.addOption({QStringLiteral("line"),
                 tr("Serve a line of N pseudo-terminals: every byte one program sends reaches "
                    "the others and the controller, as on RS-485 (a master and a listener)."),
                 n});
    p.addOption({QStringLiteral("line-echo"),
                 tr("With --line: the parties numbered in LIST (e.g. 2 or 1,3) hear every byte "
                    "they send back first, as through an adapter without echo suppression."),
                 tr("LIST")});
    p.addOption({QStringLiteral("no-baud-check"),
                 tr("Answer whatever baud rate the client set (by default a client whose baud "
                    "differs from register 40213 gets silence, as on a real line).")});
    p.addOption({QStringLiteral("tcp"),
                 tr("Serve Modbus TCP on [HOST:]PORT (127.0.0.1 unless --listen-any; port 0 "
                    "picks a free one)."),
                 tr("[HOST:]PORT")});
    p.addOption({QStringLiteral("rtu-tcp"),
                 tr("Serve Modbus RTU frames over plain TCP on [HOST:]PORT, as a transparent "
                    "RS-485/Ethernet converter passes them on (port 0 picks a free one)."),
                 tr("[HOST:]PORT")});
    p.addOption({QStringLiteral("echo"),
                 tr("Send every byte the client sends straight back to it first, as a "
                    "half-duplex USB-RS485 adapter without echo suppression does (pty and "
                    "--rtu-tcp).")});
    p.addOption({QStringLiteral("listen-any"), tr("Listen for TCP on every interface.")});
    p.addOption({{QStringLiteral("refuse-gaps"), QStringLiteral("strict-reads")},
                 tr("Refuse a read that covers a reserved register (exception 02): only the "
                    "manual's listed registers can be read.")});
    p.addOption({QStringLiteral("lacks"),
                 tr("Be a firmware without this listed register (a key or a number such as "
                    "40110): reads and writes covering it get exception 02. Repeatable."),
                 tr("REGISTER")});
    p.addOption({QStringLiteral("id"), tr("Device id 1-255 (overrides the saved one)."), n});
    p.addOption({QStringLiteral("ids"),
                 tr("Several controllers on the one port, one per id (e.g. 1,2,3 or 1-3); a "
                    "repeated id is a collision: both answer at once."),
                 tr("IDS")});
    p.addOption({QStringLiteral("state"),
                 tr("The simulator's flash: saved parameters are loaded from and saved to FILE."),
                 tr("FILE")});
    p.addOption({QStringLiteral("map"),
                 tr("Use the register map FILE instead of the built-in one."), tr("FILE")});
    p.addOption({QStringLiteral("answer-delay"),
                 tr("The controller's answer time: its answer leaves MS after a request "
                    "(default: the map's, 35, as the manual asks; other firmware answers in "
                    "2-20 ms; 0: as fast as it can)."),
                 ms});
    p.addOption({QStringLiteral("slow-coil"),
                 tr("Coil PLC (e.g. 96, save) acts at once but answers MS later, as firmware "
                    "writing its flash first. Repeatable."),
                 tr("PLC:MS")});
    p.addOption({QStringLiteral("power-cycle"),
                 tr("Switch the 24 V off AT seconds after start for OFF seconds: silence, then "
                    "the saved parameters, positions 0, nothing homed. Repeatable."),
                 tr("AT:OFF")});
    p.addOption({QStringLiteral("wire-baud"),
                 tr("Add the bytes' time on a line at N baud to every answer."), n});
    p.addOption({QStringLiteral("drop"), tr("Drop a SHARE (0-1 or %) of the answers."), share});
    p.addOption(
        {QStringLiteral("corrupt-crc"), tr("Break the CRC of a SHARE of the answers."), share});
    p.addOption(
        {QStringLiteral("late"), tr("Answer a SHARE of the requests MS later."), tr("SHARE:MS")});
    p.addOption({QStringLiteral("exception"),
                 tr("Answer a SHARE of the requests with exception CODE instead."),
                 tr("SHARE:CODE")});
    p.addOption({QStringLiteral("hangup-after"),
                 tr("Hang up the port after every N answers (it comes back, see --hangup-pause)."),
                 n});
    p.addOption({QStringLiteral("hangup-pause"),
                 tr("How long a hung-up port stays away (default 1000)."), ms});
    p.addOption({QStringLiteral("seed"), tr("Seed of the fault dice (default 1)."), n});
    p.addOption({QStringLiteral("input"),
                 tr("Set an input at start: INn=on|off|pulse (repeatable)."), tr("INn=STATE")});
    p.addOption({QStringLiteral("machine"),
                 tr("The machine's mechanics from FILE (format stepcom-sim-machine): motor "
                    "limits (stalls), backlash, switches, hard stops, wiring."),
                 tr("FILE")});
    p.addOption({QStringLiteral("truth-out"),
                 tr("Keep what really happened (count, rotor, carriage, lost steps, switches) "
                    "as JSON in FILE, rewritten when it changes (at most every 50 ms)."),
                 tr("FILE")});
    p.addOption({QStringLiteral("travel"),
                 tr("Travel of each axis between its limit switches (default 200)."), tr("MM")});
}

bool SimCommandLine::parseTcp(const QString &text, QHostAddress *address, quint16 *port,
                              QString *error)
{
    QString host;
    QString portText = text;
    const int colon = int(text.lastIndexOf(QLatin1Char(':')));
    if (colon >= 0) {
        host = text.left(colon);
        portText = text.mid(colon + 1);
        if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
            host = host.mid(1, host.size() - 2);
    }
    int p = 0;
    QHostAddress a;
    if (!toInt(portText, 0, 65535, &p) || (!host.isEmpty() && !a.setAddress(host))) {
        if (error)
            *error = tr("--tcp: '%1' is not [HOST:]PORT").arg(text);
        return false;
    }
    if (!host.isEmpty())
        *address = a;
    *port = quint16(p);
    return true;
}

std::optional<int> SimCommandLine::parseSeconds(const QString &text, int minMs, int maxMs)
{
    bool ok = false;
    const double seconds = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(seconds))
        return std::nullopt;
    const double ms = std::round(seconds * 1000.0);
    if (ms < minMs || ms > maxMs)
        return std::nullopt;
    return int(ms);
}

std::optional<std::pair<int, int>> SimCommandLine::parsePowerCycle(const QString &text,
                                                                   QString *error)
{
    const QStringList parts = text.split(QLatin1Char(':'));
    const auto at = parseSeconds(parts.value(0), 0, 86400 * 1000);
    const auto off = parseSeconds(parts.value(1), 1, 3600 * 1000);
    if (parts.size() != 2 || !at || !off) {
        if (error)
            *error = tr("--power-cycle: '%1' is not AT:OFF (seconds after start, 0-86400, and "
                        "seconds off, up to 3600; e.g. 10:3)")
                         .arg(text);
        return std::nullopt;
    }
    return std::make_pair(*at, *off);
}

std::optional<std::pair<int, int>>
SimCommandLine::parseSlowCoil(const RegisterMap &map, const QString &text, QString *error)
{
    const QStringList parts = text.split(QLatin1Char(':'));
    int plc = 0;
    int ms = 0;
    if (parts.size() != 2 || !toInt(parts.at(0), 1, 0x10000, &plc) ||
        !toInt(parts.at(1), 0, 600000, &ms)) {
        if (error)
            *error = tr("--slow-coil: '%1' is not PLC:MS (a coil number such as 96 and "
                        "milliseconds 0-600000)")
                         .arg(text);
        return std::nullopt;
    }
    if (!map.coilAt(quint16(plc - 1))) {
        if (error)
            *error = tr("--slow-coil: '%1': %2 is no coil of the map").arg(text).arg(plc);
        return std::nullopt;
    }
    return std::make_pair(plc, ms);
}

std::optional<std::pair<int, SimMachine::InputForce>>
SimCommandLine::parseInput(const QString &text, QString *error)
{
    static const QRegularExpression re(QStringLiteral("^(?:in)?(\\d+)=(on|off|pulse|1|0)$"),
                                       QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text.trimmed());
    if (!m.hasMatch()) {
        if (error)
            *error = tr("--input: '%1' is not INn=on|off|pulse").arg(text);
        return std::nullopt;
    }
    const QString state = m.captured(2).toLower();
    SimMachine::InputForce force = SimMachine::InputForce::Pulse;
    if (state == QLatin1String("on") || state == QLatin1String("1"))
        force = SimMachine::InputForce::On;
    else if (state == QLatin1String("off") || state == QLatin1String("0"))
        force = SimMachine::InputForce::Off;
    return std::make_pair(m.captured(1).toInt(), force);
}

bool SimCommandLine::toOptions(const QCommandLineParser &p, SimOptions *o, QString *error)
{
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    auto intOption = [&](const char *name, int min, int max, int *out) {
        const QString key = QLatin1String(name);
        if (!p.isSet(key))
            return true;
        if (toInt(p.value(key), min, max, out))
            return true;
        return fail(tr("--%1: '%2' must be a whole number from %3 to %4")
                        .arg(key, p.value(key))
                        .arg(min)
                        .arg(max));
    };
    if (p.isSet(QStringLiteral("map"))) {
        QStringList errors;
        const auto map = RegisterMap::loadFile(p.value(QStringLiteral("map")), &errors);
        if (!map)
            return fail(errors.join(QLatin1Char('\n')));
        o->map = *map;
    }
    o->rtu = p.isSet(QStringLiteral("pty")) || p.isSet(QStringLiteral("link"));
    o->linkPath = p.value(QStringLiteral("link"));
    o->checkBaud = !p.isSet(QStringLiteral("no-baud-check"));
    if (p.isSet(QStringLiteral("line"))) {
        if (!toInt(p.value(QStringLiteral("line")), 1, 32, &o->line))
            return fail(tr("--line: '%1' is not a number of ptys from 1 to 32")
                            .arg(p.value(QStringLiteral("line"))));
        o->rtu = true;
    }
    if (p.isSet(QStringLiteral("line-echo"))) {
        if (o->line == 0)
            return fail(tr("--line-echo needs --line N"));
        for (const QString &part : p.value(QStringLiteral("line-echo")).split(u',')) {
            int party = 0;
            if (!toInt(part.trimmed(), 1, o->line, &party))
                return fail(tr("--line-echo: '%1' is not a party of the line (1 to %2)")
                                .arg(part.trimmed(), QString::number(o->line)));
            o->lineEcho << party;
        }
    }
    o->serialPort = p.value(QStringLiteral("serial"));
    if (p.isSet(QStringLiteral("serial")) && o->serialPort.isEmpty())
        return fail(tr("--serial: no port given"));
    if (!o->serialPort.isEmpty() && o->rtu)
        return fail(tr("--serial: give either --serial or --pty/--link, not both"));
    if (!o->serialPort.isEmpty() && p.isSet(QStringLiteral("corrupt-crc")))
        return fail(tr("--corrupt-crc works on the pseudo-terminal only, not with --serial"));
    if (p.isSet(QStringLiteral("tcp"))) {
        o->tcp = true;
        if (!parseTcp(p.value(QStringLiteral("tcp")), &o->tcpAddress, &o->tcpPort, error))
            return false;
    }
    if (p.isSet(QStringLiteral("rtu-tcp"))) {
        o->rtuTcp = true;
        QHostAddress address = o->tcpAddress;
        if (!parseTcp(p.value(QStringLiteral("rtu-tcp")), &address, &o->rtuTcpPort, error)) {
            if (error)
                error->replace(QStringLiteral("--tcp"), QStringLiteral("--rtu-tcp"));
            return false;
        }
        if (p.isSet(QStringLiteral("tcp")) && address != o->tcpAddress)
            return fail(tr("--rtu-tcp and --tcp must listen on the same host"));
        o->tcpAddress = address;
    }
    o->echo = p.isSet(QStringLiteral("echo"));
    if (o->echo && !o->serialPort.isEmpty())
        return fail(tr("--echo works on the pseudo-terminal and --rtu-tcp, not with --serial"));
    if (p.isSet(QStringLiteral("listen-any")))
        o->tcpAddress = QHostAddress(QHostAddress::Any);
    o->statePath = p.value(QStringLiteral("state"));
    o->strictReads = p.isSet(QStringLiteral("refuse-gaps"));
    o->lacks = p.values(QStringLiteral("lacks"));
    int seed = int(o->faults.seed);
    if (!intOption("id", 1, 255, &o->deviceId) ||
        !intOption("answer-delay", 0, 60000, &o->answerDelayMs) ||
        !intOption("wire-baud", 1, 10000000, &o->wireBaud) ||
        !intOption("hangup-after", 0, 1000000, &o->faults.hangupAfter) ||
        !intOption("hangup-pause", 0, 600000, &o->faults.hangupPauseMs) ||
        !intOption("seed", 0, std::numeric_limits<int>::max(), &seed))
        return false;
    o->faults.seed = quint32(seed);
    if (p.isSet(QStringLiteral("ids"))) {
        if (p.isSet(QStringLiteral("id")))
            return fail(tr("--ids: give either --id or --ids, not both"));
        QString why;
        const auto ids = IdList::parse(p.value(QStringLiteral("ids")), &why, true);
        if (!ids)
            return fail(QStringLiteral("--ids: %1").arg(why));
        o->ids = *ids;
    }
    for (const char *name : {"drop", "corrupt-crc"}) {
        const QString key = QLatin1String(name);
        if (!p.isSet(key))
            continue;
        QString why;
        const auto share = FaultInjector::parseShare(p.value(key), &why);
        if (!share)
            return fail(QStringLiteral("--%1: %2").arg(key, why));
        (key == QLatin1String("drop") ? o->faults.drop : o->faults.corruptCrc) = *share;
    }
    QString why;
    if (p.isSet(QStringLiteral("late")) &&
        !FaultInjector::parseShareAndValue(p.value(QStringLiteral("late")), &o->faults.late,
                                           &o->faults.lateMs, &why))
        return fail(QStringLiteral("--late: %1").arg(why));
    if (p.isSet(QStringLiteral("exception"))) {
        if (!FaultInjector::parseShareAndValue(p.value(QStringLiteral("exception")),
                                               &o->faults.exception, &o->faults.exceptionCode,
                                               &why))
            return fail(QStringLiteral("--exception: %1").arg(why));
        if (o->faults.exceptionCode < 1 || o->faults.exceptionCode > 255)
            return fail(tr("--exception: the code must be 1-255"));
    }
    if (p.isSet(QStringLiteral("travel"))) {
        bool ok = false;
        o->travel = p.value(QStringLiteral("travel")).toDouble(&ok);
        if (!ok || o->travel <= 0)
            return fail(tr("--travel: '%1' must be a positive distance")
                            .arg(p.value(QStringLiteral("travel"))));
        o->startPosition = std::min(o->startPosition, o->travel / 4);
    }
    if (p.isSet(QStringLiteral("machine"))) {
        const auto machine = MachineFile::load(p.value(QStringLiteral("machine")), error);
        if (!machine)
            return false;
        o->machine = *machine;
    }
    o->truthOut = p.value(QStringLiteral("truth-out"));
    if (p.isSet(QStringLiteral("truth-out")) && o->truthOut.isEmpty())
        return fail(tr("--truth-out: no file given"));
    for (const QString &text : p.values(QStringLiteral("input"))) {
        const auto input = parseInput(text, error);
        if (!input)
            return false;
        o->inputs.append(*input);
    }
    for (const QString &text : p.values(QStringLiteral("slow-coil"))) {
        const auto slow = parseSlowCoil(o->map, text, error);
        if (!slow)
            return false;
        o->slowCoils.insert(slow->first, slow->second);
    }
    for (const QString &text : p.values(QStringLiteral("power-cycle"))) {
        const auto cycle = parsePowerCycle(text, error);
        if (!cycle)
            return false;
        o->powerCycles.append(*cycle);
    }
    return true;
}

} // namespace stepcom
