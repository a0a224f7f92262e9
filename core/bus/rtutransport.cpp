#include "bus/rtutransport.h"

#include "bus/answercheck.h"
#include "bus/portholders.h"
#include "bus/portsetup.h"
#include "bus/rtuframe.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSerialPort>
#include <QTcpSocket>

#include <algorithm>
#include <cmath>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <unistd.h>
#endif

namespace stepcom {

RtuTransport::RtuTransport(QObject *parent)
    : LinkBackend(parent)
{
    m_clock.start();
    m_writeTimer.setSingleShot(true);
    m_writeTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_writeTimer, &QTimer::timeout, this, &RtuTransport::scheduleWrite);
    m_timeoutTimer.setSingleShot(true);
    m_timeoutTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_timeoutTimer, &QTimer::timeout, this, &RtuTransport::onTimeout);
}

RtuTransport::~RtuTransport()
{
    close();
}

QString RtuTransport::notASerialPort(const QString &path)
{
#ifdef Q_OS_UNIX
    const QFileInfo info(path);
    if (!path.startsWith(QLatin1Char('/')) || !info.exists())
        return {};
    const QString why =
        QCoreApplication::translate("stepcom::RtuTransport",
                                    "%1 is not a serial port (give the adapter's device, e.g. "
                                    "/dev/ttyUSB0 or a /dev/serial/by-id/ link)")
            .arg(path);
    if (info.isFile() || info.isDir())
        return why;
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0)
        return {}; // permission and the like: the caller and the port say it better
    const bool tty = ::isatty(fd) == 1;
    ::close(fd);
    return tty ? QString() : why;
#else
    Q_UNUSED(path);
    return {};
#endif
}

void RtuTransport::open(const LinkSettings &settings)
{
    close();
    m_settings = settings;
    m_opening = true;
    m_failing = false;
    m_lastRxMs = -1;
    m_needQuiet = false;
    m_echoSeen = Echo::Unknown;
    m_copyAnswered.clear();
    if (settings.transport == LinkSettings::Transport::RtuTcp) {
        // The converter's line has its own baud, unknown here: count no wire time.
        m_byteMs = 0;
        m_gapMs = 0;
        auto *socket = new QTcpSocket(this);
        m_device = socket;
        connect(socket, &QTcpSocket::connected, this, [this, socket] {
            socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            if (m_opening) {
                m_opening = false;
                Q_EMIT opened(true, QString());
            }
        });
        connect(socket, &QTcpSocket::errorOccurred, this,
                [this, socket](QAbstractSocket::SocketError) { fail(socket->errorString()); });
        connect(socket, &QTcpSocket::disconnected, this, [this] {
            fail(QCoreApplication::translate("stepcom::RtuTransport",
                                             "the converter closed the connection"));
        });
        connect(socket, &QTcpSocket::readyRead, this, &RtuTransport::onReadyRead);
        socket->connectToHost(settings.host, quint16(settings.tcpPort));
        return;
    }
    auto *port = new QSerialPort(this);
    m_device = port;
    port->setPortName(settings.portName);
    port->setBaudRate(settings.baud);
    port->setParity(settings.parity);
    port->setDataBits(QSerialPort::Data8);
    port->setStopBits(settings.stopBits);
    port->setFlowControl(QSerialPort::NoFlowControl);
    // A pseudo-terminal moves bytes without a wire: no frame time, no silences to keep (the
    // simulator's wire model counts them itself).
    const bool pty =
        QFileInfo(settings.portName).canonicalFilePath().startsWith(QLatin1String("/dev/pts/"));
    const int bits = 1 + 8 + (settings.parity == QSerialPort::NoParity ? 0 : 1) +
                     (settings.stopBits == QSerialPort::TwoStop ? 2 : 1);
    m_byteMs = pty ? 0.0 : RtuFrame::charsMs(1, settings.baud, bits);
    m_gapMs = 3.5 * m_byteMs;
    if (!port->open(QIODevice::ReadWrite)) {
        // Another program on the port is named, not taken for a permission problem.
        const QString why =
            PortHolders::openFailure(settings.portName, port->error(), port->errorString());
        delete port;
        m_opening = false;
        Q_EMIT opened(false,
                      QCoreApplication::translate("stepcom::RtuTransport", "cannot open %1: %2")
                          .arg(settings.portName, why));
        return;
    }
    m_adapter = SerialAdapter::identify(settings.portName);
    // An FTDI chip holds answers up to its latency timer (16 ms): ask for 1 ms, no root needed.
    if (m_adapter.family == SerialAdapter::Family::Ftdi &&
        PortSetup::requestLowLatency(int(port->handle())).isEmpty())
        m_adapter.refreshLatency();
    // The RS-485 direction is set before anything is sent, or nothing is sent at all.
    if (const QString refused = PortSetup::applyRs485(int(port->handle()), settings, m_adapter);
        !refused.isEmpty()) {
        port->close();
        delete port;
        m_opening = false;
        Q_EMIT opened(false, refused);
        return;
    }
    connect(port, &QSerialPort::errorOccurred, this, [this, port](QSerialPort::SerialPortError e) {
        if (e != QSerialPort::NoError && e != QSerialPort::TimeoutError)
            fail(port->errorString());
    });
    connect(port, &QSerialPort::readyRead, this, &RtuTransport::onReadyRead);
    port->clear(); // whatever waited in the driver belongs to no request of ours
    // An answer to a program that used the line before may still be on its way: the link is
    // open once the line has been quiet for a moment (bytes meanwhile are discarded).
    requireQuiet();
    QTimer::singleShot(m_quietMs, this, [this, device = QPointer<QIODevice>(port)] {
        if (!m_opening || m_device != device)
            return;
        m_opening = false;
        Q_EMIT opened(true, QString());
    });
}

