#pragma once

#include "sim/host/simoptions.h"

#include <QHostAddress>
#include <QMutex>
#include <QObject>
#include <QString>

#include <memory>
#include <vector>

QT_BEGIN_NAMESPACE
class QThread;
QT_END_NAMESPACE

namespace stepcom {

class SimDevice;
class SimWorker;

// A running simulated controller: the device, and its Modbus RTU (pty) and/or TCP servers in a
// thread of their own, so answer delays never block the caller. The CLI's --sim, the window's
// built-in simulator, stepcom-sim and the tests all start one of these and talk to it with a
// normal client at rtuPath() or tcpAddress():tcpPort().
class SimHost : public QObject
{
    Q_OBJECT
public:
    struct Stats
    {
        int requests = 0;
        int answers = 0;
        int exceptions = 0;
        int dropped = 0;
        int corrupted = 0;
        int late = 0;
        int wrongBaud = 0;
        int collisions = 0;
    };

    explicit SimHost(QObject *parent = nullptr);
    ~SimHost() override;

    // Loads the state file, applies the options and opens the transports; false and a reason
    // when something could not be opened (nothing stays running then).
    bool start(const SimOptions &options, QString *error);
    void stop();
    bool isRunning() const { return m_thread != nullptr; }

    // The path clients open: the --link symlink when there is one, else the pty itself.
    // Empty while the port is hung up or without RTU.
    QString rtuPath() const;
    QString ptyPath() const;
    quint16 tcpPort() const { return m_tcpPort; }
    // RTU over TCP (SimOptions::rtuTcp), on tcpAddress().
    quint16 rtuTcpPort() const { return m_rtuTcpPort; }
    QHostAddress tcpAddress() const { return m_options.tcpAddress; }
    const SimOptions &options() const { return m_options; }

    // The controller itself, thread-safe; valid from start() until the next start() or the
    // host's destruction.
    SimDevice *device() const { return m_devices.empty() ? nullptr : m_devices.front().get(); }
    // Every controller on the line, in the order of SimOptions::ids.
    QList<SimDevice *> devices() const;
    // The first controller whose id is `id` now; null when none has it.
    SimDevice *deviceAt(int id) const;

    // Switch the 24 V supply off for `offMs` (see SimDevice::powerCycle()): id 0 every
    // controller on the line, else those with that id. False when no controller has the id.
    bool powerCycle(int offMs, int id = 0);

    // Hang up every port now; they come back after `pauseMs` (-1: the fault options' pause).
    void hangUp(int pauseMs = -1);
    Stats stats() const;

Q_SIGNALS:
    void hungUp();
    void reopened(const QString &ptyPath);
    void message(const QString &text);

private:
    std::unique_ptr<SimDevice> makeDevice(const SimOptions &options, int id,
                                          const QString &statePath, QString *error);
    void schedulePowerCycles();

    SimOptions m_options;
    std::vector<std::unique_ptr<SimDevice>> m_devices;
    QThread *m_thread = nullptr;
    SimWorker *m_worker = nullptr;
    QObject *m_schedule = nullptr; // parent of the timers of SimOptions::powerCycles
    quint16 m_tcpPort = 0;
    quint16 m_rtuTcpPort = 0;
    mutable QMutex m_pathMutex;
    QString m_ptyPath;
};

} // namespace stepcom
