#include "ctloptions.h"
#include "ctlrunner.h"
#include "i18n/translators.h"
#include "map/registermap.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

using namespace stepcom;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stepcomctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));
    QTextStream err(stderr);

    // The language first: the help and every message are translated when they are built.
    Translators translators;
    const QString language = Translators::languageFromArguments(QCoreApplication::arguments());
    if (!Translators::available().contains(language)) {
        err << QStringLiteral("stepcomctl: ") << Translators::unknownLanguageMessage(language)
            << Qt::endl;
        return CtlRunner::UsageError;
    }
    translators.install(language);

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "stepcomctl",
        "Read and write the parameters of a 2-axis stepper controller over Modbus RTU/TCP.\n\n"
        "Commands:\n"
        "  params                 list every parameter and command of the register map\n"
        "  read [KEY...]          read parameters (all when none are named)\n"
        "  write KEY=VALUE...     write parameters in engineering units, then verify\n"
        "  command NAME           pulse a command coil (e.g. motor1.stop, estop)\n"
        "  monitor                print the live status as one JSON object per line,\n"
        "                         until --count samples or Ctrl-C (--interval MS)\n\n"
        "Exit codes: 0 success, 1 link or device error, 2 usage or validation error."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"),
                                 QCoreApplication::translate("stepcomctl", "What to do."));
    CtlOptions::addOptions(parser);
    parser.addOption(Translators::languageOption());
    if (!parser.parse(QCoreApplication::arguments())) {
        err << QStringLiteral("stepcomctl: ") << parser.errorText() << Qt::endl;
        return CtlRunner::UsageError;
    }
    if (parser.isSet(QStringLiteral("help")))
        parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();

    CtlOptions options;
    if (const QString problem = CtlOptions::fromParser(parser, &options); !problem.isEmpty()) {
        err << QStringLiteral("stepcomctl: ") << problem << Qt::endl;
        return CtlRunner::UsageError;
    }
    RegisterMap map = RegisterMap::builtin();
    if (!options.mapFile.isEmpty()) {
        QStringList errors;
        auto loaded = RegisterMap::loadFile(options.mapFile, &errors);
        if (!loaded) {
            for (const QString &e : std::as_const(errors))
                err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
            return CtlRunner::UsageError;
        }
        map = *loaded;
    }
    CtlRunner runner(options, map);
    int exitCode = 0;
    QObject::connect(&runner, &CtlRunner::finished, &app, [&](int code) {
        exitCode = code;
        QCoreApplication::exit(code);
    });
    runner.start();
    app.exec();
    return exitCode;
}
