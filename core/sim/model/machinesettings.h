#pragma once

#include "sim/model/axisphysics.h"

#include <QMap>
#include <QString>

namespace stepcom {

// A whole simulated machine as a machine file describes it (see MachineFile): each axis's
// physics and the machine-wide choices.
struct MachineSettings
{
    QString source;                // the file it came from, for messages; empty: built in
    bool homingZeroesCount = true; // the home coil zeroes the count at the switch
    quint32 seed = 1;              // of the switches' jitter
    QMap<int, AxisPhysics> axes;   // by motor number (1-based)
    AxisPhysics others;            // motors the file does not name

    AxisPhysics axis(int motor) const { return axes.value(motor, others); }

    // Without a machine file: the ideal machine of AxisPhysics::ideal().
    static MachineSettings ideal()
    {
        MachineSettings m;
        m.others = AxisPhysics::ideal();
        return m;
    }
};

} // namespace stepcom
