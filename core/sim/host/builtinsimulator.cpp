#include "sim/host/builtinsimulator.h"

#include "sim/host/simhost.h"
#include "sim/model/machinefile.h"
#include "sim/model/simdevice.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

namespace stepcom {

BuiltinSimulator::BuiltinSimulator()
    : m_host(std::make_unique<SimHost>())
{}

BuiltinSimulator::~BuiltinSimulator() = default;

void BuiltinSimulator::setClientLink(int deviceId, int baud)
{
    m_clientId = deviceId;
    m_clientBaud = baud;
}

QString BuiltinSimulator::defaultFlashPath()
{
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/StepCom/stepcom/simulator/flash.json");
}

bool BuiltinSimulator::resetFlash(const QString &path, QString *error)
{
    const QFileInfo info(path);
    QStringList files;
    if (info.exists())
        files << info.absoluteFilePath();
    // The other controllers of a line of several: PATH-2, PATH-3, ...
    const QFileInfoList more = info.dir().entryInfoList({info.fileName() + QStringLiteral("-*")},
                                                        QDir::Files | QDir::Hidden);
    for (const QFileInfo &f : more)
        files << f.absoluteFilePath();
    for (const QString &file : std::as_const(files)) {
        QFile f(file);
        if (!f.remove()) {
            if (error)
                *error =
                    QCoreApplication::translate("stepcom::BuiltinSimulator", "cannot remove %1: %2")
                        .arg(file, f.errorString());
            return false;
        }
    }
    return true;
}

bool BuiltinSimulator::setMachineFile(const QString &path, QString *error)
{
    m_machine.reset();
    if (path.isEmpty())
        return true;
    QString why;
    m_machine = MachineFile::load(path, &why);
    if (!m_machine && error)
        *error = QCoreApplication::translate("stepcom::BuiltinSimulator",
                                             "%1 (the simulator runs as the ideal machine)")
                     .arg(why);
    return m_machine.has_value();
}

std::optional<LinkSettings> BuiltinSimulator::start(const RegisterMap &map, QString *error)
{
    if (!m_host->isRunning()) {
        SimOptions options;
        options.map = map;
        options.ids = m_ids;
        options.checkBaud = true; // silent when the client's baud is not the controller's
        options.statePath = m_flashPath;
        options.machine = m_machine;
        if (!m_flashPath.isEmpty() && !QDir().mkpath(QFileInfo(m_flashPath).absolutePath())) {
            if (error)
                *error = QCoreApplication::translate("stepcom::BuiltinSimulator",
                                                     "cannot make the folder of %1")
                             .arg(m_flashPath);
            return std::nullopt;
        }
#ifdef Q_OS_UNIX
        options.rtu = true;
        options.echo = m_echo;
#else
        options.tcp = true;
#endif
        if (!m_host->start(options, error))
            return std::nullopt;
    }
    LinkSettings s;
    s.timeoutMs = m_timing.timeoutMs;
    s.adaptTimeout = m_timing.adaptTimeout;
    s.retries = m_timing.retries;
    s.answerDelayMs = m_timing.answerDelayMs;
    s.turnaroundMs = m_timing.turnaroundMs;
    if (!m_host->rtuPath().isEmpty()) {
        s.transport = LinkSettings::Transport::Rtu;
        s.portName = m_host->rtuPath();
        s.baud = m_clientBaud > 0   ? m_clientBaud
                 : m_host->device() ? m_host->device()->baud()
                                    : 9600;
        s.deviceId = m_clientId > 0     ? m_clientId
                     : m_host->device() ? m_host->device()->deviceId()
                                        : 1;
        s.echo = m_echo;
    } else {
        s.transport = LinkSettings::Transport::Tcp;
        s.host = m_host->tcpAddress().toString();
        s.tcpPort = m_host->tcpPort();
        if (m_clientId > 0)
            s.deviceId = m_clientId;
    }
    return s;
}

void BuiltinSimulator::stop()
{
    m_host->stop();
}

bool BuiltinSimulator::isRunning() const
{
    return m_host->isRunning();
}

bool BuiltinSimulator::resetToFactory(QString *error)
{
    m_host->stop(); // what it holds in memory goes with it; a new start makes new devices
    return m_flashPath.isEmpty() || resetFlash(m_flashPath, error);
}

bool BuiltinSimulator::serves(const LinkSettings &s) const
{
    return s.transport == LinkSettings::Transport::Rtu
               ? !s.portName.isEmpty() && s.portName == m_host->rtuPath()
               : s.tcpPort == m_host->tcpPort() && m_host->tcpPort() != 0;
}

} // namespace stepcom
