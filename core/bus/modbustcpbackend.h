#pragma once

#include "bus/linkbackend.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

class QModbusReply;
class QModbusTcpClient;

namespace stepcom {

// Modbus TCP (MBAP) through QModbusTcpClient, which matches answers by transaction id; the
// answer is checked all the same, and frames reach the traffic log through the WireTap.
class ModbusTcpBackend : public LinkBackend
{
    Q_OBJECT
public:
    explicit ModbusTcpBackend(QObject *parent = nullptr);
    ~ModbusTcpBackend() override;

    void open(const LinkSettings &settings) override;
    void close() override;
    void send(int unit, const QModbusRequest &request, int timeoutMs) override;
    void setQuietTimeMs(int ms) override { m_quietMs = ms; }
    void requireQuiet() override;

private:
    void onClientState(int state);
    void onClientError(int error);
    void fail(const QString &reason);
    void sendNow();
    void onReplyFinished(QModbusReply *reply);

    QModbusTcpClient *m_client = nullptr;
    bool m_opening = false;
    bool m_failing = false;
    quint64 m_attempt = 0;
    int m_unit = 1;
    QModbusRequest m_request;
    int m_timeoutMs = 500;
    QPointer<QModbusReply> m_reply;
    QElapsedTimer m_sentAt;
    QElapsedTimer m_sinceQuiet;
    bool m_needQuiet = false;
    int m_quietMs = 100;
    QTimer m_sendTimer;
};

} // namespace stepcom
