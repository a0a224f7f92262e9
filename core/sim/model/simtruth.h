#pragma once

#include <QJsonObject>
#include <QList>
#include <QtGlobal>

namespace stepcom {

class SimAxis;

// What really happened on the simulated machine, beside what the registers say. Frames: the
// count and the rotor in pulses (and mm) from the count's zero; the carriage in mm from the
// nominal negative switch; offsetMm = carriageMm − rotorMm − the play the carriage has taken in
// the drive, so lostMm = carriageMm − offsetMm − countMm (negative: the carriage is behind the
// count). lostPulses is count − rotor since power-up: zeroing the count keeps it.
struct SimTruth
{
    struct Axis
    {
        int motor = 0;
        qint64 count = 0;      // the pulse counter
        double countMm = 0;    // the position register's value, mm
        double rotorMm = 0;    // the rotor in the count's frame, mm
        double carriageMm = 0; // from the nominal negative switch
        double offsetMm = 0;   // the carriage frame's origin in the count's frame
        qint64 lostPulses = 0; // count − rotor, whole 4-full-step chunks after a stall
        double lostMm = 0;     // carriage relative to the count (backlash included)
        bool stalled = false;  // out of sync now
        bool negativeSwitch = false;
        bool positiveSwitch = false;
        double negativeTripMm = 0; // the trip point of the current or next approach
        double positiveTripMm = 0;

        static Axis of(int motor, const SimAxis &axis);
    };

    qint64 timeMs = 0;
    QList<Axis> axes;

    // {"time_ms": t, "axes": [{"motor": 1, "count": ..., ...}, ...]}
    QJsonObject toJson() const;
};

} // namespace stepcom
