#include "commissioning/travelcalibration.h"

#include "map/parameter.h"

#include <QLocale>

#include <cmath>

namespace stepcom {

namespace {

constexpr qint64 kMilli = 1000; // distances are taken to 0.001 of the axis unit

QString number(double v)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator); // as typed: 2000000, not 2,000,000
    return locale.toString(v, 'f', QLocale::FloatingPointShortest);
}

} // namespace

CalibrationProposal TravelCalibration::propose(const Parameter &pitch, qint64 pitchRaw,
                                               double commanded, double measured)
{
    CalibrationProposal out;
    const QString unit = pitch.unit;
    for (const auto &[value, what] : {std::pair{commanded, tr("commanded distance")},
                                      std::pair{measured, tr("measured distance")}}) {
        if (!std::isfinite(value) || value <= 0) {
            out.error =
                tr("the %1 must be more than 0 %2, found %3")
                    .arg(what, unit, std::isfinite(value) ? number(value) : tr("not a number"));
            return out;
        }
        if (value > MaxDistance) {
            out.error =
                tr("the %1 %2 %3 is not a distance on a machine").arg(what, number(value), unit);
            return out;
        }
    }
    if (const QString why = pitch.checkRaw(pitchRaw); !why.isEmpty() || pitchRaw <= 0) {
        out.error =
            tr("the current pitch (%1) cannot be corrected: %2")
                .arg(pitch.formatRaw(pitchRaw), why.isEmpty() ? tr("it must be more than 0") : why);
        return out;
    }
    const qint64 c = std::llround(commanded * kMilli);
    const qint64 m = std::llround(measured * kMilli);
    if (c <= 0 || m <= 0) {
        out.error = tr("the distances must be at least 0.001 %1").arg(unit);
        return out;
    }
    out.factor = double(m) / double(c);
    if (out.factor > MaxFactor || out.factor < 1.0 / MaxFactor) {
        out.error = tr("%1 %2 measured for %3 %2 commanded is off by a factor of %4: that is not "
                       "a calibration error. Check the microsteps (driver DIP switches and "
                       "register), the step angle and the pitch, then measure again")
                        .arg(number(measured), unit, number(commanded),
                             QLocale().toString(out.factor, 'f', 3));
        return out;
    }
    // pitchRaw ≤ 2^31 and m ≤ 10^9: the product fits 64 bits. Round half away from zero.
    const qint64 num = pitchRaw * m;
    const qint64 corrected = (2 * num + c) / (2 * c);
    if (const QString why = pitch.checkRaw(corrected); !why.isEmpty()) {
        out.error =
            tr("the corrected pitch would be %1 %2: %3").arg(pitch.formatRaw(corrected), unit, why);
        return out;
    }
    out.raw = corrected;
    return out;
}

} // namespace stepcom