void RtuTransport::close()
{
    m_writeTimer.stop();
    m_timeoutTimer.stop();
    m_pending.reset();
    m_waiting = false;
    m_rx.clear();
    m_stray.clear();
    m_strayParsed = 0;
    m_owed.clear();
    m_lateMs = 0;
    m_discarded.clear();
    m_crcErrors = 0;
    if (QIODevice *device = m_device.data()) {
        m_device.clear();
        device->disconnect(this);
        device->close();
        device->deleteLater();
    }
    m_opening = false;
}

void RtuTransport::fail(const QString &reason)
{
    // Qt 6.4 repeats the errors of a vanished port in a tight loop: act once.
    if (m_failing)
        return;
    m_failing = true;
    const bool opening = m_opening;
    close();
    if (opening)
        Q_EMIT opened(false, reason);
    else
        Q_EMIT failed(reason);
}

void RtuTransport::requireQuiet()
{
    m_needQuiet = true;
    m_quietFromMs = nowMs();
}

void RtuTransport::send(int unit, const QModbusRequest &request, int timeoutMs)
{
    Pending p;
    p.unit = unit;
    m_unit = unit;
    p.request = request;
    p.adu = RtuFrame::adu(unit, request);
    p.timeoutMs = timeoutMs;
    m_pending = p;
    m_waiting = false;
    scheduleWrite();
}

void RtuTransport::scheduleWrite()
{
    if (!m_pending || m_waiting || !m_device)
        return;
    const double now = nowMs();
    double at = now;
    if (m_lastRxMs >= 0)
        at = std::max(at, m_lastRxMs + std::max(m_gapMs, double(m_settings.turnaroundMs)));
    if (m_needQuiet) // drain: the line has to be silent for the quiet time first
        at = std::max(at, std::max(m_quietFromMs, m_lastRxMs) + m_quietMs);
    // An answer still owed to another request could be taken for this one's: wait for it. One
    // of another shape (a read's answer, owed, and an E-STOP's) is told apart by what it says.
    pruneOwed();
    for (const Owed &o : std::as_const(m_owed)) {
        if (o.adu != m_pending->adu && couldPassForPending(o.adu))
            at = std::max(at, o.untilMs);
    }
    if (at > now + 0.05) {
        m_writeTimer.start(int(std::ceil(at - now)));
        Q_EMIT writeDeferred(m_writeTimer.interval());
        return;
    }
    writeNow();
}

