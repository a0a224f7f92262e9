#include "listen/linelistener.h"

#include "bus/portholders.h"
#include "bus/portsetup.h"

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
    if (!m_port->open(QIODevice::ReadOnly)) {
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
    emitAll(m_finder.feed(bytes, ms));
}

void LineListener::idle(qint64 ms)
{
    emitAll(m_finder.idle(ms));
    for (const HeardEvent &e : m_decoder.idle(ms))
        Q_EMIT heard(e);
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
        Q_EMIT frameHeard(f);
        for (const HeardEvent &e : m_decoder.frame(f))
            Q_EMIT heard(e);
    }
}

} // namespace stepcom
