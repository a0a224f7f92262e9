#include "scenes.h"

#include "base/writechangesdialog.h"
#include "busscenes.h"
#include "dialogs/busscandialog.h"
#include "dialogs/profilecomparedialog.h"
#include "laptopscenes.h"
#include "offlinescenes.h"
#include "padscenes.h"
#include "pages/checklistpage.h"
#include "pages/connectionpage.h"
#include "pages/inputspage.h"
#include "pages/interpolationpage.h"
#include "pages/modespage.h"
#include "pages/motionpage.h"
#include "pages/motorpage.h"
#include "pages/plotpage.h"
#include "proofscenes.h"
#include "sequencescenes.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "shooter.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/checklist/checklistdirectionstep.h"
#include "widgets/checklist/checklistinputstep.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/patheditor.h"
#include "window/mainwindow.h"
#include "window/profileactions.h"
#include "window/windowprobe.h"

#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QTabWidget>

namespace stepcom {

namespace {

using Direction = JogController::Direction;

ParameterField *field(MainWindow *window, const QString &key)
{
    for (ParameterField *f : window->findChildren<ParameterField *>()) {
        if (f->parameter().key == key)
            return f;
    }
    return nullptr;
}

bool idle(Shooter &s)
{
    SimDevice *sim = s.simulator()->device();
    return !s.session()->connection()->isConnected() ||
           (!s.session()->jog()->isBusy() && !sim->running(1) && !sim->running(2));
}

// Jog `motor` for `ms` the way a technician does (press, hold, let go) and wait until it stands.
void jog(Shooter &s, int motor, Direction direction, int ms)
{
    Script &script = s.script();
    script.then([&s, motor, direction] {
        if (!s.session()->jog()->press(motor, direction))
            s.script().fail(QStringLiteral("motor %1 did not start jogging").arg(motor));
    });
    script.sleep(ms);
    script.then([&s, motor] { s.session()->jog()->release(motor); });
    script.waitFor(QStringLiteral("motor %1 to stand still").arg(motor), [&s] { return idle(s); });
}

// Positions away from zero and a trace in the plots: the pictures of a machine that moved.
void warmup(Shooter &s)
{
    jog(s, 1, Direction::Forward, 1200);
    jog(s, 2, Direction::Forward, 800);
    jog(s, 1, Direction::Reverse, 500);
}

// The jog page while motor 1 runs: the lamp, the live position, the stop button.
void jogging(Shooter &s)
{
    const int page = s.pageIndex<MotionPage>();
    Script &script = s.script();
    script.then([&s, page] { WindowProbe(*s.window()).showPage(page); });
    script.sleep(200);
    script.then([&s] {
        if (!s.session()->jog()->press(1, Direction::Forward))
            s.script().fail(QStringLiteral("motor 1 did not start jogging"));
    });
    script.sleep(800);
    s.shoot(Shooter::sceneFileName(QStringLiteral("jogging"))); // not a page change: it would stop
    script.then([&s] { s.session()->jog()->release(1); });
    script.waitFor(QStringLiteral("motor 1 to stand still"), [&s] { return idle(s); });
}

// Both motors driving back to position 0 ("Return to data zero", not a jog: a page change does
// not stop it), watched on the Plots page.
void plotsMoving(Shooter &s)
{
    Script &script = s.script();
    script.then([&s] {
        QPushButton *button = WindowProbe(*s.window()).motionPage()->returnToZeroButton();
        if (!button->isEnabled()) {
            s.script().fail(QStringLiteral("\"Return to data zero\" is disabled"));
            return;
        }
        button->click();
    });
    script.waitFor(QStringLiteral("a motor to run"), [&s] {
        SimDevice *sim = s.simulator()->device();
        return sim->running(1) || sim->running(2);
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("plots-moving")), s.pageIndex<PlotPage>());
    script.waitFor(QStringLiteral("the motors to stand still"), [&s] { return idle(s); });
}

QDockWidget *dock(Shooter &s, const char *name)
{
    return s.window()->findChild<QDockWidget *>(QLatin1String(name));
}

// The traffic log in front of the messages, over the first motor page.
void traffic(Shooter &s)
{
    auto height = std::make_shared<int>(0);
    s.script().then([&s, height] {
        QDockWidget *d = dock(s, "trafficDock");
        if (!d) {
            s.script().fail(QStringLiteral("the window has no traffic dock"));
            return;
        }
        d->raise();
        // Tall enough for a dozen frames.
        *height = d->height();
        s.window()->resizeDocks({d}, {s.window()->height() * 2 / 5}, Qt::Vertical);
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("traffic")), s.pageIndex<MotorPage>());
    s.script().then([&s, height] {
        s.window()->resizeDocks({dock(s, "trafficDock")}, {*height}, Qt::Vertical);
        if (QDockWidget *d = dock(s, "messageDock"))
            d->raise();
    });
}

// Two edits held on the first motor page, the write dialog listing them; then written, and the
// status bar's "not saved to flash".
void writeChanges(Shooter &s)
{
    Script &script = s.script();
    script.then([&s] {
        WindowProbe(*s.window()).showPage(s.pageIndex<MotorPage>());
        ParameterField *speed = field(s.window(), QStringLiteral("motor1.speed"));
        ParameterField *accel = field(s.window(), QStringLiteral("motor1.accel_frequency"));
        if (!speed || !accel) {
            s.script().fail(QStringLiteral("motor 1's speed or acceleration field is missing"));
            return;
        }
        speed->enterText(QStringLiteral("450"));
        accel->enterText(QStringLiteral("1200"));
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("edited")));
    script.then([&s] { WindowProbe(*s.window()).writeChanges(); });
    script.waitFor(QStringLiteral("the write dialog"), [&s] {
        return WindowProbe(*s.window()).writeDialog() &&
               WindowProbe(*s.window()).writeDialog()->isVisible();
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("write-changes")), -1,
            [&s]() -> QWidget * { return WindowProbe(*s.window()).writeDialog(); });
    script.then([&s] {
        auto *write = WindowProbe(*s.window())
                          .writeDialog()
                          ->findChild<QPushButton *>(QStringLiteral("writeButton"));
        if (!write) {
            s.script().fail(QStringLiteral("the write dialog has no write button"));
            return;
        }
        write->click();
    });
    script.waitFor(QStringLiteral("the write to be verified"), [&s] {
        return !s.session()->parameters()->store()->hasEdits() &&
               s.session()->parameters()->store()->unsavedToFlash();
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("not-saved-to-flash")));
}

// A wiring mistake, held as an edit (nothing written): motor 2's home input on its positive
// limit. The wiring check judges the values shown, edits included.
void wiringWarning(Shooter &s)
{
    Script &script = s.script();
    script.then([&s] {
        ParameterField *home = field(s.window(), QStringLiteral("motor2.home_input"));
        if (!home) {
            s.script().fail(QStringLiteral("motor 2's home input field is missing"));
            return;
        }
        const auto input =
            s.session()->parameters()->store()->shownValue(QStringLiteral("motor2.limit_positive"));
        if (!input || *input == 0) {
            s.script().fail(QStringLiteral("motor 2 has no positive limit input to misuse"));
            return;
        }
        home->enterText(QString::number(*input));
        if (!s.session()->parameters()->store()->hasEdits())
            s.script().fail(QStringLiteral("the home input edit was refused"));
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("wiring-warning")), s.pageIndex<InputsPage>());
    script.then([&s] { s.session()->parameters()->store()->revertAll(); });
}

// Shows the interpolation page's tab (0 arc, 1 line) and types the values into its fields;
// false (and the script failed) when the page or a field is missing.
bool typeInterpolation(Shooter &s, int page, int tab,
                       const QList<std::pair<const char *, const char *>> &values)
{
    auto *interpolation =
        qobject_cast<InterpolationPage *>(WindowProbe(*s.window()).pages().value(page));
    if (!interpolation) {
        s.script().fail(QStringLiteral("the window has no interpolation page"));
        return false;
    }
    WindowProbe(*s.window()).showPage(page);
    interpolation->tabs()->setCurrentIndex(tab);
    for (const auto &[key, value] : values) {
        ParameterField *f = field(s.window(), QLatin1String(key));
        if (!f) {
            s.script().fail(
                QStringLiteral("the interpolation page has no field %1").arg(QLatin1String(key)));
            return false;
        }
        f->enterText(QLatin1String(value));
    }
    return true;
}

// The arc tab with a quarter circle written to the controller, running: the preview with the
// approach, the path and the live trace of the real run.
void arcRunning(Shooter &s)
{
    Script &script = s.script();
    const int page = s.pageIndex<InterpolationPage>();
    script.then([&s, page] {
        const QList<std::pair<const char *, const char *>> values = {
            {"arc.enabled", "1"},   {"arc.mode", "0"},      {"arc.start_x", "40"},
            {"arc.start_y", "20"},  {"arc.end_x", "20"},    {"arc.end_y", "40"},
            {"arc.center_x", "20"}, {"arc.center_y", "20"}, {"arc.direction", "1"},
            {"arc.speed", "120"}};
        if (!typeInterpolation(s, page, 0, values))
            return;
        s.session()->parameters()->writeChanges();
    });
    script.waitFor(QStringLiteral("the arc to be written"),
                   [&s] { return !s.session()->parameters()->store()->hasEdits(); });
    script.waitFor(QStringLiteral("Start arc to be enabled"), [&s, page] {
        auto *p = qobject_cast<InterpolationPage *>(WindowProbe(*s.window()).pages().value(page));
        return p->arcEditor()->startButton()->isEnabled();
    });
    script.then([&s, page] {
        qobject_cast<InterpolationPage *>(WindowProbe(*s.window()).pages().value(page))
            ->arcEditor()
            ->startButton()
            ->click();
    });
    script.sleep(3000);
    s.shoot(Shooter::sceneFileName(QStringLiteral("arc-running")));
    script.waitFor(
        QStringLiteral("the arc to end"), [&s] { return idle(s); }, 30000);
}

// The line tab while a line is being typed: the preview follows before anything is written.
void lineEdited(Shooter &s)
{
    Script &script = s.script();
    const int page = s.pageIndex<InterpolationPage>();
    script.then([&s, page] {
        typeInterpolation(s, page, 1,
                          {{"line.enabled", "1"},
                           {"line.start_x", "10"},
                           {"line.start_y", "5"},
                           {"line.end_x", "60"},
                           {"line.end_y", "35"},
                           {"line.speed", "200"}});
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("line-edited")));
    script.then([&s, page] {
        s.session()->parameters()->store()->revertAll();
        qobject_cast<InterpolationPage *>(WindowProbe(*s.window()).pages().value(page))
            ->tabs()
            ->setCurrentIndex(0);
    });
}

// Choosing a special mode asks first; the picture is taken with the question open, and the
// answer is No: nothing is written.
void modeQuestion(Shooter &s)
{
    Script &script = s.script();
    const int page = s.pageIndex<ModesPage>();
    const auto modes = [&s, page] {
        return qobject_cast<ModesPage *>(WindowProbe(*s.window()).pages().value(page));
    };
    script.then([&s, page, modes] {
        if (!modes()) {
            s.script().fail(QStringLiteral("the window has no modes page"));
            return;
        }
        WindowProbe(*s.window()).showPage(page);
        modes()->chooseMode(3);
    });
    script.waitFor(QStringLiteral("the mode question"), [modes] {
        return modes()->confirmation() && modes()->confirmation()->isVisible();
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("mode-question")), -1,
            [modes]() -> QWidget * { return modes()->confirmation(); });
    script.then([modes] { modes()->confirmation()->reject(); });
}

ProfileActions *profiles(Shooter &s)
{
    ProfileActions *actions = WindowProbe(*s.window()).profileActions();
    if (!actions)
        s.script().fail(QStringLiteral("the window has no profile actions"));
    return actions;
}

// A profile of the next machine (two values differ from the controller) opened: the comparison,
// before anything is written.
void profileCompare(Shooter &s)
{
    Script &script = s.script();
    const QString path = s.scratchPath(QStringLiteral("machine-a.json"));
    script.then([&s, path] {
        ProfileActions *actions = profiles(s);
        ParameterField *speed = field(s.window(), QStringLiteral("motor1.speed"));
        ParameterField *micro = field(s.window(), QStringLiteral("motor2.microsteps"));
        if (!actions || !speed || !micro) {
            s.script().fail(QStringLiteral("no profile actions or motor fields"));
            return;
        }
        WindowProbe(*s.window()).showPage(s.pageIndex<MotorPage>());
        speed->enterText(QStringLiteral("600"));
        micro->enterText(QStringLiteral("16"));
        const bool saved = actions->saveFromEditedFile(path);
        s.session()->parameters()->store()->revertAll();
        if (!saved || !actions->openFile(path))
            s.script().fail(
                QStringLiteral("the profile %1 could not be saved and opened").arg(path));
    });
    const auto dialog = [&s]() -> ProfileCompareDialog * {
        return WindowProbe(*s.window()).profileActions()->compareDialog();
    };
    script.waitFor(QStringLiteral("the comparison"), [dialog] {
        return dialog() && dialog()->isVisible() && !dialog()->isBusy() &&
               dialog()->applyButton()->isEnabled();
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("profile-compare")), -1, dialog);
    script.then([dialog] { dialog()->reject(); });
}

// A broken profile: every problem named, nothing written.
void profileError(Shooter &s)
{
    Script &script = s.script();
    const QString path = s.scratchPath(QStringLiteral("broken.json"));
    script.then([&s, path] {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) ||
            file.write("{\n  \"format\": \"stepcom-profile\",\n  \"schema\": 1,\n  \"values\": {\n"
                       "    \"motor1.speed\": 300,,\n") < 0) {
            s.script().fail(QStringLiteral("cannot write %1").arg(path));
            return;
        }
        file.close();
        if (ProfileActions *actions = profiles(s); actions && actions->openFile(path))
            s.script().fail(QStringLiteral("the broken profile was accepted"));
    });
    const auto box = [&s]() -> QWidget * {
        return WindowProbe(*s.window()).profileActions()->errorBox();
    };
    script.waitFor(QStringLiteral("the profile error"),
                   [box] { return box() && box()->isVisible(); });
    s.shoot(Shooter::sceneFileName(QStringLiteral("profile-error")), -1, box);
    script.then([&s] { WindowProbe(*s.window()).profileActions()->errorBox()->close(); });
}

