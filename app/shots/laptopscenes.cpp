#include "laptopscenes.h"

#include "pages/motorpage.h"
#include "shooter.h"

namespace stepcom::laptopscenes {

namespace {

struct Laptop
{
    const char *scene;
    QSize pixels; // the screen's physical pixels
    qreal scale;  // display scaling
    int x;        // where it lies beside the large screen
};

constexpr Laptop kSmall{"laptop-1024x600", {1024, 600}, 1.0, 3840};
constexpr Laptop kScaled{"laptop-1366x768-150", {1366, 768}, 1.5, 3840 + 1024};

QString screenName(const Laptop &l)
{
    return QString::fromLatin1(l.scene);
}

// The room the screen offers the window: its pixels divided by the scaling.
QSize logical(const Laptop &l)
{
    return {int(l.pixels.width() / l.scale), int(l.pixels.height() / l.scale)};
}

} // namespace

void small(Shooter &s)
{
    // Motor 1: the longest form, with the status dock below it on this screen.
    s.shootOnScreen(Shooter::sceneFileName(screenName(kSmall)), s.pageIndex<MotorPage>(),
                    screenName(kSmall));
}

void scaled(Shooter &s)
{
    s.shootOnScreen(Shooter::sceneFileName(screenName(kScaled)), s.pageIndex<MotorPage>(),
                    screenName(kScaled));
}

QSize pictureSize(const QString &fileName)
{
    for (const Laptop &l : {kSmall, kScaled}) {
        if (fileName == Shooter::sceneFileName(screenName(l))) {
            // The window fills the screen's room, drawn at the screen's scale.
            return logical(l) * l.scale;
        }
    }
    return {};
}

QByteArray screensJson()
{
    QByteArray json;
    for (const Laptop &l : {kSmall, kScaled}) {
        json += QStringLiteral(R"({"name": "%1", "x": %2, "y": 0, "width": %3, "height": %4, )"
                               R"("logicalDpi": 96, "logicalBaseDpi": 96, "dpr": %5}, )")
                    .arg(screenName(l))
                    .arg(l.x)
                    .arg(logical(l).width()) // the offscreen platform's sizes are logical
                    .arg(logical(l).height())
                    .arg(l.scale)
                    .toUtf8();
    }
    json.chop(2); // the last ", "
    return json + "]}";
}

} // namespace stepcom::laptopscenes
