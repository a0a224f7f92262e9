#include "base/fittoscreen.h"

#include <QScreen>
#include <QWidget>

namespace stepcom {

QSize fitToScreen(const QWidget *widget, QSize wanted)
{
    const QWidget *parent = widget->parentWidget();
    const QScreen *where = parent ? parent->screen() : widget->screen();
    return where ? wanted.boundedTo(where->availableGeometry().size() * 0.95) : wanted;
}

} // namespace stepcom
