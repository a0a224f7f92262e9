#pragma once

#include "bus/linkanswer.h"
#include "bus/linksettings.h"

#include <QObject>

namespace stepcom {

// What ModbusLink needs from a transport: open it, put one request on the line at a time, and
// hear how that attempt ended. The line's timing (silences, quiet time after trouble) is the
// transport's, because only it sees every byte.
class LinkBackend : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    // `opened(ok, reason)` follows exactly once (possibly from inside this call).
    virtual void open(const LinkSettings &settings) = 0;
    // Stop; no signal follows.
    virtual void close() = 0;
    // One request to `unit`; `answered` follows once, unless the link fails or closes first.
    virtual void send(int unit, const QModbusRequest &request, int timeoutMs) = 0;
    // After trouble the line must have been quiet this long before the next request.
    virtual void setQuietTimeMs(int ms) = 0;
    // Make the next request wait for the quiet time (a retried write's read-back).
    virtual void requireQuiet() = 0;
    virtual void setDeviceId(int) {}
    // A bus scan (ModbusLink::setScanMode): only an RTU transport can name a foreign answer.
    virtual void setScanMode(bool) {}
    // The adapter behind the line, once open ("FTDI FT232R, latency timer 1 ms"); empty when
    // not known.
    virtual QString adapterText() const { return {}; }

Q_SIGNALS:
    void opened(bool ok, const QString &reason);
    // The link died on its own after it was open (port vanished, connection closed).
    void failed(const QString &reason);
    // The request left (after the silences it had to wait for).
    void sent();
    // The request waits `ms` more before it leaves (a silence, an answer still owed).
    void writeDeferred(int ms);
    void answered(const stepcom::LinkAnswer &answer);
    // Bytes that crossed the line: `pduOffset` where the function code starts, `crcBytes` at
    // the end.
    void frame(bool sent, const QByteArray &raw, int pduOffset, int crcBytes);
    // Scan mode: a well-formed answer frame from `unit` that the request in flight (if any) was
    // not waiting for: its function code byte as on the wire and its data.
    void unitAnswered(int unit, int functionCode, const QByteArray &data);
    // The line showed whether the adapter echoes what it sends (a request's own bytes came
    // back where they cannot be its answer, or an answer came without them).
    void echoLearned(bool echoes);
};

} // namespace stepcom
