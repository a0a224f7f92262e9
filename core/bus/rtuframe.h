#pragma once

#include <QByteArray>
#include <QModbusPdu>

namespace stepcom {

// Modbus RTU framing: the unit id, the PDU and the CRC-16 (low byte first). The PDUs and
// their sizes are QtSerialBus's; only the frame around them is ours.
class RtuFrame
{
public:
    static quint16 crc(const QByteArray &bytes);
    // id, function code, data, CRC low, CRC high.
    static QByteArray adu(int unit, const QModbusPdu &pdu);
    // Bytes the answer frame at the start of `bytes` takes, CRC included: > 0 a length,
    // 0 not known yet (more bytes needed), -1 it cannot be an answer frame (garbage).
    static int answerLength(const QByteArray &bytes);
    // Bytes the request frame at the start of `bytes` takes, CRC included; 0 when more are
    // needed. A function code Qt cannot size: the bytes there are (a burst is one frame).
    static int requestLength(const QByteArray &bytes);
    static bool crcOk(const QByteArray &frame);
    // The PDU of a complete answer frame (no CRC check).
    static QModbusResponse response(const QByteArray &frame);
    // Milliseconds `bytes` characters take on a line at `baud` with `bitsPerChar` bits each.
    static double charsMs(int bytes, int baud, int bitsPerChar = 10);
};

} // namespace stepcom
