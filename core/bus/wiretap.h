#pragma once

#include <QByteArray>
#include <QObject>

#include <functional>

namespace stepcom {

// The exact bytes QtSerialBus puts on and takes off the wire, recovered from its own
// "qt.modbus" debug output (the public API exposes only PDUs). This is what lets the traffic
// view show real frames, CRC included, and garbage as it arrived.
class WireTap
{
public:
    enum class Frame { RtuSent, RtuReceived, TcpSent, TcpReceived };
    using Sink = std::function<void(Frame frame, const QByteArray &raw)>;

    // Deliver frames to `sink` until detach(owner), which the owner must call before it dies.
    // Installs the message handler and category filter on first use; other messages pass through
    // untouched.
    static void attach(QObject *owner, Sink sink);
    static void detach(QObject *owner);

    // Install the message handler now: Qt's qt.modbus messages (warnings included) stay off
    // standard error unless `passThrough` (--verbose, or QT_LOGGING_RULES naming qt.modbus).
    static void install();
    static void setPassThrough(bool passThrough);

    // Parse one qt.modbus message; returns false when it carries no frame. Exposed for tests.
    static bool parse(const QString &message, Frame *frame, QByteArray *raw);
};

} // namespace stepcom
