#include "proofscenes.h"

#include "pages/checklistpage.h"
#include "script.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "shooter.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/checklist/checklistproofstep.h"
#include "widgets/plots/marginplot.h"
#include "window/windowprobe.h"

#include <QDoubleSpinBox>
#include <QFile>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>

namespace stepcom::proofscenes {

void margin(Shooter &s)
{
    Script &script = s.script();
    const QString id = QStringLiteral("motor1.keeps_steps");
    const auto widget = [&s, id] {
        return qobject_cast<ChecklistProofStep *>(
            WindowProbe(*s.window()).checklistPage()->stepWidget(id));
    };
    const MachineSettings before = s.simulator()->device()->machine();
    script.then([&s] {
        MachineSettings m = MachineSettings::ideal();
        AxisPhysics axis = AxisPhysics::ideal();
        axis.startMm = 1.0;
        axis.pullOutRpm = 250;
        axis.pullInRpm = 100;
        m.axes.insert(1, axis);
        s.simulator()->device()->setMachine(m);
        s.simulator()->device()->setValue(QStringLiteral("motor1.start_frequency"), 1600);
        s.session()->parameters()->readAll();
    });
    script.sleep(800);
    script.then([&s, widget, id] {
        WindowProbe(*s.window()).showPage(s.pageIndex<ChecklistPage>());
        WindowProbe(*s.window()).checklistPage()->selectStep(id);
        ChecklistProofStep *w = widget();
        w->setConfirmer([](const QString &) { return true; });
        w->cyclesField()->setValue(1);
        w->distanceField()->setValue(2);
        w->fromField()->setValue(100);
        w->toField()->setValue(400);
        w->stepField()->setValue(100);
        w->marginButton()->click();
    });
    script.waitFor(
        QStringLiteral("the margin search"), [widget] { return !widget()->isRunning(); }, 180000);
    script.then([widget] {
        // The page scrolls on a laptop's screen: the plot is what the picture is about.
        for (QWidget *p = widget()->parentWidget(); p; p = p->parentWidget()) {
            if (auto *area = qobject_cast<QScrollArea *>(p)) {
                area->ensureWidgetVisible(widget()->plot(), 0, 0);
                break;
            }
        }
    });
    script.sleep(300);
    s.shoot(Shooter::sceneFileName(QStringLiteral("checklist-margin")));
    script.then([&s, before] {
        s.simulator()->device()->setMachine(before);
        s.simulator()->device()->setValue(QStringLiteral("motor1.start_frequency"), 400);
        s.simulator()->device()->setValue(QStringLiteral("motor1.speed"), 300);
        s.session()->parameters()->readAll();
        // The next language's pictures start from an empty checklist again.
        ChecklistPage *page = WindowProbe(*s.window()).checklistPage();
        QFile::remove(page->checklistFile());
        page->setProfilePath(page->profilePath());
    });
    script.sleep(500);
}

} // namespace stepcom::proofscenes
