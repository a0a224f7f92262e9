#include "bus/rtuframe.h"

namespace stepcom {

quint16 RtuFrame::crc(const QByteArray &bytes)
{
    quint16 crc = 0xFFFF;
    for (const char c : bytes) {
        crc ^= quint8(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? quint16((crc >> 1) ^ 0xA001) : quint16(crc >> 1);
    }
    return crc;
}

QByteArray RtuFrame::adu(int unit, const QModbusPdu &pdu)
{
    QByteArray frame;
    frame.reserve(int(pdu.dataSize()) + 4);
    frame.append(char(quint8(unit)));
    frame.append(char(quint8(pdu.functionCode())));
    frame.append(pdu.data());
    const quint16 sum = crc(frame);
    frame.append(char(sum & 0xFF));
    frame.append(char(sum >> 8));
    return frame;
}

int RtuFrame::answerLength(const QByteArray &bytes)
{
    if (bytes.size() < 2)
        return 0;
    const quint8 fc = quint8(bytes.at(1));
    // An exception carries one code byte. Checked here because QModbusPdu::isException()
    // trips UBSan on Qt 6.4 (the function code is stored sign-extended).
    if (fc & 0x80)
        return 5;
    if (fc == 0)
        return -1;
    const QModbusResponse probe(QModbusPdu::FunctionCode(fc), bytes.mid(2));
    if (QModbusResponse::minimumDataSize(probe) < 0)
        return -1; // a function code Qt cannot size: nothing we asked for
    // Counted answers (FC03) need their byte count before their size is known.
    if (fc == QModbusPdu::ReadHoldingRegisters && bytes.size() < 3)
        return 0;
    const int dataSize = QModbusResponse::calculateDataSize(probe);
    if (dataSize < 0)
        return bytes.size() < 3 ? 0 : -1;
    return 2 + dataSize + 2;
}

int RtuFrame::requestLength(const QByteArray &bytes)
{
    if (bytes.size() < 2)
        return 0;
    const QModbusRequest probe(QModbusPdu::FunctionCode(quint8(bytes.at(1))), bytes.mid(2));
    const int size = QModbusRequest::calculateDataSize(probe);
    if (size < 0)
        return int(bytes.size());
    return 2 + size + 2;
}

bool RtuFrame::crcOk(const QByteArray &frame)
{
    if (frame.size() < 4)
        return false;
    const quint16 sum = crc(frame.left(frame.size() - 2));
    return quint8(frame.at(frame.size() - 2)) == (sum & 0xFF) &&
           quint8(frame.at(frame.size() - 1)) == (sum >> 8);
}

QModbusResponse RtuFrame::response(const QByteArray &frame)
{
    if (frame.size() < 4)
        return {};
    return QModbusResponse(QModbusPdu::FunctionCode(quint8(frame.at(1))),
                           frame.mid(2, frame.size() - 4));
}

double RtuFrame::charsMs(int bytes, int baud, int bitsPerChar)
{
    if (baud <= 0)
        return 0.0;
    return double(bytes) * bitsPerChar * 1000.0 / baud;
}

} // namespace stepcom
