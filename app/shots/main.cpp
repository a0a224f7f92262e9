// stepcom-shots: the user guide's screenshots, taken from the real window on the built-in
// simulator (scripts/screenshots.sh runs it offscreen). Not installed; a tool of the docs.
#include "base/language.h"
#include "laptopscenes.h"
#include "scenes.h"
#include "shooter.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFile>
#include <QSettings>
#include <QStyle>
#include <QStyleFactory>
#include <QTemporaryDir>
#include <QTextStream>

using namespace stepcom;

int main(int argc, char *argv[])
{
    // The window keeps itself inside its screen (MainWindow::fitIntoScreen): offscreen, give it
    // a screen larger than any picture size asked for (the plugin's default is 800×600), and
    // beside it the small laptop screens of laptopscenes.cpp.
    QTemporaryDir screenDir;
    if (qgetenv("QT_QPA_PLATFORM") == "offscreen" && screenDir.isValid()) {
        const QString config = screenDir.filePath(QStringLiteral("screen.json"));
        QFile file(config);
        if (file.open(QIODevice::WriteOnly) &&
            file.write(R"({"screens": [{"name": "shots", "x": 0, "y": 0, "width": 3840, )"
                       R"("height": 2400, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}, )" +
                       laptopscenes::screensJson()) > 0) {
            file.close();
            qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + config.toLocal8Bit());
        }
    }
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("StepComShots"));
    QApplication::setApplicationName(QStringLiteral("stepcom-shots"));
    QApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));
    // One window per language, one after the other: closing the first must not end the run.
    QApplication::setQuitOnLastWindowClosed(false);
    // The same look on every machine that regenerates the pictures.
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QApplication::setPalette(QApplication::style()->standardPalette());

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Takes the user guide's screenshots: every page of the window and the "
                       "guide's scenes, on the built-in simulator, in each language. Run it "
                       "with QT_QPA_PLATFORM=offscreen (scripts/screenshots.sh does)."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption outOption(QStringLiteral("out"),
                                       QStringLiteral("Write <dir>/<language>/*.png (required)."),
                                       QStringLiteral("dir"));
    const QCommandLineOption langOption(QStringLiteral("lang"),
                                        QStringLiteral("Only this language (repeatable): %1.")
                                            .arg(Language::available().join(QLatin1String(", "))),
                                        QStringLiteral("language"));
    const QCommandLineOption sizeOption(QStringLiteral("size"),
                                        QStringLiteral("Window size (default 1280x800)."),
                                        QStringLiteral("WxH"), QStringLiteral("1280x800"));
    const QCommandLineOption sceneOption(
        QStringLiteral("scene"),
        QStringLiteral("Only this scene besides the pages (repeatable); the other pictures "
                       "in the directory are kept. Without it, old pictures are removed."),
        QStringLiteral("name"));
    const QCommandLineOption listOption(QStringLiteral("list-scenes"),
                                        QStringLiteral("Print the scene names and exit."));
    parser.addOptions({outOption, langOption, sizeOption, sceneOption, listOption});
    parser.process(app);

    QTextStream err(stderr);
    QStringList sceneNames;
    for (const Scene &scene : scenes())
        sceneNames << scene.name;
    if (parser.isSet(listOption)) {
        QTextStream(stdout) << sceneNames.join(QLatin1Char('\n')) << Qt::endl;
        return 0;
    }
    if (!parser.isSet(outOption)) {
        err << "stepcom-shots: --out DIR is required" << Qt::endl;
        return 2;
    }
    Shooter::Options options;
    options.outDir = QDir(parser.value(outOption));
    options.languages =
        parser.isSet(langOption) ? parser.values(langOption) : Language::available();
    for (const QString &language : std::as_const(options.languages)) {
        if (!Language::available().contains(language)) {
            err << "stepcom-shots: unknown language " << language
                << " (known: " << Language::available().join(QLatin1String(", ")) << ")"
                << Qt::endl;
            return 2;
        }
    }
    const QStringList size = parser.value(sizeOption).split(QLatin1Char('x'));
    bool okW = false;
    bool okH = false;
    options.size =
        size.size() == 2 ? QSize(size.at(0).toInt(&okW), size.at(1).toInt(&okH)) : QSize();
    if (!okW || !okH || options.size.width() < 640 || options.size.height() < 400) {
        err << "stepcom-shots: --size wants WxH, at least 640x400, not " << parser.value(sizeOption)
            << Qt::endl;
        return 2;
    }
    options.onlyScenes = parser.values(sceneOption);
    for (const QString &name : std::as_const(options.onlyScenes)) {
        if (!sceneNames.contains(name)) {
            err << "stepcom-shots: unknown scene " << name
                << " (known: " << sceneNames.join(QLatin1String(", ")) << ")" << Qt::endl;
            return 2;
        }
    }

    // Never the user's own settings (window layout, last port): a fresh, throw-away store.
    QTemporaryDir settingsDir;
    if (!settingsDir.isValid()) {
        err << "stepcom-shots: no temporary directory: " << settingsDir.errorString() << Qt::endl;
        return 1;
    }
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    // The same for the data location: the checklist's progress and the backups.
    qputenv("XDG_DATA_HOME", QFile::encodeName(settingsDir.filePath(QStringLiteral("data"))));

    Shooter shooter(options);
    int exitCode = 0;
    QObject::connect(&shooter, &Shooter::finished, &app, [&](bool ok, const QString &error) {
        if (!ok) {
            err << "stepcom-shots: " << error << Qt::endl;
            exitCode = 1;
        }
        QApplication::exit(exitCode);
    });
    shooter.start();
    const int result = app.exec();
    if (result == 0 && exitCode == 0 && !shooter.isDone()) {
        err << "stepcom-shots: ended before every picture was taken" << Qt::endl;
        return 1;
    }
    return result == 0 ? exitCode : 1;
}
