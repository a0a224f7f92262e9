#pragma once

#include "map/registermap.h"

#include <QHash>

namespace stepcom {

// The values a controller leaves the factory with: the manual's where it names one (device id
// 1, 9600 baud, no limit or home input, normal system mode), otherwise StepCom's starting
// values, plausible for a 1.8° motor with an 8× driver on a 5 mm lead screw. "New profile
// from factory values", filling what a variant profile lacks, and the simulator start here.
class FactoryValues
{
public:
    // The factory value of a holding register, always one the map allows.
    static qint64 value(const Parameter &parameter);
    // Every read-write holding register of `map` by key (link settings included).
    static QHash<QString, qint64> writable(const RegisterMap &map);
};

} // namespace stepcom
