#include "sim/host/simworker.h"

#include "bus/rtuframe.h"
#include "sim/model/simdevice.h"
#include "sim/serve/ptybridge.h"
#include "sim/serve/simresponder.h"
#include "sim/serve/simrtuserver.h"
#include "sim/serve/simrtutcpserver.h"
#include "sim/serve/simtcpserver.h"

#include <QModbusDevice>
#include <QSerialPort>
#include <QTimer>

namespace stepcom {

SimWorker::SimWorker(QList<SimDevice *> devices, const SimOptions &options)
    : m_devices(std::move(devices))
    , m_device(m_devices.first())
    , m_options(options)
{
    const int delay =
        options.answerDelayMs >= 0 ? options.answerDelayMs : options.map.answerDelayMs();
    m_responder =
        std::make_unique<SimResponder>(m_devices, delay, options.wireBaud, options.faults);
    m_responder->setSlowCoils(options.slowCoils);
}

SimWorker::~SimWorker()
{
    close();
}

bool SimWorker::open(QString *error)
{
    // Queued: an answer to the write that changed the id still leaves under the old one.
    for (SimDevice *other : std::as_const(m_devices))
        if (other != m_device)
            other->setLinkObserver({}); // the bridge points the server at each frame's id
    m_device->setLinkObserver([this] {
        QMetaObject::invokeMethod(
            this,
            [this] {
                if (!m_rtu)
                    return;
                if (m_devices.size() == 1)
                    m_rtu->setServerAddress(m_device->deviceId());
                // The controller moves to a new baud at once; the port follows once the
                // answer to the write has left (the answer delay plus its bytes' time).
                if (serialMode() &&
                    m_rtu->connectionParameter(QModbusDevice::SerialBaudRateParameter).toInt() !=
                        m_device->baud()) {
                    QTimer::singleShot(300, this, [this] {
                        if (!m_rtu || m_rtu->state() != QModbusDevice::ConnectedState)
                            return; // hung up or closed: it reopens at the new baud anyway
                        m_rtu->disconnectDevice();
                        QString why;
                        if (!openSerial(&why))
                            Q_EMIT message(why);
                    });
                }
            },
            Qt::QueuedConnection);
    });
    m_reopen = new QTimer(this);
    m_reopen->setSingleShot(true);
    connect(m_reopen, &QTimer::timeout, this, &SimWorker::reopenRtu);
    if (!m_options.manualClock) {
        // The model catches up lazily on every access; this keeps each catch-up short.
        m_sync = new QTimer(this);
        connect(m_sync, &QTimer::timeout, this, [this] { m_device->now(); });
        m_sync->start(50);
    }
    if (m_options.rtu && !openRtu(error))
        return false;
    if (serialMode() && !openSerial(error))
        return false;
    if (m_options.tcp) {
        m_tcp = new SimTcpServer(m_responder.get(), this);
        if (!m_tcp->listen(m_options.tcpAddress, m_options.tcpPort, error))
            return false;
        m_tcpPort = m_tcp->port();
        connect(m_tcp, &SimTcpServer::hangUpRequested, this, &SimWorker::scheduleHangUp);
    }
    if (m_options.rtuTcp) {
        m_rtuTcp = new SimRtuTcpServer(m_responder.get(), m_options.echo, this);
        if (!m_rtuTcp->listen(m_options.tcpAddress, m_options.rtuTcpPort, error))
            return false;
        m_rtuTcpPort = m_rtuTcp->port();
        connect(m_rtuTcp, &SimRtuTcpServer::hangUpRequested, this, &SimWorker::scheduleHangUp);
    }
    return true;
}

bool SimWorker::openRtu(QString *error)
{
#ifdef Q_OS_UNIX
    if (!m_bridge) {
        m_bridge = new PtyBridge(this);
        // Side A is the controller, side B the client's end.
        m_bridge->setTap([this](PtyBridge::Side from, const QByteArray &bytes) {
            // An echoing adapter: the client hears its own bytes at once.
            if (from == PtyBridge::Side::B && m_options.echo && !bytes.isEmpty())
                m_bridge->inject(PtyBridge::Side::B, bytes);
            // A request's first byte is its address: Qt's server answers one address, so it
            // is pointed at the controller the frame is for before it reads the frame.
            if (from == PtyBridge::Side::B && m_rtu && !bytes.isEmpty() && m_devices.size() > 1) {
                const int unit = quint8(bytes.at(0));
                if (m_responder->hasDevice(unit))
                    m_rtu->setRequestUnit(unit);
            }
            if (from != PtyBridge::Side::A || !m_rtu || bytes.isEmpty() || !m_rtu->takeCorruptCrc())
                return bytes;
            QByteArray bad = bytes;
            bad[bad.size() - 1] = char(bad.at(bad.size() - 1) ^ 0x5A);
            return bad;
        });
    }
    // The controller hears the silence between requests: Qt's server reads a burst as one
    // frame, so requests that came while it was busy are handed to it one by one.
    m_bridge->setFramer(PtyBridge::Side::B, &RtuFrame::requestLength);
    if (!m_bridge->open(error))
        return false;
    if (!m_options.linkPath.isEmpty() &&
        !m_bridge->createLink(PtyBridge::Side::B, m_options.linkPath, error)) {
        m_bridge->close();
        return false;
    }
    if (!m_rtu) {
        std::function<int()> clientBaud;
        if (m_options.checkBaud)
            clientBaud = [this] { return m_bridge->clientBaud(PtyBridge::Side::B); };
        m_rtu = new SimRtuServer(m_responder.get(), clientBaud, this);
        connect(m_rtu, &SimRtuServer::hangUpRequested, this, &SimWorker::scheduleHangUp);
        // Qt's server reads (and answers) in its port's readyRead, connected before this:
        // once it returns, the next request may go to it.
        if (auto *port = m_rtu->findChild<QSerialPort *>())
            connect(port, &QSerialPort::readyRead, m_bridge,
                    [this] { m_bridge->frameRead(PtyBridge::Side::A); });
        connect(m_rtu, &QModbusDevice::errorOccurred, this, [this](QModbusDevice::Error e) {
            if (e != QModbusDevice::NoError)
                Q_EMIT message(tr("RTU server: %1").arg(m_rtu->errorString()));
        });
    }
    m_rtu->setConnectionParameter(QModbusDevice::SerialPortNameParameter,
                                  m_bridge->path(PtyBridge::Side::A));
    m_rtu->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, QSerialPort::Baud9600);
    m_rtu->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
    m_rtu->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    m_rtu->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
    m_rtu->setServerAddress(m_device->deviceId());
    if (!m_rtu->connectDevice() || m_rtu->state() != QModbusDevice::ConnectedState) {
        if (error)
            *error = tr("cannot open the pseudo-terminal: %1").arg(m_rtu->errorString());
        m_bridge->close();
        return false;
    }
    m_ptyPath = m_bridge->path(PtyBridge::Side::B);
    if (onPtyPath)
        onPtyPath(m_ptyPath);
    return true;
#else
    if (error)
        *error = tr("Modbus RTU on a pseudo-terminal (--pty, --link) is not available on this "
                    "system (pseudo-terminals are Unix only). Use Modbus TCP instead: "
                    "stepcom-sim --tcp 5020, then connect StepCom or stepcomctl with --tcp "
                    "127.0.0.1:5020; or serve a serial port with --serial, e.g. one end of a "
                    "com0com virtual port pair (--serial COM10, StepCom on COM11).");
    return false;
#endif
}

