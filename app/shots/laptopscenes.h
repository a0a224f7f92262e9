#pragma once

#include <QByteArray>
#include <QSize>
#include <QString>

namespace stepcom {

class Shooter;

// The window on the small laptop screens technicians carry: the guide's "On a small
// laptop screen" pictures. Unlike the other pictures they are not 1280×800.
namespace laptopscenes {

// The window moves onto a screen of that size (stepcom-shots makes them beside its large one),
// so that it arranges itself as it does there (the status dock below the page, ...).
// 1024×600 at 100 %.
void small(Shooter &s);
// 1366×768 at 150 % display scaling: 910×512 of room, drawn 1.5 times finer.
void scaled(Shooter &s);
// The size of the picture `fileName` (scene-<name>.png) when it is one of these; empty otherwise.
QSize pictureSize(const QString &fileName);
// The offscreen platform's description of those screens: the rest of its "screens" list, from
// the second entry on, with the closing "]}".
QByteArray screensJson();

} // namespace laptopscenes
} // namespace stepcom
