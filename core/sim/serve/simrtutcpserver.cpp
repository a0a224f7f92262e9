#include "sim/serve/simrtutcpserver.h"

#include "bus/rtuframe.h"
#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QDataStream>
#include <QModbusPdu>
#include <QPointer>
#include <QTcpSocket>
#include <QTimer>

namespace stepcom {

SimRtuTcpServer::SimRtuTcpServer(SimResponder *responder, bool echo, QObject *parent)
    : SimTcpListener(parent)
    , m_responder(responder)
    , m_echo(echo)
{
    m_clock.start();
}

QString SimRtuTcpServer::listenError(const QHostAddress &address, quint16 port,
                                     const QString &reason) const
{
    return tr("cannot listen for RTU over TCP on %1:%2: %3")
        .arg(address.toString())
        .arg(port)
        .arg(reason);
}

void SimRtuTcpServer::onReadyRead(QTcpSocket *socket)
{
    auto it = buffers().find(socket);
    if (it == buffers().end())
        return;
    const QByteArray bytes = socket->readAll();
    if (m_echo)
        socket->write(bytes); // a half-duplex adapter hears itself
    it->append(bytes);
    while (true) {
        const int length = RtuFrame::requestLength(*it);
        if (length == 0 || it->size() < length)
            return;
        const QByteArray frame = it->left(length);
        it->remove(0, length);
        if (!RtuFrame::crcOk(frame)) {
            it->clear(); // the controller hears noise and waits for the next silence
            return;
        }
        const int unit = quint8(frame.at(0));
        const bool broadcast = unit == 0;
        if (!broadcast && !m_responder->hasDevice(unit))
            continue; // another controller's request: silence
        const QModbusRequest request(QModbusPdu::FunctionCode(quint8(frame.at(1))),
                                     frame.mid(2, length - 4));
        const SimResponder::Outcome out = m_responder->respond(unit, request);
        if (broadcast || !out.response.isValid())
            continue;
        QByteArray answer;
        QDataStream stream(&answer, QIODevice::WriteOnly);
        stream << quint8(unit) << out.response;
        const quint16 sum = RtuFrame::crc(answer);
        answer.append(char(sum & 0xFF));
        answer.append(char(sum >> 8));
        if (out.corruptCrc)
            answer[answer.size() - 1] = char(answer.at(answer.size() - 1) ^ 0x5A);
        if (out.collision) // two controllers answered at once: garbled bytes on the wire
            for (qsizetype i = 1; i < answer.size(); ++i)
                answer[i] = char(answer.at(i) ^ (0x5A + i));
        QPointer<QTcpSocket> target(socket);
        const bool hangUpAfter = out.hangUp;
        const qint64 now = m_clock.elapsed();
        const qint64 leaveAt = std::max(now, m_freeAtMs) + out.delayMs;
        m_freeAtMs = leaveAt;
        QTimer::singleShot(int(leaveAt - now), this, [this, target, answer, hangUpAfter] {
            if (target && buffers().contains(target.data()))
                target->write(answer);
            if (hangUpAfter)
                Q_EMIT hangUpRequested();
        });
        it = buffers().find(socket);
        if (it == buffers().end())
            return;
    }
}

} // namespace stepcom
