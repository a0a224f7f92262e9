#pragma once

#include "session/simulatorstarter.h"

#include <QList>

#include <memory>

namespace stepcom {

class SimHost;

// The built-in simulated controller as a session starts it (the window's "Built-in simulator",
// every program's --sim, the tests): a SimHost in this process, reached over a pseudo-terminal
// on Unix -- the same RTU path as a real adapter -- and over loopback TCP elsewhere.
class BuiltinSimulator : public SimulatorStarter
{
public:
    BuiltinSimulator();
    ~BuiltinSimulator() override;

    std::optional<LinkSettings> start(const RegisterMap &map, QString *error) override;
    void stop() override;
    bool isRunning() const override;
    bool serves(const LinkSettings &settings) const override;

    // Rehearse an adapter that echoes what it sends (--sim --echo); takes effect at start().
    void setEcho(bool echo) { m_echo = echo; }
    // Several controllers on the one line (SimOptions::ids), for the next start().
    void setIds(const QList<int> &ids) { m_ids = ids; }

    // The running simulator, for the tools and tests that act on the simulated machine.
    SimHost *host() const { return m_host.get(); }

private:
    std::unique_ptr<SimHost> m_host;
    bool m_echo = false;
    QList<int> m_ids;
};

} // namespace stepcom
