#include "sim/serve/simrtuserver.h"

#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QModbusRequest>
#include <QThread>

#include <mutex>

namespace stepcom {

SimRtuServer::SimRtuServer(SimResponder *responder, std::function<int()> clientBaud,
                           QObject *parent)
    : QModbusRtuSerialServer(parent)
    , m_responder(responder)
    , m_clientBaud(std::move(clientBaud))
{
    registerUnknownFunctionCodes();
}

void SimRtuServer::registerUnknownFunctionCodes()
{
    static std::once_flag once;
    std::call_once(once, [] {
        for (int fc = 1; fc < 0x80; ++fc) {
            const QModbusRequest probe(QModbusPdu::FunctionCode(fc), QByteArray(16, '\0'));
            if (QModbusRequest::calculateDataSize(probe) >= 0)
                continue;
            // Unknown size: the whole frame up to the CRC is taken as the request.
            QModbusRequest::registerDataSizeCalculator(
                QModbusPdu::FunctionCode(fc),
                [](const QModbusRequest &r) { return int(r.dataSize()); });
        }
    });
}

bool SimRtuServer::takeCorruptCrc()
{
    const bool corrupt = m_corruptNext;
    m_corruptNext = false;
    return corrupt;
}

void SimRtuServer::setRequestUnit(int unit)
{
    m_unit = unit;
    if (unit > 0)
        setServerAddress(unit);
}

QModbusResponse SimRtuServer::processRequest(const QModbusPdu &request)
{
    const int unit = m_unit >= 0 ? m_unit : serverAddress();
    SimDevice *device = m_responder->devicesAt(unit).value(0, m_responder->device());
    if (m_clientBaud) {
        const int clientBaud = m_clientBaud();
        if (clientBaud != 0 && clientBaud != device->baud()) {
            ++m_responder->counters().wrongBaud;
            return {};
        }
    }
    const SimResponder::Outcome out = m_responder->respond(unit, QModbusRequest(request));
    if (!out.response.isValid())
        return {};
    // The server thread may sleep: it is the simulator's own, and a controller is busy then.
    if (out.delayMs > 0)
        QThread::msleep(ulong(out.delayMs));
    m_corruptNext = out.corruptCrc;
    if (out.hangUp)
        QMetaObject::invokeMethod(this, &SimRtuServer::hangUpRequested, Qt::QueuedConnection);
    return out.response;
}

QModbusResponse SimRtuServer::processPrivateRequest(const QModbusPdu &request)
{
    return processRequest(request);
}

} // namespace stepcom
