#include "bus/modbuslink.h"

#include "bus/trafficlog.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QModbusRtuSerialClient>
#include <QModbusTcpClient>

Q_LOGGING_CATEGORY(lcBus, "stepcom.bus", QtWarningMsg)

namespace stepcom {

namespace {

// Margin over the transaction timeout before we decide the port itself has hung.
constexpr int kWatchdogGraceMs = 1500;

} // namespace

ModbusLink::ModbusLink(QObject *parent)
    : QObject(parent)
    , m_traffic(new TrafficLog(this))
{
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
    WireTap::attach(
        this, [this](WireTap::Frame frame, const QByteArray &raw) { onWireFrame(frame, raw); });
}

ModbusLink::~ModbusLink()
{
    WireTap::detach(this);
    m_openPending = false;
    if (m_client) {
        m_client->disconnect(this);
        // A reply still pending finishes (with an error) when the device disconnects: nobody
        // may hear of it now, the owners of the callbacks are being destroyed.
        for (QModbusReply *reply : m_client->findChildren<QModbusReply *>())
            reply->disconnect(this);
        m_client->disconnectDevice();
        delete m_client; // replies are its children and die with it; nothing can answer now
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

void ModbusLink::open(const LinkSettings &settings)
{
    if (m_state != State::Disconnected)
        close(tr("reconnecting"));
    m_settings = settings;
    ++m_attempt;
    m_failing = false;
    m_openPending = true;
    setState(State::Connecting, settings.describe());

    if (const QString problem = settings.validate(); !problem.isEmpty()) {
        failLink(problem);
        return;
    }
    if (settings.transport == LinkSettings::Transport::Rtu) {
        // Tell the technician what is wrong before Qt's generic "cannot open".
        const QFileInfo info(settings.portName);
        if (settings.portName.startsWith(QLatin1Char('/'))) {
            if (!info.exists()) {
                failLink(tr("serial port %1 does not exist (is the adapter plugged in?)")
                             .arg(settings.portName));
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
        auto *rtu = new QModbusRtuSerialClient(this);
        rtu->setConnectionParameter(QModbusDevice::SerialPortNameParameter, settings.portName);
        // Qt defaults to 19200 baud, even parity: set every serial parameter explicitly.
        rtu->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, settings.baud);
        rtu->setConnectionParameter(QModbusDevice::SerialParityParameter, settings.parity);
        rtu->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
        rtu->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, settings.stopBits);
        m_client = rtu;
    } else {
        auto *tcp = new QModbusTcpClient(this);
        tcp->setConnectionParameter(QModbusDevice::NetworkAddressParameter, settings.host);
        tcp->setConnectionParameter(QModbusDevice::NetworkPortParameter, settings.tcpPort);
        m_client = tcp;
    }
    m_client->setTimeout(settings.timeoutMs);
    m_client->setNumberOfRetries(0); // retries are ours, so emergencies can cut in between
    connect(m_client, &QModbusDevice::stateChanged, this,
            [this](QModbusDevice::State s) { onClientState(int(s)); });
    connect(m_client, &QModbusDevice::errorOccurred, this,
            [this](QModbusDevice::Error e) { onClientError(int(e)); });
    m_traffic->addEvent(tr("connecting to %1").arg(settings.describe()));
    if (!m_client->connectDevice()) {
        // The client may already have reported the error and been torn down inside the call.
        if (m_client)
            failLink(m_client->errorString().isEmpty()
                         ? tr("cannot open %1").arg(settings.describe())
                         : m_client->errorString());
        return;
    }
    if (!m_client)
        return;
    if (m_client->state() == QModbusDevice::ConnectedState) {
        onClientState(int(QModbusDevice::ConnectedState));
    } else {
        m_connectTimer.start(std::max(3000, settings.timeoutMs * 4));
    }
}

void ModbusLink::finishOpen(bool ok, const QString &reason)
{
    if (!m_openPending)
        return;
    m_openPending = false;
    m_connectTimer.stop();
    Q_EMIT opened(ok, reason);
}

void ModbusLink::onClientState(int s)
{
    const auto state = QModbusDevice::State(s);
    if (state == QModbusDevice::ConnectedState && m_state == State::Connecting) {
        m_sinceQuiet.start();
        m_quietRemainingMs = 0;
        setState(State::Connected, m_settings.describe());
        m_traffic->addEvent(tr("connected to %1").arg(m_settings.describe()));
        finishOpen(true, QString());
        schedulePump(0);
    } else if (state == QModbusDevice::UnconnectedState && m_state != State::Disconnected &&
               !m_failing) {
        // Qt sets the state before the error that explains it: give the error a moment.
        const quint64 attempt = m_attempt;
        QTimer::singleShot(0, this, [this, attempt] {
            if (attempt != m_attempt || m_failing || m_state == State::Disconnected)
                return;
            failLink(m_client && !m_client->errorString().isEmpty() ? m_client->errorString()
                                                                    : tr("connection closed"));
        });
    }
}

void ModbusLink::onClientError(int e)
{
    const auto error = QModbusDevice::Error(e);
    // Per-reply errors arrive on the reply; these are the link-level ones.
    if (error == QModbusDevice::ConnectionError || error == QModbusDevice::ReadError ||
        error == QModbusDevice::WriteError || error == QModbusDevice::ConfigurationError) {
        const QString text = m_client ? m_client->errorString() : QString();
        failLink(text.isEmpty() ? tr("the port reported an error") : text);
    }
}

void ModbusLink::failLink(const QString &reason)
{
    // Qt 6.4 repeats port errors in a tight loop once the device vanished: act once.
    if (m_failing || m_state == State::Disconnected) {
        if (m_openPending)
            finishOpen(false, reason);
        return;
    }
    m_failing = true;
    const bool wasConnected = m_state == State::Connected;
    qCInfo(lcBus) << "link failed:" << reason;
    m_traffic->addEvent(tr("link lost: %1").arg(reason), TrafficEntry::Kind::Error);
    close(reason);
    finishOpen(false, reason);
    if (wasConnected)
        Q_EMIT lost(reason);
}

void ModbusLink::close(const QString &reason)
{
    m_watchdog.stop();
    m_pumpTimer.stop();
    m_connectTimer.stop();
    if (m_client) {
        QModbusClient *client = std::exchange(m_client, nullptr);
        client->disconnect(this);
        client->disconnectDevice();
        // Its replies are children: deleting later lets any finished() already queued run
        // harmlessly instead of into freed memory.
        client->deleteLater();
    }
    m_reply.clear();
    const QString why = reason.isEmpty() ? tr("link closed") : reason;
    failAll(why);
    if (m_state != State::Disconnected)
        m_traffic->addEvent(tr("disconnected: %1").arg(why));
    setState(State::Disconnected, why);
    if (m_openPending)
        finishOpen(false, why);
}

void ModbusLink::failAll(const QString &reason)
{
    QList<QueuedRequest> items = m_queue.takeAll();
    if (m_inFlight)
        items.prepend(*std::exchange(m_inFlight, std::nullopt));
    for (QueuedRequest &item : items) {
        Result r;
        r.error = QModbusDevice::ConnectionError;
        r.attempts = item.attempts;
        r.mayHaveActed = item.attempts > 0 && item.request.type == Request::Type::WriteCoil;
        r.errorText = tr("%1: not done, %2").arg(describe(item.request), reason);
        complete(std::move(item), r);
    }
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

void ModbusLink::resetStats()
{
    m_stats = LinkStats();
    Q_EMIT statsChanged();
}

void ModbusLink::schedulePump(int delayMs)
{
    if (!m_pumpTimer.isActive() || m_pumpTimer.remainingTime() > delayMs)
        m_pumpTimer.start(delayMs);
}

void ModbusLink::pump()
{
    if (m_state != State::Connected || m_inFlight || m_queue.isEmpty() || !m_client)
        return;
    const qint64 quietLeft = m_quietRemainingMs - m_sinceQuiet.elapsed();
    if (quietLeft > 0) {
        schedulePump(int(quietLeft));
        return;
    }
    // In flight before it is sent: a TCP client writes (and logs the frame) inside the call.
    m_inFlight = m_queue.takeNext();
    m_inFlight->attempts += 1;
    const Request req = m_inFlight->request;
    const int id = req.unitId > 0 ? req.unitId : m_settings.deviceId;
    ++m_stats.requests;
    m_sentAt.start();
    Q_EMIT dispatched(m_inFlight->id, req);
    QModbusReply *reply = nullptr;
    switch (req.type) {
    case Request::Type::ReadHolding:
        reply = m_client->sendReadRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, req.address, req.count), id);
        break;
    case Request::Type::WriteHolding:
        // One value goes out as FC06, more as one FC10: a 32-bit value is never split.
        reply = m_client->sendWriteRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, req.address, req.values), id);
        break;
    case Request::Type::WriteCoil:
        reply = m_client->sendWriteRequest(
            QModbusDataUnit(QModbusDataUnit::Coils, req.address,
                            QList<quint16>{req.coilOn ? quint16(1) : quint16(0)}),
            id);
        break;
    }
    if (!m_inFlight)
        return; // the link failed while sending; everything was reported by failLink
    if (!reply) {
        Result r;
        r.error = QModbusDevice::WriteError;
        r.attempts = m_inFlight->attempts;
        r.errorText = tr("%1: could not send: %2")
                          .arg(describe(req), m_client ? m_client->errorString() : QString());
        complete(*std::exchange(m_inFlight, std::nullopt), r);
        schedulePump(0);
        return;
    }
    m_reply = reply;
    if (reply->isFinished()) {
        onReplyFinished(reply);
        return;
    }
    connect(reply, &QModbusReply::finished, this, [this, reply] { onReplyFinished(reply); });
    m_watchdog.start(m_settings.timeoutMs + kWatchdogGraceMs);
}

