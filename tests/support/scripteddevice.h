#pragma once

#include "sim/serve/ptybridge.h"

#include <QByteArray>
#include <QList>
#include <QObject>

#include <functional>
#include <optional>

namespace stepcom::test {

// CRC-16/Modbus, for crafting frames in tests -- an independent check of what QtSerialBus sends.
quint16 modbusCrc(const QByteArray &bytes);
QByteArray withCrc(QByteArray frame);
QByteArray fromHex(const char *spaced); // "01 03 00 00" -> bytes

// A fake controller at the far end of a pty bridge: it sees every byte the client sends,
// cuts it into request frames, and answers with whatever the test's responder returns
// (nothing, garbage, a late answer, an exception ...).
class ScriptedDevice : public QObject
{
    Q_OBJECT
public:
    // Return the bytes to send back, or nullopt for silence.
    using Responder =
        std::function<std::optional<QByteArray>(const QByteArray &request, int index)>;

    explicit ScriptedDevice(QObject *parent = nullptr);
    bool open(QString *error);
    QString clientPath() const { return m_bridge.path(PtyBridge::Side::A); }
    void setResponder(Responder responder) { m_responder = std::move(responder); }
    // Like the real controller, answers leave no sooner than 35 ms after the request: the link
    // discards sooner ones as late answers to an older request.
    void setAnswerDelayMs(int ms) { m_delayMs = ms; }
    // A device with 320 registers, answering FC03/06/10/05 correctly (writes are stored).
    void useRegisterDevice(int deviceId = 1);
    // What that register device answers to one request: responders that misbehave on some
    // requests hand the others on to it.
    std::optional<QByteArray> registerDevice(const QByteArray &request, int deviceId = 1);
    QList<quint16> registers;
    const QList<QByteArray> &requests() const { return m_requests; }
    PtyBridge &bridge() { return m_bridge; }

Q_SIGNALS:
    void requestReceived(const QByteArray &frame);

private:
    void onBytes(const QByteArray &bytes);

    PtyBridge m_bridge;
    QByteArray m_buffer;
    QList<QByteArray> m_requests;
    Responder m_responder;
    int m_delayMs = 35;
};

} // namespace stepcom::test
