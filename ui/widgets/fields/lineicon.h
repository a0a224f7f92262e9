#pragma once

#include <QIcon>

class QPalette;

namespace stepcom {

// The project's line icons (resources/sidebar/*.svg, 24×24, stroked in currentColor) as a
// QIcon drawn from the SVG at every size and device pixel ratio asked for -- crisp at ×1.5 and
// ×2 -- in the palette's text colour (greyed when disabled, highlighted text when selected),
// so they read on a dark window too. An unreadable resource gives a null icon.
QIcon lineIcon(const QString &resource, const QPalette &palette);

} // namespace stepcom
