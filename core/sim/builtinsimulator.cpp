#include "sim/builtinsimulator.h"

#include "sim/simdevice.h"
#include "sim/simhost.h"

namespace stepcom {

BuiltinSimulator::BuiltinSimulator()
    : m_host(std::make_unique<SimHost>())
{}

BuiltinSimulator::~BuiltinSimulator() = default;

std::optional<LinkSettings> BuiltinSimulator::start(const RegisterMap &map, QString *error)
{
    if (!m_host->isRunning()) {
        SimOptions options;
        options.map = map;
        options.ids = m_ids;
#ifdef Q_OS_UNIX
        options.rtu = true;
#else
        options.tcp = true;
#endif
        if (!m_host->start(options, error))
            return std::nullopt;
    }
    LinkSettings s;
    if (!m_host->rtuPath().isEmpty()) {
        s.transport = LinkSettings::Transport::Rtu;
        s.portName = m_host->rtuPath();
        s.baud = m_host->device() ? m_host->device()->baud() : 9600;
        s.deviceId = m_host->device() ? m_host->device()->deviceId() : 1;
    } else {
        s.transport = LinkSettings::Transport::Tcp;
        s.host = m_host->tcpAddress().toString();
        s.tcpPort = m_host->tcpPort();
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

bool BuiltinSimulator::serves(const LinkSettings &s) const
{
    return s.transport == LinkSettings::Transport::Rtu
               ? !s.portName.isEmpty() && s.portName == m_host->rtuPath()
               : s.tcpPort == m_host->tcpPort() && m_host->tcpPort() != 0;
}

} // namespace stepcom
