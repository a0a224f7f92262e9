#pragma once

#include <QColor>
#include <QPalette>

namespace stepcom {

// One palette for states: the machine strip's words, the sidebar's marks and the
// status bar's link state take their colours here, so a state looks the same everywhere and
// stays readable on a light and on a dark window.
enum class StateTone { Normal, Good, Running, Warning, Fault, Unknown };

// The colour of a text or mark in `tone` drawn on `palette`'s `background`: the tone's hue,
// darkened or lightened until its contrast with the background is at least kMinContrast.
QColor stateColour(StateTone tone, const QPalette &palette,
                   QPalette::ColorRole background = QPalette::Window);

// `colour` darkened on a light `background`, lightened on a dark one, until their contrast is
// at least `ratio` (a lamp's own hue, made readable on any window).
QColor withContrast(const QColor &colour, const QColor &background, double ratio);

// WCAG 2 contrast ratio of two colours (1 to 21).
double contrastRatio(const QColor &a, const QColor &b);

// What a state mark must keep against its background (WCAG's ratio for graphics and large text).
inline constexpr double kMinContrast = 3.0;

} // namespace stepcom
