#include "offlinescenes.h"

#include "dialogs/profilefilesdialog.h"
#include "map/factoryvalues.h"
#include "pages/motorpage.h"
#include "pages/plotpage.h"
#include "profile/profiledocument.h"
#include "profile/profilefile.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/sessionlog.h"
#include "session/stepmove.h"
#include "shooter.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/fields/parameterfield.h"
#include "window/mainwindow.h"
#include "window/offlineactions.h"
#include "window/profileactions.h"
#include "window/windowprobe.h"

namespace stepcom::offlinescenes {

namespace {

// Machine A's profile (the factory values with a few of its own), saved to a scratch file.
QString saveMachine(Shooter &s, const QString &file, const QString &name, qint64 speed,
                    qint64 microsteps)
{
    const RegisterMap &map = s.session()->map();
    Profile p = Profile::fromValues(map, FactoryValues::writable(map), false);
    p.name = name;
    p.notes = QStringLiteral("XY table, lead screws 5 mm");
    p.values[QStringLiteral("motor1.speed")] = speed;
    p.values[QStringLiteral("motor2.microsteps")] = microsteps;
    const QString path = s.scratchPath(file);
    if (const QString e = ProfileFile::save(path, p, map); !e.isEmpty()) {
        s.script().fail(e);
        return {};
    }
    return path;
}

} // namespace

void editing(Shooter &s)
{
    Script &script = s.script();
    const int page = s.pageIndex<MotorPage>();
    script.then([&s] {
        if (s.session()->connection()->isConnected())
            s.session()->connection()->disconnectFrom();
    });
    script.then([&s, page] {
        const QString path =
            saveMachine(s, QStringLiteral("machine-a.json"), QStringLiteral("Machine A"), 420, 8);
        if (path.isEmpty() || !WindowProbe(*s.window()).profileActions()->openFile(path)) {
            s.script().fail(QStringLiteral("the profile could not be opened offline"));
            return;
        }
        WindowProbe(*s.window()).showPage(page);
        for (ParameterField *f : s.window()->findChildren<ParameterField *>()) {
            if (f->parameter().key == QLatin1String("motor1.speed"))
                f->enterText(QStringLiteral("450"));
        }
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("offline-editing")), page);
    script.then([&s] {
        s.session()->parameters()->store()->revertAll();
        WindowProbe(*s.window()).offlineActions()->closeFile();
    });
}

void compareFiles(Shooter &s)
{
    Script &script = s.script();
    script.then([&s] {
        const QString a =
            saveMachine(s, QStringLiteral("machine-a.json"), QStringLiteral("Machine A"), 420, 8);
        const QString b =
            saveMachine(s, QStringLiteral("machine-b.json"), QStringLiteral("Machine B"), 450, 16);
        if (a.isEmpty() || b.isEmpty() ||
            !WindowProbe(*s.window()).offlineActions()->compareFiles(a, b))
            s.script().fail(QStringLiteral("the two profiles could not be compared"));
    });
    const auto dialog = [&s]() -> QWidget * {
        return WindowProbe(*s.window()).offlineActions()->filesDialog();
    };
    script.waitFor(QStringLiteral("the two files compared"),
                   [dialog] { return dialog() && dialog()->isVisible(); });
    s.shoot(Shooter::sceneFileName(QStringLiteral("profile-files-compare")), -1, dialog);
    script.then([dialog] { dialog()->close(); });
}

void replay(Shooter &s)
{
    Script &script = s.script();
    const int page = s.pageIndex<MotorPage>();
    const QString log = s.scratchPath(QStringLiteral("session-%1.log").arg(s.language()));
    const QString speed = QStringLiteral("motor1.speed");
    auto written = std::make_shared<qint64>(0);
    script.then([&s, log] {
        WindowProbe(*s.window()).sessionLog()->setFile(log);
        s.session()->connection()->connectSimulator();
    });
    script.waitFor(QStringLiteral("the read-all of the recorded session"), [&s] {
        return s.session()->connection()->isConnected() &&
               s.session()->parameters()->store()->deviceValue(QStringLiteral("motor1.position"));
    });
    script.then([&s, speed, written] {
        *written = s.session()->parameters()->store()->deviceValue(speed).value_or(300) + 50;
        s.session()->parameters()->store()->edit(speed, *written);
        s.session()->parameters()->writeChanges();
    });
    script.waitFor(QStringLiteral("the recorded write"), [&s, speed, written] {
        return s.session()->parameters()->store()->deviceValue(speed) == *written;
    });
    script.then([&s] { s.session()->stepMove()->start({StepMoveRequest::Kind::By, 1, 20.0, 0}); });
    script.sleep(300);
    script.waitFor(QStringLiteral("the recorded move"),
                   [&s] { return !s.session()->stepMove()->isBusy(); });
    script.then([&s] { s.session()->connection()->disconnectFrom(); });
    script.waitFor(QStringLiteral("the disconnect"),
                   [&s] { return !s.session()->connection()->isConnected(); });
    script.then([&s, log] {
        WindowProbe(*s.window()).sessionLog()->setFile(QString());
        WindowProbe(*s.window()).replayMode()->openPath(log);
    });
    script.waitFor(QStringLiteral("the replay"),
                   [&s] { return WindowProbe(*s.window()).replayMode()->isActive(); });
    script.then([&s, page] {
        ReplayMode *replay = WindowProbe(*s.window()).replayMode();
        // A moment of the move: after its command, before it ends.
        for (const ReplayEvent &e : replay->log().events()) {
            if (e.kind == ReplayEvent::Kind::Command)
                replay->seek(e.ms + 400);
        }
        WindowProbe(*s.window()).showPage(page);
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("replay")), page);
    // The last moment the link was up, on the Plots page with the device list open: the
    // position plot and the XY path of the move, each device's state then.
    script.then([&s] {
        ReplayMode *replay = WindowProbe(*s.window()).replayMode();
        qint64 at = replay->log().durationMs();
        while (at > 0 && !replay->log().stateAt(at).linkUp)
            at -= 10;
        replay->seek(at);
        WindowProbe(*s.window())
            .deviceListDock()
            ->toggleViewAction()
            ->trigger(); // as View → Devices does
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("replay-plots")), s.pageIndex<PlotPage>());
    script.then([&s] {
        WindowProbe(*s.window()).deviceListDock()->toggleViewAction()->trigger();
        WindowProbe(*s.window()).replayMode()->close();
    });
}

} // namespace stepcom::offlinescenes
