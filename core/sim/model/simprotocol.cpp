#include "sim/model/simprotocol.h"

#include "bus/bigendian.h"

#include "sim/model/simregisters.h"

namespace stepcom {

namespace {

using bigendian::wordAt;

void appendWord(QByteArray &data, quint16 value)
{
    data.append(char(value >> 8));
    data.append(char(value & 0xFF));
}

QModbusResponse exception(const QModbusRequest &request,
                          QModbusExceptionResponse::ExceptionCode code)
{
    return QModbusExceptionResponse(request.functionCode(), code);
}

} // namespace

SimProtocol::SimProtocol(const SimRegisters &registers, Hooks hooks, bool strictReads,
                         QSet<QString> lacking)
    : m_regs(registers)
    , m_hooks(std::move(hooks))
    , m_strictReads(strictReads)
    , m_lacking(std::move(lacking))
{}

QModbusResponse SimProtocol::process(const QModbusRequest &request) const
{
    switch (request.functionCode()) {
    case QModbusPdu::ReadHoldingRegisters:
        return readHolding(request);
    case QModbusPdu::WriteSingleCoil:
        return writeCoil(request);
    case QModbusPdu::WriteSingleRegister:
        return writeSingle(request);
    case QModbusPdu::WriteMultipleRegisters:
        return writeMultiple(request);
    default:
        return exception(request, QModbusExceptionResponse::IllegalFunction);
    }
}

QModbusResponse SimProtocol::readHolding(const QModbusRequest &request) const
{
    const QByteArray data = request.data();
    if (data.size() != 4)
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    const int start = wordAt(data, 0);
    const int count = wordAt(data, 2);
    if (count < 1 || count > m_regs.map().maxRegistersPerRequest())
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    QByteArray out;
    out.append(char(count * 2));
    if (start + count - 1 > m_regs.lastAddress())
        return exception(request, QModbusExceptionResponse::IllegalDataAddress);
    for (int address = start; address < start + count; ++address) {
        const Parameter *p = m_regs.map().holdingAt(quint16(address));
        if ((!p && m_strictReads) || (p && m_lacking.contains(p->key)))
            return exception(request, QModbusExceptionResponse::IllegalDataAddress);
        if (!p) {
            appendWord(out, 0); // reserved: the firmware's register array holds 0 there
            continue;
        }
        // Reading one word of a 32-bit value is allowed: registers are just registers.
        appendWord(out, p->encode(m_regs.raw(p)).at(address - p->address));
    }
    return QModbusResponse(request.functionCode(), out);
}

QModbusResponse SimProtocol::writeSingle(const QModbusRequest &request) const
{
    const QByteArray data = request.data();
    if (data.size() != 4)
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    const quint16 address = wordAt(data, 0);
    const quint16 value = wordAt(data, 2);
    const Parameter *p = m_regs.map().holdingAt(address);
    if (!p || !p->writable() || p->words != 1 || m_lacking.contains(p->key))
        return exception(request, QModbusExceptionResponse::IllegalDataAddress);
    const qint64 raw = p->decode(&value);
    if (!p->checkRaw(raw).isEmpty())
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    m_hooks.write({{p, raw}});
    return QModbusResponse(request.functionCode(), data);
}

QModbusResponse SimProtocol::writeMultiple(const QModbusRequest &request) const
{
    const QByteArray data = request.data();
    if (data.size() < 5)
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    const int start = wordAt(data, 0);
    const int count = wordAt(data, 2);
    const int bytes = quint8(data.at(4));
    if (count < 1 || count > m_regs.map().maxRegistersPerRequest() || bytes != 2 * count ||
        data.size() != 5 + bytes)
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    QList<quint16> words;
    for (int i = 0; i < count; ++i)
        words.append(wordAt(data, 5 + 2 * i));

    // Addresses first (02), then values (03), as the Modbus specification orders the checks.
    QList<Write> writes;
    for (int address = start; address < start + count;) {
        const Parameter *p = address <= 0xFFFF ? m_regs.map().holdingAt(quint16(address)) : nullptr;
        if (!p || !p->writable() || p->address != address ||
            int(p->lastAddress()) >= start + count || m_lacking.contains(p->key))
            return exception(request, QModbusExceptionResponse::IllegalDataAddress);
        writes.append({p, p->decode(words.constData() + (address - start))});
        address += p->words;
    }
    for (const Write &w : writes) {
        if (!w.first->checkRaw(w.second).isEmpty())
            return exception(request, QModbusExceptionResponse::IllegalDataValue);
    }
    m_hooks.write(writes);
    return QModbusResponse(request.functionCode(), data.left(4));
}

QModbusResponse SimProtocol::writeCoil(const QModbusRequest &request) const
{
    const QByteArray data = request.data();
    if (data.size() != 4)
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    const quint16 address = wordAt(data, 0);
    const quint16 value = wordAt(data, 2);
    if (value != 0xFF00 && value != 0x0000)
        return exception(request, QModbusExceptionResponse::IllegalDataValue);
    const Parameter *p = m_regs.map().coilAt(address);
    if (!p)
        return exception(request, QModbusExceptionResponse::IllegalDataAddress);
    // Coils are commands: ON executes, OFF is accepted and does nothing.
    if (value == 0xFF00 && !m_hooks.coil(*p))
        return exception(request, QModbusExceptionResponse::ServerDeviceFailure);
    return QModbusResponse(request.functionCode(), data);
}

} // namespace stepcom
