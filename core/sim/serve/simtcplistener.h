#pragma once

#include <QHash>
#include <QHostAddress>
#include <QObject>

QT_BEGIN_NAMESPACE
class QTcpServer;
class QTcpSocket;
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

// What the simulator's TCP servers share: listening, taking connections with a buffer each,
// dropping them, and hanging up (drop everything, refuse connections for a while, listen on the
// same port again). A server adds only how it reads requests from a buffer and answers them.
class SimTcpListener : public QObject
{
    Q_OBJECT
public:
    ~SimTcpListener() override;

    bool listen(const QHostAddress &address, quint16 port, QString *error);
    quint16 port() const { return m_port; }
    QHostAddress address() const { return m_address; }
    // Drop every connection and refuse new ones for `pauseMs`, then listen on the same port.
    void hangUp(int pauseMs);
    void close();
    int connectionCount() const { return int(m_buffers.size()); }

Q_SIGNALS:
    // An answer has left that was to end the connection (a fault): the simulator hangs up.
    void hangUpRequested();
    void hungUp();
    void reopened();

protected:
    explicit SimTcpListener(QObject *parent);

    // Why listening failed, in the server's own words (and translation context).
    virtual QString listenError(const QHostAddress &address, quint16 port,
                                const QString &reason) const = 0;
    // Bytes arrived on `socket`: take them, append them to its buffer, answer what is whole.
    virtual void onReadyRead(QTcpSocket *socket) = 0;
    void dropConnection(QTcpSocket *socket);
    // The bytes received on each open connection and not handled yet.
    QHash<QTcpSocket *, QByteArray> &buffers() { return m_buffers; }

private:
    void onNewConnection();

    QTcpServer *m_server;
    QTimer *m_reopen;
    QHostAddress m_address;
    quint16 m_port = 0;
    QHash<QTcpSocket *, QByteArray> m_buffers;
};

} // namespace stepcom
