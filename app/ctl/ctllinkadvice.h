#pragma once

#include "ctloptions.h"
#include "device/writeplanner.h" // ParameterWrite

#include <QCoreApplication>
#include <QStringList>

namespace stepcom {

// What stepcomctl says after a controller took a new device id or baud: whether it lasts past
// the next power-off, what the next command needs to reach it, and -- behind a converter --
// that the converter's serial side must follow the new baud.
class CtlLinkAdvice
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::CtlLinkAdvice)

public:
    // The options that reach the controller now ("--port /dev/ttyUSB0 --baud 19200 --id 7").
    static QString nextOptions(const CtlOptions &options, int deviceId, int baud);
    // The lines to print after `device.id` (newId > 0) and/or `device.baud` (newBaud > 0) were
    // written and verified; `saved`: saved to flash afterwards.
    static QStringList notes(const CtlOptions &options, int newId, int newBaud, bool saved);
    // The same for a write: the device.id and device.baud among `writes` (nothing without them).
    static QStringList notes(const CtlOptions &options, const QList<ParameterWrite> &writes,
                             bool saved);
};

} // namespace stepcom
