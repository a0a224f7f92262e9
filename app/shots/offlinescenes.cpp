#include "offlinescenes.h"

#include "dialogs/profilefilesdialog.h"
#include "mainwindow.h"
#include "map/factoryvalues.h"
#include "offlineactions.h"
#include "pages/motorpage.h"
#include "profile/profiledocument.h"
#include "profile/profilefile.h"
#include "profileactions.h"
#include "session/devicesession.h"
#include "shooter.h"
#include "widgets/fields/parameterfield.h"

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
        if (s.session()->isConnected())
            s.session()->disconnectFrom();
    });
    script.then([&s, page] {
        const QString path =
            saveMachine(s, QStringLiteral("machine-a.json"), QStringLiteral("Machine A"), 420, 8);
        if (path.isEmpty() || !s.window()->profileActions()->openFile(path)) {
            s.script().fail(QStringLiteral("the profile could not be opened offline"));
            return;
        }
        s.window()->showPage(page);
        for (ParameterField *f : s.window()->findChildren<ParameterField *>()) {
            if (f->parameter().key == QLatin1String("motor1.speed"))
                f->enterText(QStringLiteral("450"));
        }
    });
    s.shoot(Shooter::sceneFileName(QStringLiteral("offline-editing")), page);
    script.then([&s] {
        s.session()->parameters()->revertAll();
        s.window()->offlineActions()->closeFile();
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
        if (a.isEmpty() || b.isEmpty() || !s.window()->offlineActions()->compareFiles(a, b))
            s.script().fail(QStringLiteral("the two profiles could not be compared"));
    });
    const auto dialog = [&s]() -> QWidget * { return s.window()->offlineActions()->filesDialog(); };
    script.waitFor(QStringLiteral("the two files compared"),
                   [dialog] { return dialog() && dialog()->isVisible(); });
    s.shoot(Shooter::sceneFileName(QStringLiteral("profile-files-compare")), -1, dialog);
    script.then([dialog] { dialog()->close(); });
}

} // namespace stepcom::offlinescenes
