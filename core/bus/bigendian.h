#pragma once

#include <QByteArray>

namespace stepcom::bigendian {

// Modbus puts registers on the wire high byte first; the callers have checked the size.
inline int byteAt(const QByteArray &bytes, int at)
{
    return quint8(bytes.at(at));
}

inline quint16 wordAt(const QByteArray &bytes, int at)
{
    return quint16((byteAt(bytes, at) << 8) | byteAt(bytes, at + 1));
}

} // namespace stepcom::bigendian
