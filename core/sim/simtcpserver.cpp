#include "sim/simtcpserver.h"

#include "sim/simdevice.h"
#include "sim/simresponder.h"

#include <QDataStream>
#include <QTcpServer>
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
    : QObject(parent)
    , m_responder(responder)
    , m_server(new QTcpServer(this))
    , m_reopen(new QTimer(this))
{
    m_reopen->setSingleShot(true);
    connect(m_server, &QTcpServer::newConnection, this, &SimTcpServer::onNewConnection);
    connect(m_reopen, &QTimer::timeout, this, [this] {
        if (m_server->listen(m_address, m_port))
            Q_EMIT reopened();
        else
            m_reopen->start(200); // the port may linger a moment: try again
    });
}

SimTcpServer::~SimTcpServer()
{
    close();
}

bool SimTcpServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    if (!m_server->listen(address, port)) {
        if (error)
            *error = tr("cannot listen on %1:%2: %3")
                         .arg(address.toString())
                         .arg(port)
                         .arg(m_server->errorString());
        return false;
    }
    m_address = address;
    m_port = m_server->serverPort();
    return true;
}

void SimTcpServer::close()
{
    m_reopen->stop();
    m_server->close();
    const auto sockets = m_buffers.keys();
    for (QTcpSocket *s : sockets)
        dropConnection(s);
}

void SimTcpServer::hangUp(int pauseMs)
{
    if (!m_server->isListening() && m_buffers.isEmpty())
        return;
    close();
    Q_EMIT hungUp();
    m_reopen->start(std::max(0, pauseMs));
}

void SimTcpServer::onNewConnection()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        m_buffers.insert(socket, {});
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { onReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this,
                [this, socket] { dropConnection(socket); });
    }
}

void SimTcpServer::dropConnection(QTcpSocket *socket)
{
    if (!m_buffers.remove(socket))
        return;
    socket->disconnect(this);
    socket->abort();
    socket->deleteLater();
}

void SimTcpServer::onReadyRead(QTcpSocket *socket)
{
    auto it = m_buffers.find(socket);
    if (it == m_buffers.end())
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
            if (target && m_buffers.contains(target.data()))
                target->write(frame);
            if (hangUpAfter)
                Q_EMIT hangUpRequested();
        });
        it = m_buffers.find(socket);
        if (it == m_buffers.end())
            return;
    }
}

} // namespace stepcom