bool SimWorker::openSerial(QString *error)
{
    if (!m_rtu) {
        // No client end to look at: the line itself enforces the baud rate.
        m_rtu = new SimRtuServer(m_responder.get(), {}, this);
        connect(m_rtu, &SimRtuServer::hangUpRequested, this, &SimWorker::scheduleHangUp);
        connect(m_rtu, &QModbusDevice::errorOccurred, this, [this](QModbusDevice::Error e) {
            if (e != QModbusDevice::NoError)
                Q_EMIT message(tr("RTU server: %1").arg(m_rtu->errorString()));
        });
    }
    m_rtu->setConnectionParameter(QModbusDevice::SerialPortNameParameter, m_options.serialPort);
    m_rtu->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, m_device->baud());
    m_rtu->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
    m_rtu->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
    m_rtu->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
    m_rtu->setServerAddress(m_device->deviceId());
    if (!m_rtu->connectDevice() || m_rtu->state() != QModbusDevice::ConnectedState) {
        if (error)
            *error = tr("cannot open the serial port %1: %2")
                         .arg(m_options.serialPort, m_rtu->errorString());
        return false;
    }
    return true;
}

void SimWorker::reopenRtu()
{
    QString error;
    if (serialMode()) {
        if (openSerial(&error))
            Q_EMIT reopened(m_options.serialPort);
        else
            Q_EMIT message(tr("cannot re-create the port: %1").arg(error));
        return;
    }
    if (openRtu(&error))
        Q_EMIT reopened(m_ptyPath);
    else
        Q_EMIT message(tr("cannot re-create the port: %1").arg(error));
}

void SimWorker::scheduleHangUp()
{
    // A moment for the last answer to leave before the line goes dead.
    QTimer::singleShot(50, this, [this] { hangUp(-1); });
}

void SimWorker::hangUp(int pauseMs)
{
    const int pause = pauseMs >= 0 ? pauseMs : m_options.faults.hangupPauseMs;
    if (serialMode() && m_rtu && m_rtu->state() == QModbusDevice::ConnectedState) {
        m_rtu->disconnectDevice();
        m_reopen->start(pause);
    }
#ifdef Q_OS_UNIX
    if (m_bridge && m_bridge->isOpen()) {
        m_rtu->disconnectDevice();
        m_bridge->close();
        m_ptyPath.clear();
        if (onPtyPath)
            onPtyPath(m_ptyPath);
        m_reopen->start(pause);
    }
#endif
    if (m_tcp)
        m_tcp->hangUp(pause);
    if (m_rtuTcp)
        m_rtuTcp->hangUp(pause);
    Q_EMIT hungUp();
}

void SimWorker::close()
{
    m_device->setLinkObserver({});
    if (m_reopen)
        m_reopen->stop();
    if (m_sync)
        m_sync->stop();
    if (m_rtu)
        m_rtu->disconnectDevice();
#ifdef Q_OS_UNIX
    if (m_bridge)
        m_bridge->close();
#endif
    if (m_tcp)
        m_tcp->close();
    if (m_rtuTcp)
        m_rtuTcp->close();
    delete m_rtuTcp;
    m_rtuTcp = nullptr;
    delete m_rtu;
    m_rtu = nullptr;
    delete m_bridge;
    m_bridge = nullptr;
    delete m_tcp;
    m_tcp = nullptr;
}

} // namespace stepcom
