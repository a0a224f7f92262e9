#pragma once

#include "bus/rtuframe.h"

#include <QByteArray>

namespace stepcom::test {

// "01 03 00 00 00 02" and its CRC, as on the wire.
inline QByteArray rtu(const char *hex)
{
    QByteArray f = QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
    const quint16 sum = RtuFrame::crc(f);
    f.append(char(sum & 0xFF));
    f.append(char(sum >> 8));
    return f;
}

// The same with its CRC spoiled.
inline QByteArray badCrc(const char *hex)
{
    QByteArray f = rtu(hex);
    f[f.size() - 1] = char(f.at(f.size() - 1) ^ 0x5A);
    return f;
}

} // namespace stepcom::test
