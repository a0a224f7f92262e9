#include "sim/simresponder.h"

#include "sim/simdevice.h"

namespace stepcom {

SimResponder::SimResponder(SimDevice *device, int answerDelayMs, int wireBaud,
                           const FaultOptions &faults)
    : m_device(device)
    , m_answerDelayMs(answerDelayMs)
    , m_wireBaud(wireBaud)
    , m_faults(faults)
{}

int SimResponder::wireTimeMs(int requestPduBytes, int answerPduBytes, int baud)
{
    if (baud <= 0)
        return 0;
    // An RTU frame is the PDU plus the address byte and two CRC bytes.
    const qint64 bits = qint64(requestPduBytes + 3 + answerPduBytes + 3 + 7) * 10;
    return int((bits * 1000 + baud - 1) / baud);
}

SimResponder::Outcome SimResponder::respond(const QModbusRequest &request)
{
    ++m_counters.requests;
    const FaultInjector::Decision fault = m_faults.next();
    Outcome out;
    if (fault.exceptionCode != 0) {
        out.response = QModbusExceptionResponse(
            request.functionCode(), QModbusExceptionResponse::ExceptionCode(fault.exceptionCode));
    } else {
        const SimAnswer answer = m_device->handle(request);
        out.response = answer.response;
        out.linkChanged = answer.linkChanged;
    }
    if (!out.response.isValid())
        return out;
    if (fault.drop) {
        ++m_counters.dropped;
        out.response = QModbusResponse();
        return out;
    }
    out.corruptCrc = fault.corruptCrc;
    out.hangUp = fault.hangUp;
    out.delayMs = m_answerDelayMs + fault.extraDelayMs +
                  wireTimeMs(int(request.size()), int(out.response.size()), m_wireBaud);
    ++m_counters.answers;
    if (out.response.isException())
        ++m_counters.exceptions;
    if (out.corruptCrc)
        ++m_counters.corrupted;
    if (fault.extraDelayMs > 0)
        ++m_counters.late;
    return out;
}

} // namespace stepcom
