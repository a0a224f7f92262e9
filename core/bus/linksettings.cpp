#include "bus/linksettings.h"

#include <QCoreApplication>

namespace stepcom {

namespace {
QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::LinkSettings", text);
}
} // namespace

const QList<int> &LinkSettings::supportedBauds()
{
    static const QList<int> bauds{4800, 9600, 19200, 38400};
    return bauds;
}

QString LinkSettings::parityName(QSerialPort::Parity parity)
{
    switch (parity) {
    case QSerialPort::EvenParity:
        return QStringLiteral("even");
    case QSerialPort::OddParity:
        return QStringLiteral("odd");
    default:
        return QStringLiteral("none");
    }
}

bool LinkSettings::parseHostPort(const QString &text, int defaultPort, QString *host, int *port)
{
    const QString t = text.trimmed();
    const qsizetype colon = t.lastIndexOf(QLatin1Char(':'));
    if (colon < 0) {
        if (defaultPort <= 0 || t.isEmpty())
            return false;
        *host = t;
        *port = defaultPort;
        return true;
    }
    bool ok = false;
    const int p = t.mid(colon + 1).toInt(&ok);
    if (colon == 0 || !ok || p < 1 || p > 65535)
        return false;
    *host = t.left(colon);
    *port = p;
    return true;
}

bool LinkSettings::parseParity(const QString &text, QSerialPort::Parity *parity)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("none") || t == QLatin1String("n"))
        *parity = QSerialPort::NoParity;
    else if (t == QLatin1String("even") || t == QLatin1String("e"))
        *parity = QSerialPort::EvenParity;
    else if (t == QLatin1String("odd") || t == QLatin1String("o"))
        *parity = QSerialPort::OddParity;
    else
        return false;
    return true;
}

QString LinkSettings::describe() const
{
    if (transport == Transport::Tcp)
        return tr("%1:%2 · id %3").arg(host).arg(tcpPort).arg(deviceId);
    if (transport == Transport::RtuTcp)
        return tr("%1:%2 (RTU over TCP) · id %3").arg(host).arg(tcpPort).arg(deviceId);
    const QChar p = parity == QSerialPort::EvenParity  ? QLatin1Char('E')
                    : parity == QSerialPort::OddParity ? QLatin1Char('O')
                                                       : QLatin1Char('N');
    return tr("%1 · %2 8%3%4 · id %5")
        .arg(portName)
        .arg(baud)
        .arg(p)
        .arg(stopBits == QSerialPort::TwoStop ? 2 : 1)
        .arg(deviceId);
}

QString LinkSettings::validate() const
{
    if (deviceId < 1 || deviceId > 255)
        return tr("device id %1 is outside 1-255").arg(deviceId);
    if (timeoutMs < 20 || timeoutMs > 60000)
        return tr("timeout %1 ms is outside 20-60000 ms").arg(timeoutMs);
    if (retries < 0 || retries > 10)
        return tr("retries %1 is outside 0-10").arg(retries);
    if (answerDelayMs < 0 || answerDelayMs > 1000)
        return tr("answer delay %1 ms is outside 0-1000 ms").arg(answerDelayMs);
    if (turnaroundMs < 0 || turnaroundMs > 1000)
        return tr("turnaround %1 ms is outside 0-1000 ms").arg(turnaroundMs);
    if (rs485DelayBeforeUs < 0 || rs485DelayBeforeUs > 100000 || rs485DelayAfterUs < 0 ||
        rs485DelayAfterUs > 100000)
        return tr("RS-485 delays %1/%2 us are outside 0-100000 us")
            .arg(rs485DelayBeforeUs)
            .arg(rs485DelayAfterUs);
    if (answerDelayMs >= timeoutMs)
        return tr("the answer delay (%1 ms) must be shorter than the timeout (%2 ms)")
            .arg(answerDelayMs)
            .arg(timeoutMs);
    if (isNetwork()) {
        if (host.trimmed().isEmpty())
            return tr("no host given");
        if (tcpPort < 1 || tcpPort > 65535)
            return tr("TCP port %1 is outside 1-65535").arg(tcpPort);
        return {};
    }
    if (portName.trimmed().isEmpty())
        return tr("no serial port given");
    if (!supportedBauds().contains(baud))
        return tr("baud %1 is not one of 4800, 9600, 19200, 38400").arg(baud);
    if (stopBits != QSerialPort::OneStop && stopBits != QSerialPort::TwoStop)
        return tr("stop bits must be 1 or 2");
    return {};
}

double LinkSettings::charTimeMs() const
{
    if (isNetwork() || baud <= 0)
        return 0.0;
    return 10000.0 / baud;
}

bool operator==(const LinkSettings &a, const LinkSettings &b)
{
    return a.transport == b.transport && a.portName == b.portName && a.baud == b.baud &&
           a.parity == b.parity && a.stopBits == b.stopBits && a.host == b.host &&
           a.tcpPort == b.tcpPort && a.deviceId == b.deviceId && a.timeoutMs == b.timeoutMs &&
           a.retries == b.retries && a.answerDelayMs == b.answerDelayMs && a.echo == b.echo &&
           a.turnaroundMs == b.turnaroundMs && a.adaptTimeout == b.adaptTimeout &&
           a.rs485 == b.rs485 && a.rs485DelayBeforeUs == b.rs485DelayBeforeUs &&
           a.rs485DelayAfterUs == b.rs485DelayAfterUs;
}

QString LinkSettings::rs485Name(Rs485 mode)
{
    switch (mode) {
    case Rs485::Kernel:
        return QStringLiteral("kernel");
    case Rs485::Rts:
        return QStringLiteral("rts");
    case Rs485::Auto:
        break;
    }
    return QStringLiteral("auto");
}

bool LinkSettings::parseRs485(const QString &text, Rs485 *mode)
{
    for (const Rs485 m : {Rs485::Auto, Rs485::Kernel, Rs485::Rts}) {
        if (text.trimmed().compare(rs485Name(m), Qt::CaseInsensitive) == 0) {
            *mode = m;
            return true;
        }
    }
    return false;
}

} // namespace stepcom
