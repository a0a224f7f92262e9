#include "ctllinkadvice.h"

#include "map/parameter.h"

namespace stepcom {

QString CtlLinkAdvice::nextOptions(const CtlOptions &options, int deviceId, int baud)
{
    QStringList parts;
    const LinkSettings &link = options.link;
    switch (options.target) {
    case CtlOptions::Target::Port:
        parts << QStringLiteral("--port") << link.portName;
        break;
    case CtlOptions::Target::Tcp:
        parts << (link.transport == LinkSettings::Transport::RtuTcp ? QStringLiteral("--rtu-tcp")
                                                                    : QStringLiteral("--tcp"))
              << QStringLiteral("%1:%2").arg(link.host).arg(link.tcpPort);
        break;
    case CtlOptions::Target::Sim:
        parts << QStringLiteral("--sim");
        break;
    case CtlOptions::Target::None:
        break;
    }
    // A converter's serial side has its own baud: ours is only for a serial line.
    if (!link.isNetwork() && baud > 0)
        parts << QStringLiteral("--baud") << QString::number(baud);
    if (!link.isNetwork() && link.parity != QSerialPort::NoParity)
        parts << QStringLiteral("--parity") << LinkSettings::parityName(link.parity);
    parts << QStringLiteral("--id") << QString::number(deviceId);
    return parts.join(QLatin1Char(' '));
}

QStringList CtlLinkAdvice::notes(const CtlOptions &options, int newId, int newBaud, bool saved)
{
    if (newId <= 0 && newBaud <= 0)
        return {};
    const int id = newId > 0 ? newId : options.link.deviceId;
    const int baud = newBaud > 0 ? newBaud : options.link.baud;
    QStringList lines;
    if (!saved) {
        lines << (options.target == CtlOptions::Target::Sim
                      ? tr("not saved to flash: the built-in simulator starts its next run with "
                           "the id and baud it saved (add --save-to-flash to keep them)")
                      : tr("not saved to flash: after the next power-off the controller answers "
                           "at the id and baud it saved before (add --save-to-flash to keep "
                           "them)"));
    }
    if (newBaud > 0 && options.link.isNetwork())
        lines << tr("the controller now speaks %1 baud on its RS-485 side: set the converter's "
                    "(gateway's) serial side to %1 baud too, or it no longer reaches the "
                    "controller")
                     .arg(newBaud);
    lines << tr("next commands: stepcomctl %1 ...").arg(nextOptions(options, id, baud));
    return lines;
}

QStringList CtlLinkAdvice::notes(const CtlOptions &options, const QList<ParameterWrite> &writes,
                                 bool saved)
{
    int id = 0;
    int baud = 0;
    for (const ParameterWrite &w : writes) {
        if (w.parameter->key == QLatin1String("device.id"))
            id = int(w.raw);
        else if (w.parameter->key == QLatin1String("device.baud"))
            baud = int(w.raw);
    }
    return notes(options, id, baud, saved);
}

} // namespace stepcom
