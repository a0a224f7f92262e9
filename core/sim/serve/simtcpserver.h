#pragma once

#include "sim/serve/simtcplistener.h"

namespace stepcom {

// Modbus TCP (MBAP framing) in front of the simulated controller. Our own rather than
// QModbusTcpServer: Qt 6.4's writes a frame even for "no answer", so dropped answers and
// answers for other unit ids could not be silent, and it cannot delay without blocking.
// Only the device's own unit id is answered, as a TCP-to-RTU gateway would; a request that
// comes while a slow answer is pending is answered meanwhile (docs/simulator.md, "Timing").
class SimTcpServer : public SimTcpListener
{
    Q_OBJECT
public:
    explicit SimTcpServer(SimResponder *responder, QObject *parent = nullptr);

private:
    QString listenError(const QHostAddress &address, quint16 port,
                        const QString &reason) const override;
    Taken take(QByteArray &buffer) override;
    QByteArray frame(const Taken &request, const SimResponder::Outcome &out) const override;
};

} // namespace stepcom
