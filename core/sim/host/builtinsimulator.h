#pragma once

#include "session/simulatorstarter.h"
#include "sim/model/machinesettings.h"

#include <QList>

#include <memory>

namespace stepcom {

class SimHost;

// The built-in simulated controller as a session starts it (the window's "Built-in simulator",
// every program's --sim, the tests): a SimHost in this process, reached over a pseudo-terminal
// on Unix -- the same RTU path as a real adapter -- and over loopback TCP elsewhere. As a real
// controller it answers only at its own id and baud (setClientLink: what the client opens the
// line with), and the programs keep what it saved to flash in a file (setFlashPath), so a
// saved id or baud is there again on the next run, as after a power cycle.
class BuiltinSimulator : public SimulatorStarter
{
public:
    BuiltinSimulator();
    ~BuiltinSimulator() override;

    std::optional<LinkSettings> start(const RegisterMap &map, QString *error) override;
    void stop() override;
    bool isRunning() const override;
    bool serves(const LinkSettings &settings) const override;
    bool resetToFactory(QString *error) override;

    // Rehearse an adapter that echoes what it sends (--sim --echo); takes effect at start().
    void setEcho(bool echo) { m_echo = echo; }
    // Several controllers on the one line (SimOptions::ids), for the next start().
    void setIds(const QList<int> &ids) { m_ids = ids; }
    // The id and baud the client opens the line with (0: whatever the simulator holds); at
    // another id or baud the controller does not answer, as a real one.
    void setClientLink(int deviceId, int baud);
    // How long the client waits for an answer, how often it tries again, its delays (--timeout,
    // --retries, --answer-delay, --turnaround, --fixed-timeout): the link start() gives has
    // them, so the simulator is reached as the client asked (defaults: LinkSettings').
    void setClientTiming(const LinkSettings &timing) { m_timing = timing; }
    // Where what it saves to flash is kept (empty, the default: in memory, gone at stop()). The
    // n-th controller of setIds (n > 1) keeps it in PATH-n.
    void setFlashPath(const QString &path) { m_flashPath = path; }
    QString flashPath() const { return m_flashPath; }
    // The window's data folder (organisation StepCom, application stepcom), spelled out so
    // stepcomctl, another application, uses the same flash.
    static QString defaultFlashPath();
    // Forgets what was saved at `path` (and PATH-n): the next start is at the factory values.
    // False and why when a file cannot be removed.
    static bool resetFlash(const QString &path, QString *error);

    // The machine's mechanics from a machine file (MachineFile) for the next start(); empty:
    // the ideal machine. A file that cannot be used gives false and why, and the simulator keeps
    // the ideal machine (it still starts).
    bool setMachineFile(const QString &path, QString *error);
    // Where the window keeps the machine file's path (stepcom --sim --machine sets it for a run).
    static QString machineFileSettingsKey() { return QStringLiteral("simulator/machineFile"); }
    const std::optional<MachineSettings> &machine() const { return m_machine; }

    // The running simulator, for the tools and tests that act on the simulated machine.
    SimHost *host() const { return m_host.get(); }

private:
    std::unique_ptr<SimHost> m_host;
    bool m_echo = false;
    QList<int> m_ids;
    int m_clientId = 0;
    int m_clientBaud = 0;
    LinkSettings m_timing;
    QString m_flashPath;
    std::optional<MachineSettings> m_machine;
};

} // namespace stepcom
