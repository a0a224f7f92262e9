#pragma once

#include "bus/linksettings.h"

class QSettings;

namespace stepcom {

// The saved connection: LinkSettings in a QSettings group (the window's "connection" group).
// Unknown or missing values fall back to the factory settings.
namespace LinkSettingsStore {

LinkSettings read(QSettings &settings);
void write(QSettings &settings, const LinkSettings &link);

} // namespace LinkSettingsStore

} // namespace stepcom
