#include "ctloptions.h"
#include "ctlrunner.h"
#include "i18n/translators.h"
#include "map/registermap.h"
#include "sim/host/builtinsimulator.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QTextStream>

#include <memory>

using namespace stepcom;

namespace {

// Only `report` and `bundle` (its machine report) draw (QTextDocument, QPdfWriter, QPainter) and
// need a QGuiApplication; every other command stays a plain QCoreApplication that runs without
// any display.
bool wantsReport(int argc, char *argv[])
{
    QStringList args;
    for (int i = 0; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    QCommandLineParser parser;
    CtlOptions::addOptions(parser);
    parser.addOption(Translators::languageOption());
    parser.addHelpOption();
    parser.addVersionOption();
    // A support bundle holds the machine's report.
    const QString command = parser.parse(args) ? parser.positionalArguments().value(0) : QString();
    return command == QLatin1String("report") || command == QLatin1String("bundle");
}

} // namespace

int main(int argc, char *argv[])
{
    std::unique_ptr<QCoreApplication> application;
    if (wantsReport(argc, argv)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen"); // a report needs no screen
        application = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        application = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication &app = *application;
    QCoreApplication::setApplicationName(QStringLiteral("stepcomctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));
    QTextStream err(stderr);

    // The language first: the help and every message are translated when they are built.
    Translators translators;
    const QString language = Translators::languageFromArguments(QCoreApplication::arguments());
    // --json before the arguments are parsed: a usage error is said in the JSON object too.
    const bool json = CtlRunner::jsonAsked(QCoreApplication::arguments());
    if (!Translators::available().contains(language))
        return CtlRunner::failEarly(CtlRunner::UsageError,
                                    {Translators::unknownLanguageMessage(language)}, json);
    translators.install(language);

    QCommandLineParser parser;
    // The commands' lines come from the runner's dispatch table.
    parser.setApplicationDescription(
        QCoreApplication::translate("stepcomctl", "Read and write the parameters of a 2-axis "
                                                  "stepper controller over Modbus RTU/TCP.") +
        QStringLiteral("\n\n") + CtlRunner::commandsHelp() + QLatin1Char('\n') +
        CtlRunner::exitCodesHelp() + QLatin1Char('\n') +
        QCoreApplication::translate("stepcomctl", "One command's help: stepcomctl NAME --help"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"),
                                 QCoreApplication::translate("stepcomctl", "What to do."));
    CtlOptions::addOptions(parser);
    parser.addOption(Translators::languageOption());
    if (!parser.parse(QCoreApplication::arguments()))
        return CtlRunner::failEarly(CtlRunner::UsageError, {parser.errorText()}, json);
    if (parser.isSet(QStringLiteral("help"))) {
        // NAME --help: that command alone.
        const QString help = CtlRunner::commandHelp(parser.positionalArguments().value(0));
        if (!help.isEmpty()) {
            QTextStream(stdout) << help;
            return CtlRunner::Ok;
        }
        parser.showHelp(0);
    }
    if (parser.isSet(QStringLiteral("version")))
        parser.showVersion();

    CtlOptions options;
    if (const QString problem = CtlOptions::fromParser(parser, &options); !problem.isEmpty())
        return CtlRunner::failEarly(CtlRunner::UsageError, {problem}, json);
    options.language = language; // the report is written in the program's language
    if (options.simReset) {
        QString problem;
        if (!BuiltinSimulator::resetFlash(BuiltinSimulator::defaultFlashPath(), &problem))
            return CtlRunner::failEarly(CtlRunner::DeviceError, {problem}, json);
        err << QStringLiteral("stepcomctl: ")
            << QCoreApplication::translate("stepcomctl",
                                           "the built-in simulator starts from the factory "
                                           "again (id 1, 9600 baud)")
            << Qt::endl;
        if (options.command.isEmpty())
            return CtlRunner::Ok;
    }
    RegisterMap map = RegisterMap::builtin();
    if (!options.mapFile.isEmpty()) {
        QStringList errors;
        auto loaded = RegisterMap::loadFile(options.mapFile, &errors);
        if (!loaded)
            return CtlRunner::failEarly(CtlRunner::UsageError, errors, json);
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
