#pragma once

#include <QList>
#include <QString>

namespace stepcom {

class Shooter;

// The guide's pictures beyond one per page: each scene plans its steps on the shooter's script
// (set the window up, shoot, put it back). Add a scene by adding a row to scenes().
struct Scene
{
    // Before the page pictures (to set the machine up, e.g. move the motors so the plots and
    // positions show something), or after them.
    enum class When { BeforePages, AfterPages };
    QString name; // a scene that shoots names its file scene-<name>.png
    When when;
    void (*plan)(Shooter &shooter);
};

const QList<Scene> &scenes();

} // namespace stepcom
