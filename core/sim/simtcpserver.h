#pragma once

#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <QPointer>

QT_BEGIN_NAMESPACE
class QTcpServer;
class QTcpSocket;
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

class SimResponder;

// Modbus TCP (MBAP framing) in front of the simulated controller. Our own rather than
// QModbusTcpServer: Qt 6.4's writes a frame even for "no answer", so dropped answers and
// answers for other unit ids could not be silent, and it cannot delay without blocking.
// Only the device's own unit id is answered, as a TCP-to-RTU gateway would.
class SimTcpServer : public QObject
{
    Q_OBJECT
public:
    explicit SimTcpServer(SimResponder *responder, QObject *parent = nullptr);
    ~SimTcpServer() override;

    bool listen(const QHostAddress &address, quint16 port, QString *error);
    quint16 port() const { return m_port; }
    QHostAddress address() const { return m_address; }
    // Drop every connection and refuse new ones for `pauseMs`, then listen on the same port.
    void hangUp(int pauseMs);
    void close();
    int connectionCount() const { return int(m_buffers.size()); }

Q_SIGNALS:
    void hangUpRequested();
    void hungUp();
    void reopened();

private:
    void onNewConnection();
    void onReadyRead(QTcpSocket *socket);
    void dropConnection(QTcpSocket *socket);

    SimResponder *m_responder;
    QTcpServer *m_server;
    QTimer *m_reopen;
    QHostAddress m_address;
    quint16 m_port = 0;
    QHash<QTcpSocket *, QByteArray> m_buffers;
};

} // namespace stepcom