void ModbusLink::onReplyFinished(QModbusReply *reply)
{
    reply->deleteLater(); // only now: deleting an unfinished reply can crash Qt 6.4
    if (reply != m_reply || !m_inFlight)
        return;
    m_watchdog.stop();
    m_reply.clear();
    QueuedRequest item = *std::exchange(m_inFlight, std::nullopt);
    const Request &req = item.request;
    const qint64 elapsed = m_sentAt.elapsed();

    const auto intermediate = reply->intermediateErrors();
    for (QModbusDevice::IntermediateError e : intermediate) {
        if (e == QModbusDevice::ResponseCrcError)
            ++m_stats.crcErrors;
        else if (e == QModbusDevice::ResponseRequestMismatch)
            ++m_stats.mismatches;
    }

    Result r;
    r.attempts = item.attempts;
    r.error = reply->error();
    bool retry = false;
    if (r.error == QModbusDevice::NoError) {
        const QModbusDataUnit unit = reply->result();
        if (req.type == Request::Type::ReadHolding &&
            (unit.valueCount() != req.count || unit.startAddress() != req.address)) {
            // Qt matches answers by id and function only: a stray answer to an older request
            // shows up here with the wrong size.
            ++m_stats.mismatches;
            r.error = QModbusDevice::UnknownError;
            r.errorText = tr("%1: answer carried %2 registers, %3 were asked for")
                              .arg(describe(req))
                              .arg(unit.valueCount())
                              .arg(req.count);
            retry = true;
        } else {
            ++m_stats.answers;
            m_stats.addRoundTrip(elapsed);
            r.ok = true;
            r.roundTripMs = elapsed;
            if (req.type == Request::Type::ReadHolding)
                r.values = unit.values();
        }
    } else if (r.error == QModbusDevice::ProtocolError && reply->rawResult().data().size() == 1) {
        // An exception answer carries just its code. (QModbusPdu::isException() trips UBSan on
        // Qt 6.4: the function code is stored sign-extended.)
        ++m_stats.answers;
        ++m_stats.exceptions;
        r.exceptionCode = quint8(reply->rawResult().data().at(0));
        ++m_stats.exceptionsByCode[r.exceptionCode];
        r.errorText =
            tr("%1: the controller refused: %2").arg(describe(req), exceptionText(r.exceptionCode));
    } else if (r.error == QModbusDevice::TimeoutError) {
        ++m_stats.timeouts;
        const bool crc = intermediate.contains(QModbusDevice::ResponseCrcError);
        r.errorText =
            crc ? tr("%1: answers had a bad checksum (CRC)").arg(describe(req))
                : tr("%1: no answer within %2 ms").arg(describe(req)).arg(m_settings.timeoutMs);
        retry = true;
    } else {
        r.errorText = tr("%1: %2").arg(describe(req), reply->errorString());
    }

    if (!r.ok && retry) {
        // Let a late answer drain before anything else goes out.
        m_sinceQuiet.start();
        m_quietRemainingMs = m_quietMs;
        m_traffic->addEvent(r.errorText, TrafficEntry::Kind::Error);
        if (req.retryable && item.attempts <= m_settings.retries) {
            m_queue.pushFront(std::move(item));
            Q_EMIT statsChanged();
            schedulePump(m_quietMs);
            return;
        }
        r.mayHaveActed = req.type == Request::Type::WriteCoil;
        if (r.mayHaveActed)
            r.errorText += tr(" -- the controller may have acted on it");
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

void ModbusLink::onWireFrame(WireTap::Frame frame, const QByteArray &raw)
{
    if (!m_client || !m_inFlight)
        return;
    const bool tcpLink = m_settings.transport == LinkSettings::Transport::Tcp;
    const bool tcpFrame = frame == WireTap::Frame::TcpSent || frame == WireTap::Frame::TcpReceived;
    if (tcpLink != tcpFrame)
        return;
    const bool sent = frame == WireTap::Frame::RtuSent || frame == WireTap::Frame::TcpSent;
    if (sent)
        m_stats.bytesSent += quint64(raw.size());
    else
        m_stats.bytesReceived += quint64(raw.size());
    m_traffic->addFrame(sent ? TrafficEntry::Direction::Sent : TrafficEntry::Direction::Received,
                        raw, tcpFrame ? 7 : 1, tcpFrame ? 0 : 2, &m_inFlight->request);
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
