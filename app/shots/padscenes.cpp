#include "padscenes.h"

#include "gamepad/virtualgamepad.h"
#include "pages/motionpage.h"
#include "script.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "shooter.h"
#include "widgets/motion/gamepadpanel.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QCheckBox>
#include <QScrollArea>

#include <memory>

namespace stepcom::padscenes {

void jogging(Shooter &s)
{
    Script &script = s.script();
    auto pad = std::make_shared<VirtualGamepad>();
    const auto panel = [&s] { return s.window()->findChild<GamepadPanel *>(); };
    script.then([&s, panel] {
        WindowProbe(*s.window()).showPage(s.pageIndex<MotionPage>());
        panel()->enableBox()->setChecked(true);
    });
    script.then([pad] {
        QString why;
        if (pad->attach(QStringLiteral("Wireless Controller"), &why)) {
            pad->setAxis(VirtualGamepad::Axis::RightTrigger, 1.0);
            pad->setAxis(VirtualGamepad::Axis::LeftX, 0.9);
        }
    });
    script.waitFor(
        QStringLiteral("the pad's jog"), [&s] { return s.session()->jog()->isJogging(1); }, 20000);
    script.then([panel] {
        // The page scrolls on a laptop's screen: the pad's box is what the picture is about.
        for (QWidget *p = panel()->parentWidget(); p; p = p->parentWidget()) {
            if (auto *area = qobject_cast<QScrollArea *>(p)) {
                area->ensureWidgetVisible(panel(), 0, 0);
                break;
            }
        }
    });
    script.sleep(600);
    s.shoot(Shooter::sceneFileName(QStringLiteral("gamepad-jogging")));
    script.then([pad, panel] {
        pad->detach();
        panel()->enableBox()->setChecked(false); // SDL stops after the pad has gone
    });
    script.waitFor(
        QStringLiteral("the jog's end"), [&s] { return !s.session()->jog()->isBusy(); }, 20000);
}

} // namespace stepcom::padscenes
