#include "sim/serve/simresponder.h"

#include "sim/model/simdevice.h"

namespace stepcom {

SimResponder::SimResponder(QList<SimDevice *> devices, int answerDelayMs, int wireBaud,
                           const FaultOptions &faults)
    : m_devices(std::move(devices))
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

QList<SimDevice *> SimResponder::devicesAt(int unit) const
{
    QList<SimDevice *> found;
    for (SimDevice *d : m_devices)
        if ((unit == 0 || d->deviceId() == unit) && !d->isPoweredOff())
            found.append(d);
    return found;
}

int SimResponder::answerDelayMs(const QModbusRequest &request) const
{
    if (m_slowCoils.isEmpty() || request.functionCode() != QModbusPdu::WriteSingleCoil ||
        request.dataSize() != 4)
        return m_answerDelayMs;
    quint16 address = 0;
    quint16 value = 0;
    request.decodeData(&address, &value);
    // Only an executed command (FF00) makes the firmware busy; 0000 does nothing.
    return value == 0xFF00 ? m_answerDelayMs + m_slowCoils.value(int(address) + 1, 0)
                           : m_answerDelayMs;
}

SimResponder::Outcome SimResponder::respond(int unit, const QModbusRequest &request)
{
    const QList<SimDevice *> targets = devicesAt(unit);
    if (targets.isEmpty())
        return {}; // someone else's request: silence
    if (unit == 0 || targets.size() > 1) {
        // Every controller that heard it acts; a broadcast is never answered, and two
        // answers at once are garbage on an RS-485 pair.
        Outcome out;
        QModbusResponse first;
        for (SimDevice *d : targets) {
            const SimAnswer answer = d->handle(request);
            out.linkChanged = answer.linkChanged || out.linkChanged;
            if (!first.isValid())
                first = answer.response;
        }
        if (unit == 0 || !first.isValid())
            return out;
        ++m_counters.requests;
        ++m_counters.collisions;
        // An answer of the right length whose bytes the other controller's answer garbled:
        // the client's CRC check rejects it.
        out.collision = true;
        out.corruptCrc = true;
        out.response = first;
        out.delayMs =
            answerDelayMs(request) + wireTimeMs(int(request.size()), int(first.size()), m_wireBaud);
        return out;
    }
    SimDevice *device = targets.first();
    ++m_counters.requests;
    const FaultInjector::Decision fault = m_faults.next();
    Outcome out;
    if (fault.exceptionCode != 0) {
        out.response = QModbusExceptionResponse(
            request.functionCode(), QModbusExceptionResponse::ExceptionCode(fault.exceptionCode));
    } else {
        const SimAnswer answer = device->handle(request);
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
    out.delayMs = answerDelayMs(request) + fault.extraDelayMs +
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
