#pragma once

#include "bus/linksettings.h"

#include <QString>

#include <optional>

namespace stepcom {

class RegisterMap;

// The seam between a session and the built-in simulator: stepcom_core knows only this
// interface, the programs that offer --sim hand the session stepcom_sim's BuiltinSimulator.
class SimulatorStarter
{
public:
    virtual ~SimulatorStarter() = default;
    // Start the simulated controller for `map` unless it runs; the settings that reach it, or
    // nullopt and a reason in `error`.
    virtual std::optional<LinkSettings> start(const RegisterMap &map, QString *error) = 0;
    virtual void stop() = 0;
    virtual bool isRunning() const = 0;
    // Whether a link with these settings talks to this simulator.
    virtual bool serves(const LinkSettings &settings) const = 0;
    // Stops it and forgets what it saved to flash: the next start is at the factory values.
    // False and why when that cannot be done.
    virtual bool resetToFactory(QString *error) = 0;
};

} // namespace stepcom
