#pragma once

#include <QSize>

class QWidget;

namespace stepcom {

// `wanted` (a dialog's or tool window's first size, from its font) made no larger than the
// screen `widget` (or its parent) is on, with room for the window frame: a 1366×768 laptop at
// 150 % has 910×512 to offer, a netbook 1024×600.
QSize fitToScreen(const QWidget *widget, QSize wanted);

} // namespace stepcom
