#include "sim/host/simconsole.h"

#include "sim/host/simcommandline.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QRegularExpression>

namespace stepcom {

SimConsole::SimConsole(SimHost *host)
    : m_host(host)
{}

QString SimConsole::help()
{
    return tr(
        "Commands:\n"
        "  status                 motors, inputs, outputs, link and traffic\n"
        "  in N on|off|pulse      drive input N by hand (pulse: on for 50 ms)\n"
        "  get KEY                show a register (e.g. get motor1.position)\n"
        "  set KEY VALUE          write a parameter as a client would (e.g. set motor1.speed 600)\n"
        "  do COMMAND             run a coil command (e.g. do motor1.move, do estop)\n"
        "  place N MM             put carriage N at MM on its travel by hand\n"
        "  hangup [MS]            hang up the port; it comes back after MS\n"
        "  power-cycle [S] [id N] switch the 24 V off for S seconds (default 3), every\n"
        "                         controller or the one with id N; it comes back with what\n"
        "                         was saved, positions 0, nothing homed\n"
        "  help                   this text\n"
        "  quit                   end the simulator");
}

SimConsole::Result SimConsole::execute(const QString &line)
{
    static const QRegularExpression space(QStringLiteral("\\s+"));
    const QStringList words = line.trimmed().split(space, Qt::SkipEmptyParts);
    if (words.isEmpty())
        return {};
    const QString cmd = words.first().toLower();
    const QStringList args = words.mid(1);
    if (cmd == QLatin1String("help") || cmd == QLatin1String("?"))
        return {help()};
    if (cmd == QLatin1String("quit") || cmd == QLatin1String("exit"))
        return {QString(), true, true};
    if (!m_host->device())
        return {tr("the simulator is not running"), false};
    if (cmd == QLatin1String("status"))
        return status();
    if (cmd == QLatin1String("in") || cmd == QLatin1String("input"))
        return input(args);
    if (cmd == QLatin1String("get"))
        return get(args);
    if (cmd == QLatin1String("set"))
        return set(args);
    if (cmd == QLatin1String("do"))
        return run(args);
    if (cmd == QLatin1String("place"))
        return place(args);
    if (cmd == QLatin1String("power-cycle") || cmd == QLatin1String("powercycle"))
        return powerCycle(args);
    if (cmd == QLatin1String("hangup")) {
        bool ok = true;
        const int ms = args.isEmpty() ? -1 : args.first().toInt(&ok);
        if (!ok || ms < -1)
            return {tr("usage: hangup [MS]"), false};
        m_host->hangUp(ms);
        return {tr("hanging up")};
    }
    return {tr("unknown command '%1' (try help)").arg(words.first()), false};
}

SimConsole::Result SimConsole::input(const QStringList &args)
{
    if (args.size() != 2)
        return {tr("usage: in N on|off|pulse"), false};
    QString error;
    const auto parsed =
        SimCommandLine::parseInput(args.at(0) + QLatin1Char('=') + args.at(1), &error);
    SimDevice *d = m_host->device();
    if (!parsed || parsed->first < 1 || parsed->first > d->inputCount())
        return {tr("usage: in N on|off|pulse, N from 1 to %1").arg(d->inputCount()), false};
    d->setInput(parsed->first, parsed->second);
    return {
        tr("IN%1 is %2").arg(parsed->first).arg(d->input(parsed->first) ? tr("on") : tr("off"))};
}

SimConsole::Result SimConsole::get(const QStringList &args)
{
    if (args.size() != 1)
        return {tr("usage: get KEY"), false};
    SimDevice *d = m_host->device();
    const Parameter *p = d->map().find(args.first());
    const auto raw = d->value(args.first());
    if (!p || !raw)
        return {tr("%1: no such register").arg(args.first()), false};
    return {QStringLiteral("%1 = %2").arg(p->key, p->displayRaw(*raw))};
}

SimConsole::Result SimConsole::set(const QStringList &args)
{
    if (args.size() != 2)
        return {tr("usage: set KEY VALUE"), false};
    SimDevice *d = m_host->device();
    const Parameter *p = d->map().find(args.first());
    if (!p)
        return {tr("%1: no such register").arg(args.first()), false};
    QString error;
    const auto raw = p->parse(args.at(1), &error);
    if (!raw || !d->setValue(p->key, *raw, &error))
        return {error, false};
    return {QStringLiteral("%1 = %2").arg(p->key, p->displayRaw(*raw))};
}

SimConsole::Result SimConsole::run(const QStringList &args)
{
    if (args.size() != 1)
        return {tr("usage: do COMMAND"), false};
    QString error;
    if (!m_host->device()->command(args.first(), &error))
        return {error, false};
    return {tr("done: %1").arg(args.first())};
}

SimConsole::Result SimConsole::place(const QStringList &args)
{
    bool okMotor = false;
    bool okPos = false;
    const int motor = args.value(0).toInt(&okMotor);
    const double mm = args.value(1).toDouble(&okPos);
    SimDevice *d = m_host->device();
    if (args.size() != 2 || !okMotor || !okPos || motor < 1 || motor > d->motorCount())
        return {tr("usage: place N MM"), false};
    d->setMachinePosition(motor, mm);
    return {tr("carriage %1 at %2").arg(motor).arg(d->machinePosition(motor), 0, 'f', 2)};
}

SimConsole::Result SimConsole::powerCycle(const QStringList &args)
{
    const Result usage{tr("usage: power-cycle [SECONDS] [id N]"), false};
    QStringList rest = args;
    int ms = 3000;
    if (!rest.isEmpty() && rest.first().toLower() != QLatin1String("id")) {
        const auto seconds = SimCommandLine::parseSeconds(rest.takeFirst(), 1, 3600 * 1000);
        if (!seconds)
            return usage;
        ms = *seconds;
    }
    int id = 0;
    if (!rest.isEmpty()) {
        bool ok = false;
        id = rest.value(1).toInt(&ok);
        if (rest.size() != 2 || rest.first().toLower() != QLatin1String("id") || !ok || id < 1 ||
            id > 255)
            return usage;
    }
    if (!m_host->powerCycle(ms, id))
        return {tr("no controller has id %1").arg(id), false};
    const QString seconds = QString::number(ms / 1000.0);
    if (id != 0)
        return {tr("id %1: 24 V off for %2 s").arg(id).arg(seconds)};
    return {tr("24 V off for %1 s").arg(seconds)};
}

SimConsole::Result SimConsole::status() const
{
    QStringList lines;
    lines << m_host->device()->statusText();
    if (m_host->options().rtu)
        lines << tr("rtu: %1").arg(m_host->rtuPath().isEmpty() ? tr("(hung up)")
                                                               : m_host->rtuPath());
    if (m_host->options().tcp)
        lines << tr("tcp: %1:%2").arg(m_host->tcpAddress().toString()).arg(m_host->tcpPort());
    const SimHost::Stats s = m_host->stats();
    lines << tr("requests %1, answers %2 (exceptions %3), dropped %4, bad CRC %5, late %6, "
                "wrong baud %7")
                 .arg(s.requests)
                 .arg(s.answers)
                 .arg(s.exceptions)
                 .arg(s.dropped)
                 .arg(s.corrupted)
                 .arg(s.late)
                 .arg(s.wrongBaud);
    return {lines.join(QLatin1Char('\n'))};
}

} // namespace stepcom
