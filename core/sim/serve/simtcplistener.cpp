#include "sim/serve/simtcplistener.h"

#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

namespace stepcom {

SimTcpListener::SimTcpListener(SimResponder *responder, Busy busy, QObject *parent)
    : QObject(parent)
    , m_responder(responder)
    , m_busy(busy)
    , m_server(new QTcpServer(this))
    , m_reopen(new QTimer(this))
{
    m_clock.start();
    m_reopen->setSingleShot(true);
    connect(m_server, &QTcpServer::newConnection, this, &SimTcpListener::onNewConnection);
    connect(m_reopen, &QTimer::timeout, this, [this] {
        if (m_server->listen(m_address, m_port))
            Q_EMIT reopened();
        else
            m_reopen->start(200); // the port may linger a moment: try again
    });
}

SimTcpListener::~SimTcpListener()
{
    close();
}

bool SimTcpListener::listen(const QHostAddress &address, quint16 port, QString *error)
{
    if (!m_server->listen(address, port)) {
        if (error)
            *error = listenError(address, port, m_server->errorString());
        return false;
    }
    m_address = address;
    m_port = m_server->serverPort();
    return true;
}

void SimTcpListener::close()
{
    m_reopen->stop();
    m_server->close();
    const auto sockets = m_buffers.keys();
    for (QTcpSocket *s : sockets)
        dropConnection(s);
}

void SimTcpListener::hangUp(int pauseMs)
{
    if (!m_server->isListening() && m_buffers.isEmpty())
        return;
    close();
    Q_EMIT hungUp();
    m_reopen->start(std::max(0, pauseMs));
}

void SimTcpListener::onNewConnection()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        m_buffers.insert(socket, {});
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { onReadyRead(socket); });
        connect(socket, &QTcpSocket::disconnected, this,
                [this, socket] { dropConnection(socket); });
    }
}

void SimTcpListener::heard(QTcpSocket *, const QByteArray &) {}

void SimTcpListener::onReadyRead(QTcpSocket *socket)
{
    if (!m_buffers.contains(socket))
        return;
    const QByteArray bytes = socket->readAll();
    heard(socket, bytes);
    m_buffers[socket].append(bytes);
    // An answer may hang up or drop the connection: its buffer is looked up again each time.
    for (auto it = m_buffers.find(socket); it != m_buffers.end(); it = m_buffers.find(socket)) {
        const Taken taken = take(*it);
        if (taken.what == Taken::What::Wait)
            return;
        if (taken.what == Taken::What::Drop) {
            dropConnection(socket);
            return;
        }
        // Another id's request is silence; unit 0 is a broadcast, acted on, never answered.
        const SimResponder::Outcome out = m_responder->respond(taken.unit, taken.request);
        if (taken.unit != 0 && out.response.isValid())
            send(socket, frame(taken, out), out);
    }
}

void SimTcpListener::send(QTcpSocket *socket, const QByteArray &bytes,
                          const SimResponder::Outcome &out)
{
    const qint64 now = m_clock.elapsed();
    const qint64 leaveAt =
        (m_busy == Busy::OneAtATime ? std::max(now, m_freeAtMs) : now) + out.delayMs;
    m_freeAtMs = leaveAt;
    QPointer<QTcpSocket> target(socket);
    const bool hangUpAfter = out.hangUp;
    QTimer::singleShot(int(leaveAt - now), this, [this, target, bytes, hangUpAfter] {
        if (target && m_buffers.contains(target.data()))
            target->write(bytes);
        if (hangUpAfter)
            Q_EMIT hangUpRequested();
    });
}

void SimTcpListener::dropConnection(QTcpSocket *socket)
{
    if (!m_buffers.remove(socket))
        return;
    socket->disconnect(this);
    socket->abort();
    socket->deleteLater();
}

} // namespace stepcom