// A controller at id 7 that nobody remembers: the bus scan finds it.
void busScan(Shooter &s)
{
    Script &script = s.script();
    script.then([&s] {
        SimHost *sim = s.extraSimulator(7);
        if (!sim)
            return;
        auto *page = qobject_cast<ConnectionPage *>(
            WindowProbe(*s.window()).pages().value(s.pageIndex<ConnectionPage>()));
        if (!page) {
            s.script().fail(QStringLiteral("the window has no connection page"));
            return;
        }
        WindowProbe(*s.window()).showPage(s.pageIndex<ConnectionPage>());
        BusScanDialog *dialog = page->openBusScan();
        LinkSettings base;
        base.portName = sim->rtuPath();
        dialog->setBaseSettings(base);
        dialog->setCheckedBauds({9600, 19200});
        dialog->setIdRange(1, 10);
        dialog->setProbeTimeoutMs(0); // fitted to the baud, as a technician finds it
        dialog->startScan();
    });
    const auto dialog = [&s]() -> BusScanDialog * {
        auto *page = qobject_cast<ConnectionPage *>(
            WindowProbe(*s.window()).pages().value(s.pageIndex<ConnectionPage>()));
        return page ? page->scanDialog() : nullptr;
    };
    script.waitFor(
        QStringLiteral("the bus scan to finish"),
        [dialog] { return dialog() && !dialog()->isScanning() && dialog()->foundCount() > 0; },
        30000);
    s.shoot(Shooter::sceneFileName(QStringLiteral("bus-scan")), -1, dialog);
    script.then([dialog] { dialog()->reject(); });
}

