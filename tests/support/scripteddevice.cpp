#include "scripteddevice.h"

#include <QTimer>

namespace stepcom::test {

quint16 modbusCrc(const QByteArray &bytes)
{
    quint16 crc = 0xFFFF;
    for (char c : bytes) {
        crc ^= quint8(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? quint16((crc >> 1) ^ 0xA001) : quint16(crc >> 1);
    }
    return crc;
}

QByteArray withCrc(QByteArray frame)
{
    const quint16 crc = modbusCrc(frame);
    frame.append(char(crc & 0xFF));
    frame.append(char(crc >> 8));
    return frame;
}

QByteArray fromHex(const char *spaced)
{
    return QByteArray::fromHex(QByteArray(spaced).replace(' ', ""));
}

ScriptedDevice::ScriptedDevice(QObject *parent)
    : QObject(parent)
{
    // Take every byte the client sends; nothing is forwarded to the (unused) side B.
    m_bridge.setTap([this](PtyBridge::Side from, const QByteArray &bytes) {
        if (from == PtyBridge::Side::A)
            onBytes(bytes);
        return QByteArray();
    });
}

bool ScriptedDevice::open(QString *error)
{
    return m_bridge.open(error);
}

void ScriptedDevice::onBytes(const QByteArray &bytes)
{
    m_buffer += bytes;
    while (m_buffer.size() >= 8) {
        const int fc = quint8(m_buffer.at(1));
        int length = 8;
        if (fc == 0x10) {
            if (m_buffer.size() < 7)
                return;
            length = 9 + quint8(m_buffer.at(6));
        }
        if (m_buffer.size() < length)
            return;
        const QByteArray frame = m_buffer.left(length);
        m_buffer.remove(0, length);
        const int index = int(m_requests.size());
        m_requests << frame;
        Q_EMIT requestReceived(frame);
        if (!m_responder)
            continue;
        const std::optional<QByteArray> answer = m_responder(frame, index);
        if (!answer)
            continue;
        if (m_delayMs <= 0)
            m_bridge.inject(PtyBridge::Side::A, *answer);
        else
            QTimer::singleShot(m_delayMs, this,
                               [this, a = *answer] { m_bridge.inject(PtyBridge::Side::A, a); });
    }
}

void ScriptedDevice::useRegisterDevice(int deviceId)
{
    registers = QList<quint16>(320, 0);
    m_responder = [this, deviceId](const QByteArray &request, int) {
        return registerDevice(request, deviceId);
    };
}

std::optional<QByteArray> ScriptedDevice::registerDevice(const QByteArray &request, int deviceId)
{
    if (quint8(request.at(0)) != deviceId)
        return std::nullopt;
    auto word = [&](int at) {
        return int((quint8(request.at(at)) << 8) | quint8(request.at(at + 1)));
    };
    const int fc = quint8(request.at(1));
    const int address = word(2);
    QByteArray answer = request.left(2);
    auto exception = [&](int code) {
        QByteArray e;
        e.append(request.at(0));
        e.append(char(fc | 0x80));
        e.append(char(code));
        return withCrc(e);
    };
    switch (fc) {
    case 0x03: {
        const int count = word(4);
        if (count < 1 || count >= 50)
            return exception(3);
        if (address + count > registers.size())
            return exception(2);
        answer.append(char(count * 2));
        for (int i = 0; i < count; ++i) {
            answer.append(char(registers[address + i] >> 8));
            answer.append(char(registers[address + i] & 0xFF));
        }
        return withCrc(answer);
    }
    case 0x06:
        if (address >= registers.size())
            return exception(2);
        registers[address] = quint16(word(4));
        return request;
    case 0x10: {
        const int count = word(4);
        if (address + count > registers.size())
            return exception(2);
        for (int i = 0; i < count; ++i)
            registers[address + i] = quint16(word(7 + 2 * i));
        return withCrc(request.left(6));
    }
    case 0x05:
        return request;
    default:
        return exception(1);
    }
}

} // namespace stepcom::test
