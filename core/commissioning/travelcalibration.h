#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace stepcom {

struct Parameter;

// What a travel calibration proposes: the corrected pitch as the register holds it, or why not.
struct CalibrationProposal
{
    std::optional<qint64> raw; // the corrected pitch, raw (×100 for a pitch in hundredths)
    QString error;             // why there is no proposal, naming what was wrong
    double factor = 0;         // measured ÷ commanded
    bool ok() const { return raw.has_value(); }
};

// The travel calibration step: the axis was commanded to move `commanded`, the technician
// measured `measured`; the pitch that makes the next move right is
//     corrected pitch = pitch × measured ÷ commanded,
// rounded (half away from zero) to the pitch register's resolution and checked against its range
// (both from the register map). Pure; exact: the distances are taken to 0.001 of the axis unit
// and the arithmetic is done in whole numbers, so 5.00 × 10.03 ÷ 10 is 5.02, not 5.01.
class TravelCalibration
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::TravelCalibration)
public:
    // A measurement off by more than this factor (either way) is not a calibration error but a
    // wrong microstep or pitch setting, or a misread scale: refused with a message saying so.
    static constexpr double MaxFactor = 1.5;
    // Distances above this (axis units) are refused as absurd (a typo, not a machine).
    static constexpr double MaxDistance = 1.0e6;

    static CalibrationProposal propose(const Parameter &pitch, qint64 pitchRaw, double commanded,
                                       double measured);
};

} // namespace stepcom
