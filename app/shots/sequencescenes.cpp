#include "sequencescenes.h"

#include "pages/sequencepage.h"
#include "script.h"
#include "sequence/sequencerunner.h"
#include "shooter.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/sequence/sequencerunpanel.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QDir>
#include <QFile>
#include <QSpinBox>

namespace stepcom::sequencescenes {

namespace {

const char kCycle[] = R"({"format": "stepcom-sequence", "version": 1,
 "points": {"load": {"motor1": 40.0}, "unload": {"motor1": 10.0}, "clear": {"motor1": 25.0}},
 "limits": {"motor1": {"min": 0, "max": 300}},
 "steps": [
   {"home": "motor1"},
   {"repeat": 2, "steps": [
     {"move_to": "load"},
     {"wait_input": 3, "on": true, "timeout_s": 20},
     {"output": 1, "on": true},
     {"dwell_ms": 300},
     {"move_to": "clear"},
     {"move_to": "unload"},
     {"output": 1, "on": false}]}]})";

} // namespace

void running(Shooter &s)
{
    Script &script = s.script();
    const auto page = [&s] { return s.window()->findChild<SequencePage *>(); };
    const QString path = QDir::temp().filePath(QStringLiteral("pick-and-place.stepseq"));
    script.then([&s, page, path] {
        QFile f(path);
        if (f.open(QIODevice::WriteOnly))
            f.write(kCycle);
        f.close();
        s.simulator()->device()->setInput(3, SimDevice::InputForce::On);
        WindowProbe(*s.window()).showPage(s.pageIndex<SequencePage>());
        SequencePage *p = page();
        p->setConfirmer([](const QString &) { return true; });
        p->openFile(path);
        p->runPanel()->cyclesBox()->setValue(5);
        p->runPanel()->run();
    });
    script.waitFor(
        QStringLiteral("the first cycle's way back"),
        [page] {
            SequenceRunner *r = page()->runPanel()->runner();
            return r->cycle() >= 1 && r->currentStep() == QLatin1String("steps[1].steps[4]");
        },
        120000);
    s.shoot(Shooter::sceneFileName(QStringLiteral("sequence-run")));
    script.then([&s, page, path] {
        page()->runPanel()->stop();
        s.simulator()->device()->setInput(3, SimDevice::InputForce::Off);
        QFile::remove(path);
    });
    script.waitFor(
        QStringLiteral("the run's end"), [page] { return !page()->runPanel()->isBusy(); }, 20000);
}

} // namespace stepcom::sequencescenes
