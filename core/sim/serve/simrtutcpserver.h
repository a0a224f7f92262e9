#pragma once

#include "sim/serve/simtcplistener.h"

namespace stepcom {

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
    void heard(QTcpSocket *socket, const QByteArray &bytes) override;
    Taken take(QByteArray &buffer) override;
    QByteArray frame(const Taken &request, const SimResponder::Outcome &out) const override;

    bool m_echo;
};

} // namespace stepcom
