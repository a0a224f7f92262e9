#include "busscenes.h"

#include "motion/referencetracker.h"
#include "pages/motorpage.h"
#include "script.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionline.h"
#include "shooter.h"
#include "widgets/docks/devicelistdock.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QAction>

namespace stepcom::busscenes {

void deviceList(Shooter &s)
{
    // The built-in simulator serves ids 1, 2 and 3 (Shooter); the list names them as a
    // technician would, motor 1 of device 2 homed, device 2 in view.
    Script &script = s.script();
    script.then([&s] {
        DeviceListDock *dock = WindowProbe(*s.window()).deviceListDock();
        s.session()->line()->setDeviceIds({1, 2, 3});
        dock->setName(1, QStringLiteral("X/Y table"));
        dock->setName(2, QStringLiteral("Z axis, spindle"));
        dock->setName(3, QStringLiteral("Loader"));
        dock->toggleViewAction()->trigger(); // as View → Devices on the line does
        s.session()->line()->showDevice(2);
    });
    script.sleep(1500);
    script.then([&s] { s.session()->command(QStringLiteral("motor1.home")); });
    script.waitFor(
        QStringLiteral("device 2's motor 1 to be referenced"),
        [&s] { return s.session()->motion()->references()->isReferenced(1); }, 30000);
    script.sleep(2500); // the other devices' background status
    s.shoot(Shooter::sceneFileName(QStringLiteral("device-list")), s.pageIndex<MotorPage>());
    script.then([&s] {
        s.session()->line()->showDevice(1);
        WindowProbe(*s.window()).deviceListDock()->hide();
        s.session()->line()->setDeviceIds({});
    });
    script.sleep(1000);
}

} // namespace stepcom::busscenes
