#pragma once

#include "sim/serve/simresponder.h"

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

// What the simulator's TCP servers share: listening, taking connections with a buffer each,
// dropping them, hanging up (drop everything, refuse connections for a while, listen on the
// same port again), and serving: every whole request goes to the SimResponder, the faults it
// decides apply alike, and each answer leaves after its delay. A server adds only its framing
// (how a request is taken from a buffer and how an answer is framed) and whether the controller
// behind it is busy while an answer is pending (docs/simulator.md, "Timing").
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
    // One request taken from the front of a connection's buffer.
    struct Taken
    {
        enum class What {
            Wait,    // nothing whole yet: wait for more bytes
            Request, // `unit` and `request` were taken off the buffer
            Drop,    // not this protocol: the connection is dropped
        };
        What what = What::Wait;
        int unit = 0;
        QModbusRequest request;
        quint16 transaction = 0; // Modbus TCP's, repeated in its answer
    };

    // While an answer is pending: the next request waits until it has left (the line behind
    // an RS-485 converter), or is answered meanwhile (Modbus TCP).
    enum class Busy { OneAtATime, Overlapping };

    SimTcpListener(SimResponder *responder, Busy busy, QObject *parent);

    // Why listening failed, in the server's own words (and translation context).
    virtual QString listenError(const QHostAddress &address, quint16 port,
                                const QString &reason) const = 0;
    // The next request in `buffer`, removed from it (with what it discards).
    virtual Taken take(QByteArray &buffer) = 0;
    // The bytes of the answer `out` to `request`, with its faults (collision, CRC).
    virtual QByteArray frame(const Taken &request, const SimResponder::Outcome &out) const = 0;
    // Every byte as it arrives, before it is taken (an adapter's echo).
    virtual void heard(QTcpSocket *socket, const QByteArray &bytes);

private:
    void onNewConnection();
    // Bytes arrived on `socket`: append them to its buffer, answer what is whole.
    void onReadyRead(QTcpSocket *socket);
    // `bytes` leave on `socket` once the controller is free and `out`'s delay is over.
    void send(QTcpSocket *socket, const QByteArray &bytes, const SimResponder::Outcome &out);
    void dropConnection(QTcpSocket *socket);

    SimResponder *m_responder;
    Busy m_busy;
    QTcpServer *m_server;
    QTimer *m_reopen;
    QHostAddress m_address;
    quint16 m_port = 0;
    QHash<QTcpSocket *, QByteArray> m_buffers; // received and not taken yet, per connection
    // Busy::OneAtATime: when the pending answer will have left.
    QElapsedTimer m_clock;
    qint64 m_freeAtMs = 0;
};

} // namespace stepcom