// A serial port that is not there: what the connection page says. Last, as it disconnects.
void portMissing(Shooter &s)
{
    Script &script = s.script();
    const int index = s.pageIndex<ConnectionPage>();
    script.then([&s] { s.session()->connection()->disconnectFrom(); });
    script.waitFor(QStringLiteral("the disconnect"),
                   [&s] { return !s.session()->connection()->isConnected(); });
    auto port = std::make_shared<QString>();
    script.then([&s, index, port] {
        // A name that does not exist here, so the picture never talks to a real adapter.
        for (int n = 0; n < 100 && port->isEmpty(); ++n) {
            const QString candidate = QStringLiteral("/dev/ttyUSB%1").arg(n);
            if (!QFileInfo::exists(candidate))
                *port = candidate;
        }
        auto *page = qobject_cast<ConnectionPage *>(WindowProbe(*s.window()).pages().value(index));
        WindowProbe(*s.window()).showPage(index);
        LinkSettings settings;
        settings.portName = *port;
        page->applySettings(settings);
        page->setTransport(ConnectionPage::Transport::Serial);
        page->connectNow();
    });
    script.waitFor(QStringLiteral("the connection attempt to fail"), [&s, index, port] {
        auto *page = qobject_cast<ConnectionPage *>(WindowProbe(*s.window()).pages().value(index));
        return !s.session()->connection()->isConnected() && page->statusText().contains(*port);
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("port-missing")));
}

