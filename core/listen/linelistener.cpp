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
    m_outgoing.clear();
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
    if (!m_outgoing.isEmpty() && !m_decoder.waiting() && m_finder.held() == 0 &&
        (m_sentAtMs < 0 || ms - m_sentAtMs >= kAnswerWaitMs))
        sendNow();
}

void LineListener::idle(qint64 ms)
{
    emitAll(m_finder.idle(ms));
    for (const HeardEvent &e : m_decoder.idle(ms))
        Q_EMIT heard(e);
    // Or the line has been quiet for a silence (nobody is answering anything now).
    if (!m_outgoing.isEmpty() && ms - m_lastByteMs >= m_finder.silenceMs() &&
        (m_sentAtMs < 0 || ms - m_sentAtMs >= kAnswerWaitMs))
        sendNow();
}

QByteArray LineListener::emergencyStopFrame(const RegisterMap &map, int unit)
{
    for (const Parameter *c : map.coils()) {
        if (c->command != CommandClass::Emergency)
            continue;
        QByteArray pdu;
        pdu.append(char(c->address >> 8));
        pdu.append(char(c->address & 0xFF));
        pdu.append(char(0xFF));
        pdu.append(char(0x00));
        return RtuFrame::adu(unit, QModbusRequest(QModbusPdu::WriteSingleCoil, pdu));
    }
    return {};
}

bool LineListener::sendInSilence(const QByteArray &frame)
{
    if (!m_port || !m_mayTransmit || !m_port->isOpen())
        return false;
    m_outgoing = frame;
    m_tries = 0;
    m_sentAtMs = -1;
    if (now() - m_lastByteMs >= m_finder.silenceMs() && !m_decoder.waiting())
        sendNow();
    return true;
}

void LineListener::sendNow()
{
    if (m_tries >= kSendTries) {
        Q_EMIT sendFailed(std::exchange(m_outgoing, {}));
        return;
    }
    ++m_tries;
    const int fd = int(m_port->handle());
    const bool rts = m_settings.rs485 == LinkSettings::Rs485::Rts;
    if (rts)
        PortSetup::setRts(fd, true);
    m_port->write(m_outgoing);
    m_port->flush();
    if (rts)
        PortSetup::endOfSend(fd);
    m_sentAtMs = now();
    Q_EMIT frameSent(m_outgoing, m_tries);
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
        // The controller's answer to what StepCom sent (a copy of it) ends the sending.
        if (!m_outgoing.isEmpty() && m_sentAtMs >= 0 && f.bytes == m_outgoing) {
            Q_EMIT frameAnswered(std::exchange(m_outgoing, {}));
            continue;
        }
        Q_EMIT frameHeard(f);
        for (const HeardEvent &e : m_decoder.frame(f))
            Q_EMIT heard(e);
    }
}

} // namespace stepcom
