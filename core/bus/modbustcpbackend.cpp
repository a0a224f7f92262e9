#include "bus/modbustcpbackend.h"

#include "bus/answercheck.h"
#include "bus/wiretap.h"

#include <QCoreApplication>
#include <QModbusTcpClient>
#include <QVariant>

namespace stepcom {

ModbusTcpBackend::ModbusTcpBackend(QObject *parent)
    : LinkBackend(parent)
{
    m_sendTimer.setSingleShot(true);
    connect(&m_sendTimer, &QTimer::timeout, this, &ModbusTcpBackend::sendNow);
    WireTap::attach(this, [this](WireTap::Frame f, const QByteArray &raw) {
        if (!m_client || (f != WireTap::Frame::TcpSent && f != WireTap::Frame::TcpReceived))
            return;
        Q_EMIT frame(f == WireTap::Frame::TcpSent, raw, 7, 0);
    });
}

ModbusTcpBackend::~ModbusTcpBackend()
{
    WireTap::detach(this);
    close();
}

void ModbusTcpBackend::open(const LinkSettings &settings)
{
    close();
    ++m_attempt;
    m_opening = true;
    m_failing = false;
    m_client = new QModbusTcpClient(this);
    m_client->setConnectionParameter(QModbusDevice::NetworkAddressParameter, settings.host);
    m_client->setConnectionParameter(QModbusDevice::NetworkPortParameter, settings.tcpPort);
    m_client->setTimeout(settings.timeoutMs);
    m_client->setNumberOfRetries(0); // retries are ModbusLink's
    connect(m_client, &QModbusDevice::stateChanged, this,
            [this](QModbusDevice::State s) { onClientState(int(s)); });
    connect(m_client, &QModbusDevice::errorOccurred, this,
            [this](QModbusDevice::Error e) { onClientError(int(e)); });
    if (!m_client->connectDevice()) {
        // The client may already have reported the error inside the call.
        if (m_client)
            fail(m_client->errorString().isEmpty()
                     ? QCoreApplication::translate("stepcom::ModbusLink", "cannot open %1")
                           .arg(settings.describe())
                     : m_client->errorString());
        return;
    }
    if (m_client && m_client->state() == QModbusDevice::ConnectedState)
        onClientState(int(QModbusDevice::ConnectedState));
}

void ModbusTcpBackend::close()
{
    m_sendTimer.stop();
    if (m_client) {
        QModbusTcpClient *client = std::exchange(m_client, nullptr);
        client->disconnect(this);
        for (QModbusReply *reply : client->findChildren<QModbusReply *>())
            reply->disconnect(this);
        client->disconnectDevice();
        // Replies are its children: deleting later lets a queued finished() run harmlessly.
        client->deleteLater();
    }
    m_reply.clear();
    m_opening = false;
}

void ModbusTcpBackend::onClientState(int s)
{
    const auto state = QModbusDevice::State(s);
    if (state == QModbusDevice::ConnectedState && m_opening) {
        m_opening = false;
        Q_EMIT opened(true, QString());
    } else if (state == QModbusDevice::UnconnectedState && !m_failing) {
        // Qt sets the state before the error that explains it: give the error a moment.
        const quint64 attempt = m_attempt;
        QTimer::singleShot(0, this, [this, attempt] {
            if (attempt != m_attempt || m_failing || !m_client)
                return;
            fail(!m_client->errorString().isEmpty()
                     ? m_client->errorString()
                     : QCoreApplication::translate("stepcom::ModbusLink", "connection closed"));
        });
    }
}

void ModbusTcpBackend::onClientError(int e)
{
    const auto error = QModbusDevice::Error(e);
    if (error == QModbusDevice::ConnectionError || error == QModbusDevice::ReadError ||
        error == QModbusDevice::WriteError || error == QModbusDevice::ConfigurationError) {
        const QString text = m_client ? m_client->errorString() : QString();
        fail(text.isEmpty()
                 ? QCoreApplication::translate("stepcom::ModbusLink", "the port reported an error")
                 : text);
    }
}

void ModbusTcpBackend::fail(const QString &reason)
{
    if (m_failing)
        return;
    m_failing = true;
    const bool opening = m_opening;
    close();
    if (opening)
        Q_EMIT opened(false, reason);
    else
        Q_EMIT failed(reason);
}

void ModbusTcpBackend::requireQuiet()
{
    m_needQuiet = true;
    m_sinceQuiet.start();
}

void ModbusTcpBackend::send(int unit, const QModbusRequest &request, int timeoutMs)
{
    m_unit = unit;
    m_request = request;
    m_timeoutMs = timeoutMs;
    const qint64 left = m_needQuiet ? m_quietMs - m_sinceQuiet.elapsed() : 0;
    if (left > 0) {
        m_sendTimer.start(int(left));
        return;
    }
    sendNow();
}

void ModbusTcpBackend::sendNow()
{
    if (!m_client)
        return;
    m_needQuiet = false;
    m_client->setTimeout(m_timeoutMs);
    m_sentAt.start();
    QModbusReply *reply = m_client->sendRawRequest(m_request, m_unit);
    if (!reply) {
        LinkAnswer a;
        a.kind = LinkAnswer::Kind::Failed;
        a.errorText = m_client ? m_client->errorString() : QString();
        Q_EMIT answered(a);
        return;
    }
    Q_EMIT sent();
    m_reply = reply;
    if (reply->isFinished()) {
        onReplyFinished(reply);
        return;
    }
    connect(reply, &QModbusReply::finished, this, [this, reply] { onReplyFinished(reply); });
}

void ModbusTcpBackend::onReplyFinished(QModbusReply *reply)
{
    reply->deleteLater(); // only now: deleting an unfinished reply can crash Qt 6.4
    if (reply != m_reply)
        return;
    m_reply.clear();
    LinkAnswer a;
    const QModbusResponse raw = reply->rawResult();
    const int fc = quint8(m_request.functionCode());
    if (reply->error() == QModbusDevice::NoError ||
        (reply->error() == QModbusDevice::ProtocolError && raw.data().size() == 1)) {
        // From the error, not the PDU: QModbusPdu::isException() trips UBSan on Qt 6.4.
        const int afc = reply->error() == QModbusDevice::NoError ? fc : fc | 0x80;
        if (const QString why = AnswerCheck::mismatch(m_request, afc, raw.data()); !why.isEmpty()) {
            a.kind = LinkAnswer::Kind::Timeout;
            a.discarded << why;
        } else {
            a.kind = LinkAnswer::Kind::Answer;
            a.response = raw;
            a.exceptionCode = AnswerCheck::exceptionCode(afc, raw.data());
            a.roundTripMs = m_sentAt.elapsed();
        }
    } else if (reply->error() == QModbusDevice::TimeoutError) {
        a.kind = LinkAnswer::Kind::Timeout;
    } else {
        a.kind = LinkAnswer::Kind::Failed;
        a.errorText = reply->errorString();
    }
    if (a.kind != LinkAnswer::Kind::Answer)
        requireQuiet();
    Q_EMIT answered(a);
}

} // namespace stepcom