// The checklist's direction step after its small step: "did the axis move toward + ?".
void checklistDirection(Shooter &s)
{
    Script &script = s.script();
    script.then([&s] {
        WindowProbe(*s.window()).showPage(s.pageIndex<ChecklistPage>());
        ChecklistPage *page = WindowProbe(*s.window()).checklistPage();
        page->selectStep(QStringLiteral("motor1.direction"));
        auto *w = qobject_cast<ChecklistDirectionStep *>(
            page->stepWidget(QStringLiteral("motor1.direction")));
        w->moveButton()->click();
    });
    script.waitFor(QStringLiteral("the direction step's question"), [&s] {
        auto *w = qobject_cast<ChecklistDirectionStep *>(
            WindowProbe(*s.window())
                .checklistPage()
                ->stepWidget(QStringLiteral("motor1.direction")));
        return w && w->yesButton()->isEnabled();
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("checklist-direction")));
}

// A miswired positive limit found by the checklist: the register says IN3, IN1 answered; the
// fix is proposed. The register is put back afterwards.
void checklistMiswired(Shooter &s)
{
    Script &script = s.script();
    const auto widget = [&s] {
        return qobject_cast<ChecklistInputStep *>(
            WindowProbe(*s.window())
                .checklistPage()
                ->stepWidget(QStringLiteral("motor1.limit_positive")));
    };
    script.then([&s] {
        s.simulator()->device()->setValue(QStringLiteral("motor1.limit_positive"), 3);
        s.session()->parameters()->readAll();
    });
    script.sleep(800);
    script.then([&s, widget] {
        WindowProbe(*s.window()).showPage(s.pageIndex<ChecklistPage>());
        WindowProbe(*s.window())
            .checklistPage()
            ->selectStep(QStringLiteral("motor1.limit_positive"));
        widget()->watchButton()->click();
        s.simulator()->device()->setInput(1, SimDevice::InputForce::On);
    });
    script.sleep(600);
    script.then([&s] { s.simulator()->device()->setInput(1, SimDevice::InputForce::Off); });
    script.sleep(600);
    script.then([widget] { widget()->doneButton()->click(); });
    s.shoot(Shooter::sceneFileName(QStringLiteral("checklist-miswired")));
    script.then([&s] {
        s.simulator()->device()->setValue(QStringLiteral("motor1.limit_positive"), 1);
        s.session()->parameters()->readAll();
        // The next language's pictures start from an empty checklist again.
        ChecklistPage *page = WindowProbe(*s.window()).checklistPage();
        QFile::remove(page->checklistFile());
        page->setProfilePath(page->profilePath());
    });
    script.sleep(500);
}

} // namespace

