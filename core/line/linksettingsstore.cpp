#include "line/linksettingsstore.h"

#include <QSettings>

namespace stepcom::LinkSettingsStore {

LinkSettings read(QSettings &settings)
{
    const auto value = [&settings](const char *key, const QVariant &fallback) {
        return settings.value(QLatin1String(key), fallback);
    };
    LinkSettings s;
    const QString transport = value("transport", {}).toString();
    s.transport = transport == QLatin1String("tcp")       ? LinkSettings::Transport::Tcp
                  : transport == QLatin1String("rtu-tcp") ? LinkSettings::Transport::RtuTcp
                                                          : LinkSettings::Transport::Rtu;
    s.portName = value("port", s.portName).toString();
    s.baud = value("baud", s.baud).toInt();
    LinkSettings::parseParity(value("parity", {}).toString(), &s.parity); // keeps none if unknown
    s.stopBits = value("stopBits", 1).toInt() == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop;
    s.host = value("host", s.host).toString();
    s.tcpPort = value("tcpPort", s.tcpPort).toInt();
    s.deviceId = value("deviceId", s.deviceId).toInt();
    s.timeoutMs = value("timeoutMs", s.timeoutMs).toInt();
    s.retries = value("retries", s.retries).toInt();
    s.answerDelayMs = value("answerDelayMs", s.answerDelayMs).toInt();
    s.turnaroundMs = value("turnaroundMs", s.turnaroundMs).toInt();
    s.echo = value("echo", s.echo).toBool();
    LinkSettings::parseRs485(value("rs485", {}).toString(), &s.rs485); // keeps auto if unknown
    s.rs485DelayBeforeUs = value("rs485DelayBeforeUs", 0).toInt();
    s.rs485DelayAfterUs = value("rs485DelayAfterUs", 0).toInt();
    s.adaptTimeout = value("adaptTimeout", s.adaptTimeout).toBool();
    return s;
}

void write(QSettings &settings, const LinkSettings &s)
{
    const auto set = [&settings](const char *key, const QVariant &v) {
        settings.setValue(QLatin1String(key), v);
    };
    set("transport", s.transport == LinkSettings::Transport::Tcp      ? QStringLiteral("tcp")
                     : s.transport == LinkSettings::Transport::RtuTcp ? QStringLiteral("rtu-tcp")
                                                                      : QStringLiteral("serial"));
    set("port", s.portName);
    set("baud", s.baud);
    set("parity", LinkSettings::parityName(s.parity));
    set("stopBits", s.stopBits == QSerialPort::TwoStop ? 2 : 1);
    set("host", s.host);
    set("tcpPort", s.tcpPort);
    set("deviceId", s.deviceId);
    set("timeoutMs", s.timeoutMs);
    set("retries", s.retries);
    set("answerDelayMs", s.answerDelayMs);
    set("turnaroundMs", s.turnaroundMs);
    set("echo", s.echo);
    set("rs485", LinkSettings::rs485Name(s.rs485));
    set("rs485DelayBeforeUs", s.rs485DelayBeforeUs);
    set("rs485DelayAfterUs", s.rs485DelayAfterUs);
    set("adaptTimeout", s.adaptTimeout);
}

} // namespace stepcom::LinkSettingsStore
