#include "sim/serve/simtcpserver.h"

#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QDataStream>
#include <QPointer>
#include <QTcpSocket>
#include <QTimer>

namespace stepcom {

namespace {

constexpr int kHeader = 7; // transaction, protocol, length, unit

quint16 be16(const QByteArray &b, int at)
{
    return quint16((quint8(b.at(at)) << 8) | quint8(b.at(at + 1)));
}

} // namespace

SimTcpServer::SimTcpServer(SimResponder *responder, QObject *parent)
    : SimTcpListener(parent)
    , m_responder(responder)
{}

QString SimTcpServer::listenError(const QHostAddress &address, quint16 port,
                                  const QString &reason) const
{
    return tr("cannot listen on %1:%2: %3").arg(address.toString()).arg(port).arg(reason);
}

void SimTcpServer::onReadyRead(QTcpSocket *socket)
{
    auto it = buffers().find(socket);
    if (it == buffers().end())
        return;
    it->append(socket->readAll());
    while (it->size() >= kHeader) {
        const QByteArray &buf = *it;
        const quint16 transaction = be16(buf, 0);
        const quint16 protocol = be16(buf, 2);
        const int length = be16(buf, 4);
        if (protocol != 0 || length < 2 || length > 254) {
            dropConnection(socket); // not Modbus: a gateway closes such connections
            return;
        }
        if (buf.size() < 6 + length)
            return;
        const quint8 unit = quint8(buf.at(6));
        const QByteArray pduBytes = buf.mid(kHeader, length - 1);
        it->remove(0, 6 + length);
        const QModbusRequest request(QModbusPdu::FunctionCode(quint8(pduBytes.at(0))),
                                     pduBytes.mid(1));
        // Another id's request is silence; unit 0 is a broadcast, never answered.
        const SimResponder::Outcome out = m_responder->respond(unit, request);
        if (!out.response.isValid() || unit == 0)
            continue;
        QByteArray frame;
        QDataStream stream(&frame, QIODevice::WriteOnly);
        stream << transaction << quint16(0) << quint16(out.response.size() + 1) << unit
               << out.response;
        if (out.collision) // two answers at once: the gateway passes on garbled bytes
            for (qsizetype i = kHeader; i < frame.size(); ++i)
                frame[i] = char(frame.at(i) ^ (0x5A + i));
        QPointer<QTcpSocket> target(socket);
        const bool hangUpAfter = out.hangUp;
        QTimer::singleShot(out.delayMs, this, [this, target, frame, hangUpAfter] {
            if (target && buffers().contains(target.data()))
                target->write(frame);
            if (hangUpAfter)
                Q_EMIT hangUpRequested();
        });
        it = buffers().find(socket);
        if (it == buffers().end())
            return;
    }
}

} // namespace stepcom
