#include "sim/serve/simtcpserver.h"

#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QDataStream>

namespace stepcom {

namespace {

constexpr int kHeader = 7; // transaction, protocol, length, unit

quint16 be16(const QByteArray &b, int at)
{
    return quint16((quint8(b.at(at)) << 8) | quint8(b.at(at + 1)));
}

} // namespace

SimTcpServer::SimTcpServer(SimResponder *responder, QObject *parent)
    : SimTcpListener(responder, Busy::Overlapping, parent)
{}

QString SimTcpServer::listenError(const QHostAddress &address, quint16 port,
                                  const QString &reason) const
{
    return tr("cannot listen on %1:%2: %3").arg(address.toString()).arg(port).arg(reason);
}

SimTcpListener::Taken SimTcpServer::take(QByteArray &buffer)
{
    Taken taken;
    if (buffer.size() < kHeader)
        return taken;
    const quint16 protocol = be16(buffer, 2);
    const int length = be16(buffer, 4);
    if (protocol != 0 || length < 2 || length > 254) {
        taken.what = Taken::What::Drop; // not Modbus: a gateway closes such connections
        return taken;
    }
    if (buffer.size() < 6 + length)
        return taken;
    taken.what = Taken::What::Request;
    taken.transaction = be16(buffer, 0);
    taken.unit = quint8(buffer.at(6));
    const QByteArray pdu = buffer.mid(kHeader, length - 1);
    buffer.remove(0, 6 + length);
    taken.request = QModbusRequest(QModbusPdu::FunctionCode(quint8(pdu.at(0))), pdu.mid(1));
    return taken;
}

QByteArray SimTcpServer::frame(const Taken &request, const SimResponder::Outcome &out) const
{
    QByteArray frame;
    QDataStream stream(&frame, QIODevice::WriteOnly);
    stream << request.transaction << quint16(0) << quint16(out.response.size() + 1)
           << quint8(request.unit) << out.response;
    if (out.collision) // two answers at once: the gateway passes on garbled bytes
        for (qsizetype i = kHeader; i < frame.size(); ++i)
            frame[i] = char(frame.at(i) ^ (0x5A + i));
    return frame;
}

} // namespace stepcom
