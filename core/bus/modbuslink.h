#pragma once

#include "bus/linksettings.h"
#include "bus/linkstats.h"
#include "bus/request.h"
#include "bus/requestqueue.h"

#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <optional>

namespace stepcom {

class LinkBackend;
struct LinkAnswer;
class TrafficLog;

// The link to one line. One transaction on the wire at a time, taken from a priority queue
// (emergency > commands and writes > reads > polling); our own retries, so an emergency stop
// can go out between two attempts of a poll; our own watchdog, because a vanished port can
// leave a transaction unfinished forever. The line itself is a LinkBackend: StepCom's own RTU
// transport (serial port or RTU over TCP) or QModbusTcpClient for Modbus TCP.
class ModbusLink : public QObject
{
    Q_OBJECT
public:
    enum class State { Disconnected, Connecting, Connected };
    Q_ENUM(State)

    explicit ModbusLink(QObject *parent = nullptr);
    ~ModbusLink() override;

    // Connect; `opened(ok, reason)` follows exactly once for this attempt.
    void open(const LinkSettings &settings);
    // Disconnect; everything queued and in flight fails with "link closed" (or `reason`), and
    // so does what their callbacks submit meanwhile -- unless a callback opened the link again.
    void close(const QString &reason = QString());
    State state() const { return m_state; }
    bool isConnected() const { return m_state == State::Connected; }
    const LinkSettings &settings() const { return m_settings; }
    // After the controller's id changed (register 40212) the link follows without reopening.
    void setDeviceId(int id) { m_settings.deviceId = id; }
    // Pause before retrying a request the controller refused as busy (exception 06).
    static constexpr int kBusyPauseMs = 200;

    // Queue a request; `callback` runs once with the result (not if `context` died first).
    quint64 submit(Request request, ResultCallback callback, QObject *context = nullptr);
    // Fail every queued (not in-flight) request of priority `from` or lower; returns how many.
    int cancelQueued(Priority from, const QString &reason = QString());
    int queuedCount() const { return m_queue.size(); }
    bool isBusy() const { return m_inFlight.has_value(); }

    // Silence after a timeout or a bad answer before the next request, so a late answer to
    // the old request cannot be taken for the answer to the new one.
    void setQuietTimeMs(int ms);
    int quietTimeMs() const { return m_quietMs; }

    // A bus scan: a probe nothing answered leaves no quiet time and owes no late answer, its
    // timeout counts from the start of the request (the frame is in the scanner's), and
    // every well-formed answer from a unit other than the one asked is reported
    // (`unitAnswered`): an RTU answer carries its address, so a late one still names its id.
    void setScanMode(bool on);

    // The answer timeout for `request` now: its own, or the settings' fitted to the round
    // trips measured for its device (LinkSettings::adaptTimeout). After a timeout the fitted
    // one doubles for that device with each further timeout (up to the set timeout) until it
    // answers again, as TCP backs off its retransmission timer: a controller or a computer
    // busy for a moment costs one more try, not a string of them, while a silent device is
    // still given up on at the set timeout.
    int timeoutFor(const Request &request) const;
    // Round trips counted before the timeout adapts to them.
    static constexpr int kAdaptAfter = 5;
    // Doublings of the fitted timeout at most (x8).
    static constexpr int kMaxBackoff = 3;
    // A controller that answered this recently is not told to check its id, baud and wiring.
    static constexpr qint64 kRecentAnswerMs = 10000;

    // The controller's own answer time, told apart from the bytes' time on the wire
    // (AnswerTimeFit): known on a serial line once answers of different lengths were timed;
    // nothing on TCP, on a pseudo-terminal without a wire, or before.
    std::optional<double> answerTimeMs(int unit) const;

    const LinkStats &stats() const { return m_stats; }
    void resetStats();
    TrafficLog *traffic() const { return m_traffic; }

Q_SIGNALS:
    void opened(bool ok, const QString &reason);
    void stateChanged(stepcom::ModbusLink::State state, const QString &reason);
    // The link dropped on its own (port vanished, gateway closed, watchdog).
    void lost(const QString &reason);
    // A request was put on the wire.
    void dispatched(quint64 id, const stepcom::Request &request);
    void finished(quint64 id, const stepcom::Request &request, const stepcom::Result &result);
    void statsChanged();
    // The request's own bytes came back where they cannot be its answer and the echo option is
    // off: the adapter echoes what it sends. The link skips the copies from now on (offer to
    // remember the option).
    void echoDetected();
    // Scan mode: an answer from `unit` that no request in flight was waiting for (a read's
    // registers, or the exception code it refused with).
    void unitAnswered(int unit, int exceptionCode, const QList<quint16> &values);

private:
    void setState(State state, const QString &reason);
    void finishOpen(bool ok, const QString &reason);
    void onBackendOpened(bool ok, const QString &reason);
    void pump();
    void schedulePump(int delayMs);
    void onAnswered(const LinkAnswer &answer);
    void onWatchdog();
    void complete(QueuedRequest item, Result result);
    void failLink(const QString &reason);
    void failAll(const QString &reason);
    void onUnitAnswered(int unit, int functionCode, const QByteArray &data);
    void onEchoLearned(bool echoes);
    void onFrame(bool sent, const QByteArray &raw, int pduOffset, int crcBytes);
    QString describe(const Request &request) const;
    QString noAnswerText(const Request &request, const LinkAnswer &answer) const;

    LinkSettings m_settings;
    State m_state = State::Disconnected;
    LinkBackend *m_backend = nullptr;
    bool m_openPending = false;
    QTimer m_connectTimer;
    RequestQueue m_queue;
    std::optional<QueuedRequest> m_inFlight;
    QTimer m_watchdog;
    QTimer m_pumpTimer;
    int m_quietMs = 100;
    bool m_scanMode = false;
    QDeadlineTimer m_notBefore; // a busy controller gets a pause before the next request
    quint64 m_nextId = 1;
    LinkStats m_stats;
    TrafficLog *m_traffic;
    bool m_failing = false;
    int m_inFlightTimeoutMs = 0;
    QElapsedTimer m_clock;
    QHash<int, qint64> m_lastAnswer; // by device id: m_clock's time of its last answer
    QHash<int, int> m_backoff;       // by device id: timeouts since its last answer (capped)
    QString m_closingReason;         // while close() fails what was queued; empty otherwise
    quint64 m_attempt = 0;           // connect attempts, so stale deferred checks do nothing
};

} // namespace stepcom
