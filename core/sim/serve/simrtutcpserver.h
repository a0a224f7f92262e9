#pragma once

#include "sim/serve/simtcplistener.h"

#include <QElapsedTimer>

namespace stepcom {

class SimResponder;

// The simulated controller behind a transparent RS-485/Ethernet converter: Modbus RTU frames,
// CRC and all, over a plain TCP connection (no MBAP header). Frames with a bad CRC and
// requests for other ids get silence, as on the line behind a real converter.
class SimRtuTcpServer : public SimTcpListener
{
    Q_OBJECT
public:
    SimRtuTcpServer(SimResponder *responder, bool echo, QObject *parent = nullptr);

private:
    QString listenError(const QHostAddress &address, quint16 port,
                        const QString &reason) const override;
    void onReadyRead(QTcpSocket *socket) override;

    SimResponder *m_responder;
    bool m_echo;
    // The controller does one thing at a time: a request that arrives while an answer is
    // pending is taken up only once that answer has left.
    QElapsedTimer m_clock;
    qint64 m_freeAtMs = 0;
};

} // namespace stepcom