void RtuTransport::writeNow()
{
    m_needQuiet = false;
    m_strayParsed = 0;
    if (!m_stray.isEmpty())
        discard(std::exchange(m_stray, {}),
                QCoreApplication::translate("stepcom::RtuTransport",
                                            "bytes that arrived between two requests"));
    m_rx.clear();
    m_echoStripped = false;
    m_copyAnswered.clear();
    const QByteArray &adu = m_pending->adu;
    auto *port = qobject_cast<QSerialPort *>(m_device.data());
    const bool rts = port && m_settings.rs485 == LinkSettings::Rs485::Rts;
    if (rts)
        PortSetup::setRts(int(port->handle()), true);
    const qint64 written = m_device->write(adu);
    if (rts) {
        // The request out of Qt's buffer and off the wire, then RTS falls for the answer.
        port->flush();
        PortSetup::endOfSend(int(port->handle()));
    }
    if (written != adu.size()) {
        LinkAnswer a;
        a.kind = LinkAnswer::Kind::Failed;
        a.errorText = m_device->errorString();
        finish(a);
        return;
    }
    m_sentAtMs = nowMs();
    m_waiting = true;
    const double frameMs = m_byteMs * double(adu.size());
    // The timeout counts from the end of the request on the line; a scan's probe timeout is
    // fitted with the request's frame in it already (BusScanner::fittedProbeTimeoutMs).
    m_timeoutTimer.start(m_pending->timeoutMs + (m_scan ? 0 : int(std::ceil(frameMs))));
    Q_EMIT frame(true, adu, 1, 2);
    Q_EMIT sent();
}

void RtuTransport::onReadyRead()
{
    if (!m_device)
        return;
    const QByteArray bytes = m_device->readAll();
    if (bytes.isEmpty())
        return;
    m_lastRxMs = nowMs();
    if (!m_waiting) {
        // Nobody asked: a late answer. The next request waits until the line is quiet.
        m_stray += bytes;
        m_needQuiet = true;
        m_quietFromMs = m_lastRxMs;
        takeStrayFrames();
        scheduleWrite(); // a request waiting for an owed answer may go sooner now
        return;
    }
    m_rx += bytes;
    processBuffer();
}

void RtuTransport::discard(const QByteArray &bytes, const QString &why)
{
    if (!bytes.isEmpty())
        Q_EMIT frame(false, bytes, 1, 2);
    m_discarded << why;
}

QByteArray RtuTransport::checkedAnswerAtStart() const
{
    const int length = RtuFrame::answerLength(m_rx);
    if (length <= 0 || m_rx.size() < length)
        return {};
    const QByteArray f = m_rx.left(length);
    if (!RtuFrame::crcOk(f) || quint8(f.at(0)) != m_pending->unit)
        return {};
    if (!AnswerCheck::mismatch(m_pending->request, quint8(f.at(1)), f.mid(2, f.size() - 4))
             .isEmpty())
        return {};
    return f;
}

void RtuTransport::learnEcho(bool echoes)
{
    const Echo seen = echoes ? Echo::Yes : Echo::No;
    if (m_echoSeen == seen)
        return;
    m_echoSeen = seen;
    Q_EMIT echoLearned(echoes);
}

