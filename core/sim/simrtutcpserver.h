#pragma once

#include <QElapsedTimer>
#include <QHash>
#include <QHostAddress>
#include <QObject>

QT_BEGIN_NAMESPACE
class QTcpServer;
class QTcpSocket;
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

class SimResponder;

// The simulated controller behind a transparent RS-485/Ethernet converter: Modbus RTU frames,
// CRC and all, over a plain TCP connection (no MBAP header). Frames with a bad CRC and
// requests for other ids get silence, as on the line behind a real converter.
class SimRtuTcpServer : public QObject
{
    Q_OBJECT
public:
    SimRtuTcpServer(SimResponder *responder, bool echo, QObject *parent = nullptr);
    ~SimRtuTcpServer() override;

    bool listen(const QHostAddress &address, quint16 port, QString *error);
    quint16 port() const { return m_port; }
    // Drop every connection and refuse new ones for `pauseMs`, then listen on the same port.
    void hangUp(int pauseMs);
    void close();

Q_SIGNALS:
    void hangUpRequested();

private:
    void onNewConnection();
    void onReadyRead(QTcpSocket *socket);
    void dropConnection(QTcpSocket *socket);

    SimResponder *m_responder;
    bool m_echo;
    QTcpServer *m_server;
    QTimer *m_reopen;
    QHostAddress m_address;
    quint16 m_port = 0;
    QHash<QTcpSocket *, QByteArray> m_buffers;
    // The controller does one thing at a time: a request that arrives while an answer is
    // pending is taken up only once that answer has left.
    QElapsedTimer m_clock;
    qint64 m_freeAtMs = 0;
};

} // namespace stepcom
