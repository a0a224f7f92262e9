#include "sim/simrtutcpserver.h"

#include "bus/rtuframe.h"
#include "sim/simdevice.h"
#include "sim/simresponder.h"

#include <QDataStream>
#include <QModbusPdu>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

namespace stepcom {

namespace {

// Bytes of the request frame at the start of `b` (CRC included), 0 when more are needed.
int requestLength(const QByteArray &b)
{
    if (b.size() < 2)
        return 0;
    const QModbusRequest probe(QModbusPdu::FunctionCode(quint8(b.at(1))), b.mid(2));
    const int size = QModbusRequest::calculateDataSize(probe);
    if (size < 0) // a function code Qt cannot size: the burst is the frame
        return int(b.size());
    return 2 + size + 2;
}

} // namespace

SimRtuTcpServer::SimRtuTcpServer(SimResponder *responder, bool echo, QObject *parent)
    : QObject(parent)
    , m_responder(responder)
    , m_echo(echo)
    , m_server(new QTcpServer(this))
    , m_reopen(new QTimer(this))
{
    m_clock.start();
    m_reopen->setSingleShot(true);
    connect(m_server, &QTcpServer::newConnection, this, &SimRtuTcpServer::onNewConnection);
    connect(m_reopen, &QTimer::timeout, this, [this] {
        if (!m_server->listen(m_address, m_port))
            m_reopen->start(200); // the port may linger a moment: try again
    });
}

SimRtuTcpServer::~SimRtuTcpServer()
{
    close();
}

bool SimRtuTcpServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    if (!m_server->listen(address, port)) {
        if (error)
            *error = tr("cannot listen for RTU over TCP on %1:%2: %3")
                         .arg(address.toString())
                         .arg(port)
                         .arg(m_server->errorString());
        return false;
    }
    m_address = address;
    m_port = m_server->serverPort();
    return true;
}

void SimRtuTcpServer::close()
{
    m_reopen->stop();
    m_server->close();
    const auto sockets = m_buffers.keys();
    for (QTcpSocket *s : sockets)
        dropConnection(s);
}

void SimRtuTcpServer::hangUp(int pauseMs)
{
    if (!m_server->isListening() && m_buffers.isEmpty())
        return;
    close();
    m_reopen->start(std::max(0, pauseMs));
}

void SimRtuTcpServer::onNewConnection()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        m_buffers.insert(socket, {});
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { onReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this,
                [this, socket] { dropConnection(socket); });
    }
}

void SimRtuTcpServer::dropConnection(QTcpSocket *socket)
{
    if (!m_buffers.remove(socket))
        return;
    socket->disconnect(this);
    socket->abort();
    socket->deleteLater();
}

void SimRtuTcpServer::onReadyRead(QTcpSocket *socket)
{
    auto it = m_buffers.find(socket);
    if (it == m_buffers.end())
        return;
    const QByteArray bytes = socket->readAll();
    if (m_echo)
        socket->write(bytes); // a half-duplex adapter hears itself
    it->append(bytes);
    while (true) {
        const int length = requestLength(*it);
        if (length == 0 || it->size() < length)
            return;
        const QByteArray frame = it->left(length);
        it->remove(0, length);
        if (!RtuFrame::crcOk(frame)) {
            it->clear(); // the controller hears noise and waits for the next silence
            return;
        }
        const int unit = quint8(frame.at(0));
        const bool broadcast = unit == 0;
        if (!broadcast && !m_responder->hasDevice(unit))
            continue; // another controller's request: silence
        const QModbusRequest request(QModbusPdu::FunctionCode(quint8(frame.at(1))),
                                     frame.mid(2, length - 4));
        const SimResponder::Outcome out = m_responder->respond(unit, request);
        if (broadcast || !out.response.isValid())
            continue;
        QByteArray answer;
        QDataStream stream(&answer, QIODevice::WriteOnly);
        stream << quint8(unit) << out.response;
        const quint16 sum = RtuFrame::crc(answer);
        answer.append(char(sum & 0xFF));
        answer.append(char(sum >> 8));
        if (out.corruptCrc)
            answer[answer.size() - 1] = char(answer.at(answer.size() - 1) ^ 0x5A);
        if (out.collision) // two controllers answered at once: garbled bytes on the wire
            for (qsizetype i = 1; i < answer.size(); ++i)
                answer[i] = char(answer.at(i) ^ (0x5A + i));
        QPointer<QTcpSocket> target(socket);
        const bool hangUpAfter = out.hangUp;
        const qint64 now = m_clock.elapsed();
        const qint64 leaveAt = std::max(now, m_freeAtMs) + out.delayMs;
        m_freeAtMs = leaveAt;
        QTimer::singleShot(int(leaveAt - now), this, [this, target, answer, hangUpAfter] {
            if (target && m_buffers.contains(target.data()))
                target->write(answer);
            if (hangUpAfter)
                Q_EMIT hangUpRequested();
        });
        it = m_buffers.find(socket);
        if (it == m_buffers.end())
            return;
    }
}

} // namespace stepcom