void RtuTransport::processBuffer()
{
    const auto tr = [](const char *text) {
        return QCoreApplication::translate("stepcom::RtuTransport", text);
    };
    while (m_waiting && !m_rx.isEmpty()) {
        const QByteArray &adu = m_pending->adu;
        const double at = nowMs() - m_sentAtMs;
        const int fc = quint8(adu.at(1));
        // An FC05/06 answer is a byte-for-byte copy of the request: only these can be both.
        const bool copyCanAnswer = fc == 0x05 || fc == 0x06;
        if (!m_echoStripped && m_rx.size() < adu.size() && adu.startsWith(m_rx)) {
            // The start of the echo, or of the answer: an FC10 answer is the request's first
            // six bytes and its own CRC. A complete answer that checks out is taken.
            if (expectEcho() || checkedAnswerAtStart().isEmpty())
                return;
        } else if (!m_echoStripped && m_rx.startsWith(adu) && (expectEcho() || !copyCanAnswer)) {
            // The request's own bytes: an FC03/FC10 request is never its own answer.
            if (!copyCanAnswer)
                learnEcho(true);
            m_echoStripped = true;
            Q_EMIT frame(false, adu, 1, 2);
            m_rx.remove(0, int(adu.size()));
            continue;
        }
        const int length = RtuFrame::answerLength(m_rx);
        if (length == 0)
            return;
        if (length < 0 || length > 256) {
            discard(std::exchange(m_rx, {}), tr("bytes that are no answer frame"));
            return;
        }
        if (m_rx.size() < length)
            return;
        const QByteArray f = m_rx.left(length);
        m_rx.remove(0, length);
        if (!RtuFrame::crcOk(f)) {
            // The rest of the burst cannot be framed reliably either.
            ++m_crcErrors;
            discard(f + std::exchange(m_rx, {}), tr("an answer with a bad checksum (CRC)"));
            return;
        }
        if (quint8(f.at(0)) != m_pending->unit) {
            reportForeign(f);
            discard(
                f,
                tr("an answer from device %1, not %2").arg(quint8(f.at(0))).arg(m_pending->unit));
            continue;
        }
        pruneOwed();
        // A controller answers in order: a frame while it owes answers is the oldest's --
        // unless it is what this request asked for and no answer to that one: then the owed
        // answer never came (the controller did not hear that attempt).
        qsizetype owedAt = oldestOwed(quint8(f.at(0)));
        const QByteArray data = f.mid(2, f.size() - 4);
        if (owedAt >= 0 && m_owed.at(owedAt).adu != adu && answers(adu, quint8(f.at(1)), data) &&
            !answers(m_owed.at(owedAt).adu, quint8(f.at(1)), data)) {
            const char unit = f.at(0);
            m_owed.removeIf([unit](const Owed &o) { return o.adu.at(0) == unit; });
            owedAt = -1;
        }
        const bool owed = owedAt >= 0;
        if (owed && m_owed.at(owedAt).adu != adu) {
            owedAnswerCame(owedAt);
            discard(f, tr("a late answer to an earlier request"));
            continue;
        }
        if (const QString why = AnswerCheck::mismatch(m_pending->request, quint8(f.at(1)), data);
            !why.isEmpty()) {
            if (owed)
                owedAnswerCame(owedAt);
            discard(f, why);
            continue;
        }
        if (owed) {
            // An earlier attempt of this very request: its answer is this one's too, and this
            // attempt's own answer may still come.
            owedAnswerCame(owedAt);
            m_owed.append({adu, owedUntilMs(), m_sentAtMs});
        }
        // An answer with no copy before it: a read or block write shows the adapter is quiet.
        if (!copyCanAnswer && !m_echoStripped)
            learnEcho(false);
        if (copyCanAnswer && !m_echoStripped && m_owed.isEmpty())
            m_copyAnswered = adu;
        Q_EMIT frame(false, f, 1, 2);
        LinkAnswer a;
        a.kind = LinkAnswer::Kind::Answer;
        a.response = RtuFrame::response(f);
        a.exceptionCode = AnswerCheck::exceptionCode(quint8(f.at(1)), data);
        a.roundTripMs = qint64(std::llround(at));
        finish(a);
        return;
    }
}

void RtuTransport::onTimeout()
{
    if (!m_waiting)
        return;
    // A scan owes no answer: a late one names its unit and is counted for it.
    if (!m_scan)
        m_owed.append({m_pending->adu, owedUntilMs(), m_sentAtMs});
    LinkAnswer a;
    a.kind = LinkAnswer::Kind::Timeout;
    a.onlyEcho = m_echoStripped && m_rx.isEmpty();
    if (!m_rx.isEmpty())
        discard(std::exchange(m_rx, {}),
                QCoreApplication::translate("stepcom::RtuTransport", "an incomplete answer"));
    finish(a);
}

