#include "sim/model/simtruth.h"

#include "sim/model/simaxis.h"

#include <QJsonArray>

#include <cmath>

namespace stepcom {

SimTruth::Axis SimTruth::Axis::of(int motor, const SimAxis &axis)
{
    const double spu = axis.settings().stepsPerUnit();
    Axis a;
    a.motor = motor;
    a.count = axis.steps();
    a.countMm = double(axis.positionRaw()) / 100.0;
    a.rotorMm = axis.rotorSteps() / spu;
    a.carriageMm = axis.machinePosition();
    a.offsetMm = axis.rotorMachinePosition() - a.rotorMm;
    const double lost = axis.exactSteps() - axis.rotorSteps();
    a.lostPulses = qint64(std::llround(lost));
    a.lostMm = a.carriageMm - a.offsetMm - axis.exactSteps() / spu;
    a.stalled = axis.stalled();
    a.negativeSwitch = axis.negativeSwitch();
    a.positiveSwitch = axis.positiveSwitch();
    a.negativeTripMm = axis.negativeSwitchState().tripPoint();
    a.positiveTripMm = axis.positiveSwitchState().tripPoint();
    return a;
}

QJsonObject SimTruth::toJson() const
{
    QJsonArray list;
    for (const Axis &a : axes) {
        list.append(QJsonObject{{QStringLiteral("motor"), a.motor},
                                {QStringLiteral("count"), a.count},
                                {QStringLiteral("count_mm"), a.countMm},
                                {QStringLiteral("rotor_mm"), a.rotorMm},
                                {QStringLiteral("carriage_mm"), a.carriageMm},
                                {QStringLiteral("offset_mm"), a.offsetMm},
                                {QStringLiteral("lost_pulses"), a.lostPulses},
                                {QStringLiteral("lost_mm"), a.lostMm},
                                {QStringLiteral("stalled"), a.stalled},
                                {QStringLiteral("negative_switch"), a.negativeSwitch},
                                {QStringLiteral("positive_switch"), a.positiveSwitch},
                                {QStringLiteral("negative_trip_mm"), a.negativeTripMm},
                                {QStringLiteral("positive_trip_mm"), a.positiveTripMm}});
    }
    return {{QStringLiteral("time_ms"), timeMs}, {QStringLiteral("axes"), list}};
}

} // namespace stepcom
