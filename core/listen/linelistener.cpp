#include "listen/linelistener.h"

#include "bus/portholders.h"
#include "bus/portsetup.h"
#include "bus/rtuframe.h"
#include "map/registermap.h"

#include <QSerialPort>
#include <QTimer>

namespace stepcom {

LineListener::LineListener(const RegisterMap *map, QObject *parent)
    : QObject(parent)
    , m_map(map)
    , m_decoder(map)
{}

LineListener::~LineListener()
{
    close();
}

bool LineListener::open(const LinkSettings &settings, QString *error)
{
    close();
    m_settings = settings;
    m_finder = FrameFinder(settings.baud);
    m_decoder = ListenDecoder(m_map, settings.baud);
    m_port = new QSerialPort(this);
    m_port->setPortName(settings.portName);
    // Read-only: whatever happens, a listener cannot put a byte on the line.
    m_estop.cancel();
    m_verdictOwed = false;
    if (!m_port->open(m_mayTransmit ? QIODevice::ReadWrite : QIODevice::ReadOnly)) {
        *error =
            PortHolders::openFailure(settings.portName, m_port->error(), m_port->errorString());
        delete std::exchange(m_port, nullptr);
        return false;
    }
    const bool set = m_port->setBaudRate(settings.baud) &&
                     m_port->setDataBits(QSerialPort::Data8) &&
                     m_port->setParity(settings.parity) && m_port->setStopBits(settings.stopBits) &&
                     m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!set) {
        *error = m_port->errorString();
        close();
        return false;
    }
    m_adapter = SerialAdapter::identify(settings.portName);
    // Frames are said as soon as their bytes are in: an FTDI chip should not hold them 16 ms.
    if (m_adapter.family == SerialAdapter::Family::Ftdi &&
        PortSetup::requestLowLatency(int(m_port->handle())).isEmpty())
        m_adapter.refreshLatency();
    // RTS-switched RS-485 direction: RTS low keeps the adapter receiving, never driving.
    if (const QString refused = PortSetup::applyRs485(int(m_port->handle()), settings, m_adapter);
        !refused.isEmpty()) {
        *error = refused;
        close();
        return false;
    }
    m_port->clear(QSerialPort::Input); // what waited from before is not this line's now
    m_clock.start();
    connect(m_port, &QSerialPort::readyRead, this, &LineListener::readPort);
    connect(m_port, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
        if (e == QSerialPort::NoError || e == QSerialPort::TimeoutError)
            return;
        const QString reason = m_port->errorString();
        close();
        Q_EMIT lost(reason);
    });
    m_tick = new QTimer(this);
    m_tick->setInterval(kTickMs);
    connect(m_tick, &QTimer::timeout, this, [this] { idle(now()); });
    m_tick->start();
    return true;
}

void LineListener::close()
{
    delete std::exchange(m_tick, nullptr);
    if (m_port) {
        m_port->disconnect(this);
        m_port->close();
        m_port->deleteLater();
        m_port = nullptr;
    }
}

bool LineListener::isOpen() const
{
    return m_port && m_port->isOpen();
}

void LineListener::readPort()
{
    if (m_port)
        feed(m_port->readAll(), now());
}

void LineListener::feed(const QByteArray &bytes, qint64 ms)
{
    m_lastByteMs = ms;
    emitAll(m_finder.feed(bytes, ms));
    // The first silence after the other master's frame: an answer just ended a pair.
    if (m_estop.isActive() && !m_decoder.waiting() && m_finder.held() == 0)
        sendDue(ms);
}

void LineListener::idle(qint64 ms)
{
    emitAll(m_finder.idle(ms));
    for (const HeardEvent &e : m_decoder.idle(ms))
        Q_EMIT heard(e);
    // Or the line has been quiet for a silence (nobody is answering anything now).
    if (m_estop.isActive() && ms - m_lastByteMs >= m_finder.silenceMs())
        sendDue(ms);
}

QByteArray LineListener::emergencyStopFrame(const RegisterMap &map, int unit)
{
    return EstopConfirmation::stopFrameFor(map, unit);
}

bool LineListener::sendEmergencyStop(int unit)
{
    if (!m_port || !m_mayTransmit || !m_port->isOpen())
        return false;
    m_estop = EstopConfirmation(*m_map, unit, m_settings.echo || m_echoLearned);
    if (!m_estop.isValid())
        return false;
    m_estop.start();
    m_verdictOwed = true;
    if (now() - m_lastByteMs >= m_finder.silenceMs() && !m_decoder.waiting())
        sendDue(now());
    return true;
}

void LineListener::sendDue(qint64 ms)
{
    const QByteArray frame = m_estop.due(ms);
    if (frame.isEmpty()) {
        sayVerdict();
        return;
    }
    sendNow(frame);
    m_estop.sent(now());
    const bool estop = frame == m_estop.stopFrame();
    Q_EMIT frameSent(frame, estop, estop ? m_estop.stopTries() : m_estop.readTries());
}

void LineListener::sendNow(const QByteArray &frame)
{
    const int fd = int(m_port->handle());
    const bool rts = m_settings.rs485 == LinkSettings::Rs485::Rts;
    if (rts)
        PortSetup::setRts(fd, true);
    m_port->write(frame);
    m_port->flush();
    if (rts)
        PortSetup::endOfSend(fd);
}

void LineListener::sayVerdict()
{
    if (!m_verdictOwed || m_estop.verdict() == EstopConfirmation::Verdict::Pending)
        return;
    m_verdictOwed = false;
    Q_EMIT emergencyStopSettled(m_estop.verdict() == EstopConfirmation::Verdict::Acknowledged,
                                m_estop.text());
}

void LineListener::finish()
{
    m_finder.finish();
    for (const HeardEvent &e : m_decoder.finish())
        Q_EMIT heard(e);
}

void LineListener::emitAll(const QList<HeardFrame> &frames)
{
    for (const HeardFrame &f : frames) {
        // StepCom's own frames (their echo, the controller's copy, the read's answer) are not
        // the other master's traffic.
        if (m_estop.isActive() && m_estop.heard(f, m_decoder.waitingRequest())) {
            if (m_estop.takeEchoLearned() && !std::exchange(m_echoLearned, true))
                Q_EMIT echoSuspected();
            sayVerdict();
            continue;
        }
        Q_EMIT frameHeard(f);
        for (const HeardEvent &e : m_decoder.frame(f))
            Q_EMIT heard(e);
    }
}

} // namespace stepcom
