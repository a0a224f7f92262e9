#pragma once

#include "sim/host/simoptions.h"

#include <QList>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>

QT_BEGIN_NAMESPACE
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

class PtyBridge;
class SimDevice;
class SimResponder;
class SimRtuServer;
class SimTcpServer;
class SimRtuTcpServer;

// The transports of a SimHost, living in the simulator's own thread: the pty bridge with the
// RTU server on its device side (or the RTU server on a serial port), the TCP server, hang-ups
// and their recovery.
class SimWorker : public QObject
{
    Q_OBJECT
public:
    // `devices`: every controller on the line (at least one); the first sets the serial baud.
    SimWorker(QList<SimDevice *> devices, const SimOptions &options);
    ~SimWorker() override;

    // In the worker's thread. On success the pty path and TCP port are known.
    bool open(QString *error);
    void close();
    // Hang up every transport; they come back after `pauseMs` (-1: the options' pause).
    void hangUp(int pauseMs);

    QString ptyPath() const { return m_ptyPath; }
    quint16 tcpPort() const { return m_tcpPort; }
    quint16 rtuTcpPort() const { return m_rtuTcpPort; }
    SimResponder *responder() const { return m_responder.get(); }
    // Called from the worker's thread whenever the pty path changes (empty while hung up).
    std::function<void(const QString &)> onPtyPath;

Q_SIGNALS:
    void hungUp();
    void reopened(const QString &ptyPath);
    void message(const QString &text);

private:
    bool openRtu(QString *error);
    // Modbus RTU on SimOptions::serialPort at the device's baud.
    bool openSerial(QString *error);
    bool serialMode() const { return !m_options.serialPort.isEmpty(); }
    void reopenRtu();
    void scheduleHangUp();

    QList<SimDevice *> m_devices;
    SimDevice *m_device; // the first: its baud is the line's
    SimOptions m_options;
    std::unique_ptr<SimResponder> m_responder;
    PtyBridge *m_bridge = nullptr;
    SimRtuServer *m_rtu = nullptr;
    SimTcpServer *m_tcp = nullptr;
    SimRtuTcpServer *m_rtuTcp = nullptr;
    QTimer *m_reopen = nullptr;
    QTimer *m_sync = nullptr; // keeps the model close to real time between requests
    QString m_ptyPath;
    quint16 m_tcpPort = 0;
    quint16 m_rtuTcpPort = 0;
};

} // namespace stepcom
