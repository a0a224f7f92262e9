#include "widgets/fields/statetone.h"

#include <cmath>

namespace stepcom {

namespace {

double luminance(const QColor &c)
{
    auto channel = [](double v) {
        return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    const QColor rgb = c.toRgb();
    return 0.2126 * channel(rgb.redF()) + 0.7152 * channel(rgb.greenF()) +
           0.0722 * channel(rgb.blueF());
}

// Mixes `from` towards `to` by `t` (0..1).
QColor mix(const QColor &from, const QColor &to, double t)
{
    return QColor::fromRgbF(float(from.redF() + (to.redF() - from.redF()) * t),
                            float(from.greenF() + (to.greenF() - from.greenF()) * t),
                            float(from.blueF() + (to.blueF() - from.blueF()) * t));
}

} // namespace

double contrastRatio(const QColor &a, const QColor &b)
{
    const double la = luminance(a);
    const double lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

QColor stateColour(StateTone tone, const QPalette &palette, QPalette::ColorRole background)
{
    const QColor back = palette.color(QPalette::Active, background);
    const bool dark = back.lightness() < 128;
    QColor colour;
    switch (tone) {
    case StateTone::Good:
        colour = dark ? QColor(110, 220, 110) : QColor(0, 120, 0);
        break;
    case StateTone::Running:
        colour = dark ? QColor(110, 180, 255) : QColor(0, 90, 190);
        break;
    case StateTone::Warning:
        colour = dark ? QColor(255, 170, 60) : QColor(170, 80, 0);
        break;
    case StateTone::Fault:
        colour = dark ? QColor(255, 110, 110) : QColor(190, 20, 20);
        break;
    case StateTone::Unknown:
        // Grey, as the palette greys what it cannot use, but never too faint to read.
        colour = palette.color(QPalette::Disabled, QPalette::WindowText);
        break;
    case StateTone::Normal:
        colour = palette.color(QPalette::Active, QPalette::WindowText);
        break;
    }
    // A palette of the system's own may put any background under it.
    return withContrast(colour, back, kMinContrast);
}

QColor withContrast(const QColor &colour, const QColor &background, double ratio)
{
    // Move towards black or white until the mark stands out as much as the rule asks.
    const QColor extreme = background.lightness() < 128 ? QColor(Qt::white) : QColor(Qt::black);
    QColor c = colour.toRgb();
    for (int step = 1; step <= 10 && contrastRatio(c, background) < ratio; ++step)
        c = mix(c, extreme, 0.1 * step);
    return c;
}

} // namespace stepcom
