#include "sim/serve/simtcplistener.h"

#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

namespace stepcom {

SimTcpListener::SimTcpListener(QObject *parent)
    : QObject(parent)
    , m_server(new QTcpServer(this))
    , m_reopen(new QTimer(this))
{
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

void SimTcpListener::dropConnection(QTcpSocket *socket)
{
    if (!m_buffers.remove(socket))
        return;
    socket->disconnect(this);
    socket->abort();
    socket->deleteLater();
}

} // namespace stepcom
