#include "bus/modbuslink.h"

#include "bus/answercheck.h"
#include "bus/linkanswer.h"
#include "bus/modbustcpbackend.h"
#include "bus/rtutransport.h"
#include "bus/trafficlog.h"
#include "bus/wiretap.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLoggingCategory>

#include <cmath>

Q_LOGGING_CATEGORY(lcBus, "stepcom.bus", QtWarningMsg)

namespace stepcom {

namespace {

// Margin over the transaction timeout before we decide the port itself has hung.
constexpr int kWatchdogGraceMs = 1500;

QModbusRequest toPdu(const Request &req)
{
    QByteArray data;
    const auto put = [&data](int word) {
        data.append(char((word >> 8) & 0xFF));
        data.append(char(word & 0xFF));
    };
    put(req.address);
    switch (req.type) {
    case Request::Type::ReadHolding:
        put(req.count);
        return QModbusRequest(QModbusPdu::ReadHoldingRegisters, data);
    case Request::Type::WriteCoil:
        put(req.coilOn ? 0xFF00 : 0x0000);
        return QModbusRequest(QModbusPdu::WriteSingleCoil, data);
    case Request::Type::WriteHolding:
        break;
    }
    // One value goes out as FC06, more as one FC10: a 32-bit value is never split.
    if (req.values.size() == 1) {
        put(req.values.first());
        return QModbusRequest(QModbusPdu::WriteSingleRegister, data);
    }
    put(int(req.values.size()));
    data.append(char(req.values.size() * 2));
    for (quint16 v : req.values)
        put(v);
    return QModbusRequest(QModbusPdu::WriteMultipleRegisters, data);
}

} // namespace

ModbusLink::ModbusLink(QObject *parent)
    : QObject(parent)
    , m_traffic(new TrafficLog(this))
{
    m_clock.start();
    WireTap::install(); // qt.modbus warnings (the simulator's, the TCP client's) off stderr
    m_watchdog.setSingleShot(true);
    connect(&m_watchdog, &QTimer::timeout, this, &ModbusLink::onWatchdog);
    m_pumpTimer.setSingleShot(true);
    connect(&m_pumpTimer, &QTimer::timeout, this, &ModbusLink::pump);
    m_connectTimer.setSingleShot(true);
    connect(&m_connectTimer, &QTimer::timeout, this, [this] {
        failLink(tr("no connection to %1 within %2 s")
                     .arg(m_settings.describe())
                     .arg(m_connectTimer.interval() / 1000.0));
    });
}

ModbusLink::~ModbusLink()
{
    m_openPending = false;
    if (m_backend) {
        // A transaction still pending must tell no one: the owners of the callbacks are being
        // destroyed.
        m_backend->disconnect(this);
        m_backend->close();
        delete m_backend;
    }
}

void ModbusLink::setState(State state, const QString &reason)
{
    if (m_state == state)
        return;
    m_state = state;
    qCDebug(lcBus) << "link state" << state << reason;
    Q_EMIT stateChanged(state, reason);
}

void ModbusLink::setQuietTimeMs(int ms)
{
    m_quietMs = ms;
    if (m_backend)
        m_backend->setQuietTimeMs(ms);
}

void ModbusLink::open(const LinkSettings &settings)
{
    if (m_state != State::Disconnected)
        close(tr("reconnecting"));
    m_settings = settings;
    m_stats.echo = settings.transport == LinkSettings::Transport::Tcp ? 0 : -1; // learnt anew
    m_lastAnswer.clear();
    m_backoff.clear();
    ++m_attempt;
    m_failing = false;
    m_closingReason.clear(); // a callback reopens while the link closes: submit queues again
    m_openPending = true;
    setState(State::Connecting, settings.describe());

    if (const QString problem = settings.validate(); !problem.isEmpty()) {
        failLink(problem);
        return;
    }
    if (settings.transport == LinkSettings::Transport::Rtu) {
        // Tell the technician what is wrong before the port's generic "cannot open".
        const QFileInfo info(settings.portName);
        if (settings.portName.startsWith(QLatin1Char('/'))) {
            if (!info.exists()) {
                failLink(tr("serial port %1 does not exist (is the adapter plugged in?)")
                             .arg(settings.portName));
                return;
            }
            if (const QString why = RtuTransport::notASerialPort(settings.portName);
                !why.isEmpty()) {
                failLink(why);
                return;
            }
            if (!info.isReadable() || !info.isWritable()) {
                failLink(tr("no permission to open %1: add your user to the group that owns it "
                            "(on Debian and Ubuntu: sudo usermod -aG dialout $USER), then log "
                            "out and in again")
                             .arg(settings.portName));
                return;
            }
        }
    }
    if (settings.transport == LinkSettings::Transport::Tcp)
        m_backend = new ModbusTcpBackend(this);
    else
        m_backend = new RtuTransport(this);
    m_backend->setQuietTimeMs(m_quietMs);
    m_backend->setScanMode(m_scanMode);
    connect(m_backend, &LinkBackend::unitAnswered, this, &ModbusLink::onUnitAnswered);
    connect(m_backend, &LinkBackend::echoLearned, this, &ModbusLink::onEchoLearned);
    connect(m_backend, &LinkBackend::opened, this, &ModbusLink::onBackendOpened);
    connect(m_backend, &LinkBackend::failed, this, &ModbusLink::failLink);
    connect(m_backend, &LinkBackend::answered, this, &ModbusLink::onAnswered);
    connect(m_backend, &LinkBackend::frame, this, &ModbusLink::onFrame);
    // The watchdog waits for the driver, not for the silences the transport keeps: it starts
    // again for the answer once the request left, and covers a wait announced before.
    connect(m_backend, &LinkBackend::writeDeferred, this, [this](int ms) {
        if (m_inFlight)
            m_watchdog.start(ms + m_inFlightTimeoutMs + m_settings.turnaroundMs + kWatchdogGraceMs);
    });
    connect(m_backend, &LinkBackend::sent, this, [this] {
        if (m_inFlight)
            m_watchdog.start(m_inFlightTimeoutMs + m_settings.turnaroundMs + kWatchdogGraceMs);
    });
    m_traffic->addEvent(tr("connecting to %1").arg(settings.describe()));
    const quint64 attempt = m_attempt;
    m_backend->open(settings);
    if (attempt == m_attempt && m_state == State::Connecting)
        m_connectTimer.start(std::max(3000, settings.timeoutMs * 4));
}

void ModbusLink::onBackendOpened(bool ok, const QString &reason)
{
    if (m_state != State::Connecting)
        return;
    if (!ok) {
        failLink(reason.isEmpty() ? tr("cannot open %1").arg(m_settings.describe()) : reason);
        return;
    }
    m_connectTimer.stop();
    setState(State::Connected, m_settings.describe());
    m_traffic->addEvent(tr("connected to %1").arg(m_settings.describe()));
    m_stats.adapter = m_backend ? m_backend->adapterText() : QString();
    if (!m_stats.adapter.isEmpty())
        m_traffic->addEvent(tr("adapter: %1").arg(m_stats.adapter));
    finishOpen(true, QString());
    schedulePump(0);
}

void ModbusLink::finishOpen(bool ok, const QString &reason)
{
    if (!m_openPending)
        return;
    m_openPending = false;
    m_connectTimer.stop();
    Q_EMIT opened(ok, reason);
}

void ModbusLink::failLink(const QString &reason)
{
    // A vanished port repeats its errors: act once.
    if (m_failing || m_state == State::Disconnected) {
        if (m_openPending)
            finishOpen(false, reason);
        return;
    }
    m_failing = true;
    const bool wasConnected = m_state == State::Connected;
    qCInfo(lcBus) << "link failed:" << reason;
    m_traffic->addEvent(tr("link lost: %1").arg(reason), TrafficEntry::Kind::Error);
    const quint64 attempt = m_attempt;
    close(reason);
    // A callback may have opened the link again: that attempt's verdict is its own.
    if (attempt == m_attempt)
        finishOpen(false, reason);
    if (wasConnected)
        Q_EMIT lost(reason);
}

void ModbusLink::close(const QString &reason)
{
    m_watchdog.stop();
    m_pumpTimer.stop();
    m_connectTimer.stop();
    if (m_backend) {
        LinkBackend *backend = std::exchange(m_backend, nullptr);
        backend->disconnect(this);
        backend->close();
        backend->deleteLater();
    }
    const QString why = reason.isEmpty() ? tr("link closed") : reason;
    // The results run callbacks, and those submit follow-ups (a write's read-back, the next
    // poll) or even open the link again. Until the state says so, the link still looks
    // connected: what is submitted meanwhile fails with the rest instead of waiting in the
    // queue of a closed link, unless a callback opened a new connection, which owns the
    // state from then on.
    const quint64 attempt = m_attempt;
    m_closingReason = why;
    failAll(why);
    if (attempt != m_attempt)
        return;
    m_closingReason.clear();
    Q_ASSERT(!m_inFlight && m_queue.isEmpty());
    if (m_state != State::Disconnected)
        m_traffic->addEvent(tr("disconnected: %1").arg(why));
    setState(State::Disconnected, why);
    if (m_openPending)
        finishOpen(false, why);
}

void ModbusLink::failAll(const QString &reason)
{
    const quint64 attempt = m_attempt;
    const auto fail = [this, &reason](QueuedRequest item) {
        Result r;
        r.error = QModbusDevice::ConnectionError;
        r.attempts = item.attempts;
        r.mayHaveActed = item.attempts > 0 && item.request.type == Request::Type::WriteCoil;
        r.errorText = tr("%1: not done, %2").arg(describe(item.request), reason);
        complete(std::move(item), r);
    };
    if (m_inFlight)
        fail(*std::exchange(m_inFlight, std::nullopt));
    // One at a time: a callback may submit more (they fail too) or open the link again (then
    // what is still queued goes out on the new connection).
    while (attempt == m_attempt && !m_queue.isEmpty())
        fail(m_queue.takeNext());
}

quint64 ModbusLink::submit(Request request, ResultCallback callback, QObject *context)
{
    QueuedRequest item;
    item.id = m_nextId++;
    item.request = std::move(request);
    item.callback = std::move(callback);
    item.context = context;
    item.hasContext = context != nullptr;
    const quint64 id = item.id;
    if (!m_closingReason.isEmpty()) {
        // Submitted by a callback while the link closes (see close()): it fails with the rest.
        m_queue.push(std::move(item));
        return id;
    }
    if (m_state != State::Connected) {
        Result r;
        r.error = QModbusDevice::ConnectionError;
        r.errorText = tr("%1: not connected").arg(describe(item.request));
        // Asynchronous like every other result, so callers need no special case.
        QTimer::singleShot(
            0, this, [this, item = std::move(item), r]() mutable { complete(std::move(item), r); });
        return id;
    }
    m_queue.push(std::move(item));
    schedulePump(0);
    return id;
}

int ModbusLink::cancelQueued(Priority from, const QString &reason)
{
    QList<QueuedRequest> items = m_queue.takeFrom(from);
    for (QueuedRequest &item : items) {
        Result r;
        r.error = QModbusDevice::ReplyAbortedError;
        r.errorText = tr("%1: cancelled%2")
                          .arg(describe(item.request),
                               reason.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(reason));
        complete(std::move(item), r);
    }
    return int(items.size());
}

void ModbusLink::setScanMode(bool on)
{
    m_scanMode = on;
    if (m_backend)
        m_backend->setScanMode(on);
}

void ModbusLink::onUnitAnswered(int unit, int functionCode, const QByteArray &data)
{
    QList<quint16> values;
    const int exception = AnswerCheck::exceptionCode(functionCode, data);
    if (exception == 0 && functionCode == 0x03) {
        for (int at = 1; at + 1 < data.size(); at += 2)
            values << quint16((quint8(data.at(at)) << 8) | quint8(data.at(at + 1)));
    }
    Q_EMIT unitAnswered(unit, exception, values);
}

std::optional<double> ModbusLink::answerTimeMs(int unit) const
{
    if (m_settings.transport != LinkSettings::Transport::Rtu)
        return std::nullopt;
    const auto it = m_stats.answerTimes.constFind(unit);
    if (it == m_stats.answerTimes.cend())
        return std::nullopt;
    return it->answerMs(m_settings.charTimeMs());
}

int ModbusLink::timeoutFor(const Request &req) const
{
    if (req.timeoutMs > 0)
        return req.timeoutMs;
    const int ceiling = m_settings.timeoutMs;
    const int id = req.unitId > 0 ? req.unitId : m_settings.deviceId;
    const RoundTrips trips = m_stats.byUnit.value(id);
    if (!m_settings.adaptTimeout || m_scanMode || trips.count < quint64(kAdaptAfter))
        return ceiling;
    // The answer's own frame on the wire (0 on TCP), and the latency of USB adapters, which
    // pass bytes on in packets (FTDI: 16 ms each way).
    const int answerBytes = req.type == Request::Type::ReadHolding ? 5 + 2 * req.count : 8;
    const double frameMs = m_settings.charTimeMs() * answerBytes;
    constexpr double kSlackMs = 40;
    const double floor = std::max(0, m_settings.answerDelayMs) + frameMs + kSlackMs;
    const double fitted = 4.0 * double(trips.median()) + frameMs + kSlackMs / 2;
    const double backedOff = std::max(floor, fitted) * double(1 << m_backoff.value(id, 0));
    return std::min(ceiling, int(std::ceil(backedOff)));
}

void ModbusLink::onEchoLearned(bool echoes)
{
    m_stats.echo = echoes ? 1 : 0;
    if (echoes == m_settings.echo) {
        Q_EMIT statsChanged();
        return;
    }
    if (echoes) {
        m_traffic->addEvent(tr("the adapter echoes what it sends: the request's own bytes came "
                               "back before the answer; they are skipped from now on"),
                            TrafficEntry::Kind::Error);
        Q_EMIT echoDetected();
    } else {
        m_traffic->addEvent(tr("the adapter does not echo what it sends (the echo option is on): "
                               "answers are read without skipping a copy"),
                            TrafficEntry::Kind::Error);
    }
    Q_EMIT statsChanged();
}

void ModbusLink::resetStats()
{
    const int echo = m_stats.echo; // what the line showed of the adapter stays known
    m_stats = LinkStats();
    m_stats.echo = echo;
    Q_EMIT statsChanged();
}

void ModbusLink::schedulePump(int delayMs)
{
    if (!m_pumpTimer.isActive() || m_pumpTimer.remainingTime() > delayMs)
        m_pumpTimer.start(delayMs);
}

void ModbusLink::pump()
{
    if (m_state != State::Connected || m_inFlight || m_queue.isEmpty() || !m_backend)
        return;
    if (const qint64 left = m_notBefore.remainingTime(); left > 0) {
        schedulePump(int(left));
        return;
    }
    m_inFlight = m_queue.takeNext();
    m_inFlight->attempts += 1;
    const Request &req = m_inFlight->request;
    const int id = req.unitId > 0 ? req.unitId : m_settings.deviceId;
    ++m_stats.requests;
    Q_EMIT dispatched(m_inFlight->id, m_inFlight->request);
    // The transport waits for the silences the line needs; the watchdog covers that too.
    const int timeoutMs = timeoutFor(req);
    m_inFlightTimeoutMs = timeoutMs;
    m_watchdog.start(timeoutMs + m_quietMs + m_settings.turnaroundMs + kWatchdogGraceMs);
    m_backend->send(id, toPdu(req), timeoutMs);
}

QString ModbusLink::noAnswerText(const Request &req, const LinkAnswer &a) const
{
    if (a.crcErrors > 0 && a.discarded.size() == a.crcErrors)
        return tr("%1: answers had a bad checksum (CRC)").arg(describe(req));
    QString text = tr("%1: no answer within %2 ms").arg(describe(req)).arg(m_inFlightTimeoutMs);
    if (!a.discarded.isEmpty())
        text += tr(" (discarded: %1)").arg(a.discarded.join(QStringLiteral("; ")));
    const int id = req.unitId > 0 ? req.unitId : m_settings.deviceId;
    const qint64 answeredAgo =
        m_lastAnswer.value(id, -1) < 0 ? -1 : m_clock.elapsed() - m_lastAnswer.value(id);
    if (a.discarded.isEmpty() && a.crcErrors == 0 && !a.onlyEcho && answeredAgo >= 0 &&
        answeredAgo < kRecentAnswerMs) {
        // The same line and id answered a moment ago: the wiring and settings are fine.
        text += tr(" -- it answered %1 s ago: busy (writing its flash?), switched off, or a "
                   "disturbed line")
                    .arg(double(answeredAgo) / 1000.0, 0, 'f', 1);
    } else if (a.discarded.isEmpty() && a.crcErrors == 0 && !a.onlyEcho) {
        if (m_settings.isNetwork())
            text += tr(" -- check the device id (%1), the host and port, and the converter's "
                       "serial settings; the bus scan finds controllers (the window's Scan bus, or "
                       "stepcomctl scan)")
                        .arg(id);
        else
            text += tr(" -- check the device id (%1), the baud rate and parity (%2), the A/B "
                       "wiring; the bus scan finds controllers (the window's Scan bus, or "
                       "stepcomctl scan)")
                        .arg(id)
                        .arg(QStringLiteral("%1 8%2%3")
                                 .arg(m_settings.baud)
                                 .arg(LinkSettings::parityName(m_settings.parity).at(0).toUpper())
                                 .arg(m_settings.stopBits == QSerialPort::TwoStop ? 2 : 1));
    }
    if (a.onlyEcho)
        text += tr(" -- only the request's own bytes came back (the adapter's echo): the "
                   "controller did not answer");
    return text;
}

void ModbusLink::onAnswered(const LinkAnswer &a)
{
    if (!m_inFlight)
        return;
    m_watchdog.stop();
    QueuedRequest item = *std::exchange(m_inFlight, std::nullopt);
    const Request &req = item.request;
    m_stats.crcErrors += quint64(a.crcErrors);
    const int stale = int(a.discarded.size()) - a.crcErrors;
    if (stale > 0)
        m_stats.stale += quint64(stale);
    for (const QString &why : a.discarded)
        m_traffic->addEvent(tr("stale/foreign answer discarded: %1").arg(why),
                            TrafficEntry::Kind::Error);

    Result r;
    r.attempts = item.attempts;
    bool retry = false;
    int retryPauseMs = 0;
    switch (a.kind) {
    case LinkAnswer::Kind::Answer:
        ++m_stats.answers;
        m_lastAnswer.insert(req.unitId > 0 ? req.unitId : m_settings.deviceId, m_clock.elapsed());
        m_backoff.remove(req.unitId > 0 ? req.unitId : m_settings.deviceId);
        if (const int code = a.exceptionCode; code != 0) {
            ++m_stats.exceptions;
            ++m_stats.exceptionsByCode[code];
            r.error = QModbusDevice::ProtocolError;
            r.exceptionCode = code;
            r.errorText =
                tr("%1: the controller refused: %2").arg(describe(req), exceptionText(code));
            // Busy means it did not act: even a motion command may go again, after a pause.
            if (code == 6 && item.attempts <= m_settings.retries) {
                retry = true;
                retryPauseMs = kBusyPauseMs;
            }
            break;
        }
        // Both frames on the wire (address, PDU, CRC) and the silence between them.
        m_stats.addRoundTrip(a.roundTripMs, req.unitId > 0 ? req.unitId : m_settings.deviceId,
                             int(toPdu(req).size() + a.response.size()) + 6 + 7);
        if (req.timeoutMs <= 0)
            m_stats.timeoutMs = timeoutFor(req);
        r.ok = true;
        r.roundTripMs = a.roundTripMs;
        if (req.type == Request::Type::ReadHolding) {
            const QByteArray d = a.response.data(); // byte count, then the registers
            for (int at = 1; at + 1 < d.size(); at += 2)
                r.values << quint16((quint8(d.at(at)) << 8) | quint8(d.at(at + 1)));
        }
        // Another try was needed: the answers of the earlier ones may still come, and the next
        // request (a write's read-back) must not meet them.
        if (item.attempts > 1)
            m_backend->requireQuiet();
        break;
    case LinkAnswer::Kind::Timeout: {
        ++m_stats.timeouts;
        if (!m_scanMode) {
            int &backoff = m_backoff[req.unitId > 0 ? req.unitId : m_settings.deviceId];
            backoff = std::min(backoff + 1, kMaxBackoff);
        }
        r.error = QModbusDevice::TimeoutError;
        r.errorText = noAnswerText(req, a);
        retry = req.retryable && item.attempts <= m_settings.retries;
        if (!retry && req.type == Request::Type::WriteCoil) {
            r.mayHaveActed = true;
            r.errorText += tr(" -- the controller may have acted on it");
        }
        break;
    }
    case LinkAnswer::Kind::Failed:
        r.error = QModbusDevice::WriteError;
        r.errorText = tr("%1: could not send: %2").arg(describe(req), a.errorText);
        break;
    }

    if (!r.ok && (retry || a.kind == LinkAnswer::Kind::Timeout))
        m_traffic->addEvent(r.errorText, TrafficEntry::Kind::Error);
    if (retry && m_backend) {
        m_queue.pushFront(std::move(item));
        if (retryPauseMs > 0)
            m_notBefore.setRemainingTime(retryPauseMs);
        Q_EMIT statsChanged();
        schedulePump(retryPauseMs);
        return;
    }
    if (!r.ok)
        ++m_stats.failed;
    Q_EMIT statsChanged();
    complete(std::move(item), r);
    schedulePump(0);
}

void ModbusLink::onWatchdog()
{
    if (!m_inFlight)
        return;
    failLink(tr("the port stopped responding (no answer and no timeout from the driver)"));
}

void ModbusLink::complete(QueuedRequest item, Result result)
{
    Q_EMIT finished(item.id, item.request, result);
    if (item.hasContext && !item.context)
        return;
    if (item.callback)
        item.callback(result);
}

void ModbusLink::onFrame(bool sent, const QByteArray &raw, int pduOffset, int crcBytes)
{
    if (sent)
        m_stats.bytesSent += quint64(raw.size());
    else
        m_stats.bytesReceived += quint64(raw.size());
    m_traffic->addFrame(sent ? TrafficEntry::Direction::Sent : TrafficEntry::Direction::Received,
                        raw, pduOffset, crcBytes, m_inFlight ? &m_inFlight->request : nullptr);
}

QString ModbusLink::describe(const Request &request) const
{
    QString where;
    if (request.type == Request::Type::WriteCoil)
        where = tr("coil %1").arg(request.address + 1, 5, 10, QLatin1Char('0'));
    else
        where = QStringLiteral("%1 (0x%2)")
                    .arg(40001 + request.address)
                    .arg(QString::number(request.address, 16)
                             .rightJustified(4, QLatin1Char('0'))
                             .toUpper());
    if (request.unitId > 0 && request.unitId != m_settings.deviceId)
        where = tr("id %1, %2").arg(request.unitId).arg(where);
    if (request.what.isEmpty())
        return where;
    return QStringLiteral("%1 [%2]").arg(request.what, where);
}

} // namespace stepcom