double RtuTransport::owedUntilMs() const
{
    // A timeout fitted to the answers seen so far may be far shorter than the one set: an
    // answer is owed for as long as the set one says an answer may take -- or, once the
    // controller answered later than that, as long as it showed it may take.
    return m_sentAtMs + kOwedTimeouts * std::max({double(m_pending->timeoutMs),
                                                  double(m_settings.timeoutMs), m_lateMs});
}

qsizetype RtuTransport::oldestOwed(quint8 unit) const
{
    for (qsizetype i = 0; i < m_owed.size(); ++i) {
        if (quint8(m_owed.at(i).adu.at(0)) == unit)
            return i;
    }
    return -1;
}

void RtuTransport::owedAnswerCame(qsizetype index)
{
    m_lateMs = std::min(kMaxLateMs, std::max(m_lateMs, nowMs() - m_owed.at(index).sentAtMs));
    m_owed.removeAt(index);
}

bool RtuTransport::answers(const QByteArray &adu, int functionCode, const QByteArray &data)
{
    const QModbusRequest request(QModbusPdu::FunctionCode(quint8(adu.at(1))),
                                 adu.mid(2, adu.size() - 4));
    return AnswerCheck::mismatch(request, functionCode, data).isEmpty();
}

bool RtuTransport::couldPassForPending(const QByteArray &owedAdu) const
{
    const QByteArray &adu = m_pending->adu;
    if (owedAdu.size() < 6 || adu.size() < 6 || owedAdu.at(0) != adu.at(0) ||
        owedAdu.at(1) != adu.at(1))
        return false;
    switch (quint8(adu.at(1))) {
    case 0x03: // the answer carries the count of registers asked for
        return owedAdu.mid(4, 2) == adu.mid(4, 2);
    case 0x05:
    case 0x06:
    case 0x10: // the answer repeats the address and the value (or count)
        return owedAdu.mid(2, 4) == adu.mid(2, 4);
    default:
        return true;
    }
}

void RtuTransport::pruneOwed()
{
    const double now = nowMs();
    m_owed.removeIf([now](const Owed &o) { return o.untilMs <= now; });
}

void RtuTransport::takeStrayFrames()
{
    // Each complete frame of our unit between requests is the oldest owed answer.
    while (true) {
        const QByteArray rest = m_stray.mid(m_strayParsed);
        const int length = RtuFrame::answerLength(rest);
        if (length <= 0 || rest.size() < length)
            return;
        const QByteArray f = rest.left(length);
        if (!RtuFrame::crcOk(f))
            return; // noise: the rest cannot be framed; it is discarded with the next request
        m_strayParsed += length;
        reportForeign(f);
        pruneOwed();
        if (const qsizetype owedAt = oldestOwed(quint8(f.at(0))); owedAt >= 0) {
            owedAnswerCame(owedAt);
        } else if (!m_copyAnswered.isEmpty() && f == m_copyAnswered) {
            // A second copy of a command nothing else owes: the first was the adapter's echo,
            // this the controller's answer (which confirms the command all the same).
            m_copyAnswered.clear();
            learnEcho(true);
        }
    }
}

void RtuTransport::reportForeign(const QByteArray &frame)
{
    if (m_scan && frame.size() >= 4)
        Q_EMIT unitAnswered(quint8(frame.at(0)), quint8(frame.at(1)),
                            frame.mid(2, frame.size() - 4));
}

void RtuTransport::finish(LinkAnswer answer)
{
    m_timeoutTimer.stop();
    m_waiting = false;
    m_pending.reset();
    answer.discarded = std::exchange(m_discarded, {});
    answer.crcErrors = std::exchange(m_crcErrors, 0);
    // A scan's probe that heard nothing at all leaves nothing to wait for.
    const bool silent = m_scan && answer.kind == LinkAnswer::Kind::Timeout &&
                        answer.discarded.isEmpty() && m_rx.isEmpty();
    if (!silent && (answer.kind != LinkAnswer::Kind::Answer || !answer.discarded.isEmpty() ||
                    !m_rx.isEmpty())) {
        // Something else is talking on the line: let it finish before the next request.
        m_stray += std::exchange(m_rx, {});
        takeStrayFrames();
        requireQuiet();
    }
    Q_EMIT answered(answer);
}

} // namespace stepcom
