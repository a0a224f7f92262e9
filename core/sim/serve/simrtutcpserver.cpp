#include "sim/serve/simrtutcpserver.h"

#include "bus/rtuframe.h"
#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QDataStream>
#include <QModbusPdu>
#include <QTcpSocket>

namespace stepcom {

SimRtuTcpServer::SimRtuTcpServer(SimResponder *responder, bool echo, QObject *parent)
    : SimTcpListener(responder, Busy::OneAtATime, parent)
    , m_echo(echo)
{}

QString SimRtuTcpServer::listenError(const QHostAddress &address, quint16 port,
                                     const QString &reason) const
{
    return tr("cannot listen for RTU over TCP on %1:%2: %3")
        .arg(address.toString())
        .arg(port)
        .arg(reason);
}

void SimRtuTcpServer::heard(QTcpSocket *socket, const QByteArray &bytes)
{
    if (m_echo)
        socket->write(bytes); // a half-duplex adapter hears itself
}

SimTcpListener::Taken SimRtuTcpServer::take(QByteArray &buffer)
{
    Taken taken;
    const int length = RtuFrame::requestLength(buffer);
    if (length == 0 || buffer.size() < length)
        return taken;
    const QByteArray frame = buffer.left(length);
    buffer.remove(0, length);
    if (!RtuFrame::crcOk(frame)) {
        buffer.clear(); // the controller hears noise and waits for the next silence
        return taken;
    }
    taken.what = Taken::What::Request;
    taken.unit = quint8(frame.at(0));
    taken.request =
        QModbusRequest(QModbusPdu::FunctionCode(quint8(frame.at(1))), frame.mid(2, length - 4));
    return taken;
}

QByteArray SimRtuTcpServer::frame(const Taken &request, const SimResponder::Outcome &out) const
{
    QByteArray answer;
    QDataStream stream(&answer, QIODevice::WriteOnly);
    stream << quint8(request.unit) << out.response;
    const quint16 sum = RtuFrame::crc(answer);
    answer.append(char(sum & 0xFF));
    answer.append(char(sum >> 8));
    if (out.corruptCrc)
        answer[answer.size() - 1] = char(answer.at(answer.size() - 1) ^ 0x5A);
    if (out.collision) // two controllers answered at once: garbled bytes on the wire
        for (qsizetype i = 1; i < answer.size(); ++i)
            answer[i] = char(answer.at(i) ^ (0x5A + i));
    return answer;
}

} // namespace stepcom