const QList<Scene> &scenes()
{
    using W = Scene::When;
    static const QList<Scene> table = {
        {QStringLiteral("warmup"), W::BeforePages, &warmup},
        {QStringLiteral("jogging"), W::AfterPages, &jogging},
        {QStringLiteral("plots-moving"), W::AfterPages, &plotsMoving},
        {QStringLiteral("traffic"), W::AfterPages, &traffic},
        {QStringLiteral("wiring-warning"), W::AfterPages, &wiringWarning},
        {QStringLiteral("arc-running"), W::AfterPages, &arcRunning},
        {QStringLiteral("line-edited"), W::AfterPages, &lineEdited},
        {QStringLiteral("mode-question"), W::AfterPages, &modeQuestion},
        {QStringLiteral("bus-scan"), W::AfterPages, &busScan},
        {QStringLiteral("profile-compare"), W::AfterPages, &profileCompare},
        {QStringLiteral("profile-error"), W::AfterPages, &profileError},
        {QStringLiteral("write-changes"), W::AfterPages, &writeChanges},
        {QStringLiteral("checklist-direction"), W::AfterPages, &checklistDirection},
        {QStringLiteral("checklist-miswired"), W::AfterPages, &checklistMiswired},
        {QStringLiteral("checklist-margin"), W::AfterPages, &proofscenes::margin},
        {QStringLiteral("sequence-run"), W::AfterPages, &sequencescenes::running},
        {QStringLiteral("gamepad-jogging"), W::AfterPages, &padscenes::jogging},
        {QStringLiteral("device-list"), W::AfterPages, &busscenes::deviceList},
        // Small laptop screens, while connected: before port-missing.
        {QStringLiteral("laptop-1024x600"), W::AfterPages, &laptopscenes::small},
        {QStringLiteral("laptop-1366x768-150"), W::AfterPages, &laptopscenes::scaled},
        {QStringLiteral("port-missing"), W::AfterPages, &portMissing},
        // Without a controller: after port-missing, which leaves it disconnected.
        {QStringLiteral("offline-editing"), W::AfterPages, &offlinescenes::editing},
        {QStringLiteral("profile-files-compare"), W::AfterPages, &offlinescenes::compareFiles},
        {QStringLiteral("replay"), W::AfterPages, &offlinescenes::replay},
    };
    return table;
}

} // namespace stepcom
