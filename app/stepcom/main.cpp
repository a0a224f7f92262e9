#include "device/devicesession.h"
#include "i18n/translators.h"
#include "language.h"
#include "mainwindow.h"
#include "sim/builtinsimulator.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QTextStream>

#include <memory>

using namespace stepcom;

namespace {

// The program's own options; texts are translated when the translators are installed first.
struct Options
{
    QCommandLineOption sim{
        QStringLiteral("sim"),
        QCoreApplication::translate("stepcom", "Start connected to the built-in simulator.")};
    QCommandLineOption port{
        QStringLiteral("port"),
        QCoreApplication::translate("stepcom", "Connect to this serial port at start."),
        QCoreApplication::translate("stepcom", "path")};
    QCommandLineOption tcp{
        QStringLiteral("tcp"),
        QCoreApplication::translate("stepcom", "Connect to this Modbus TCP gateway at start."),
        QCoreApplication::translate("stepcom", "host:port")};
    QCommandLineOption baud{QStringLiteral("baud"),
                            QCoreApplication::translate("stepcom", "Baud rate (default 9600)."),
                            QCoreApplication::translate("stepcom", "rate"), QStringLiteral("9600")};
    QCommandLineOption id{QStringLiteral("id"),
                          QCoreApplication::translate("stepcom", "Device id (default 1)."),
                          QCoreApplication::translate("stepcom", "id"), QStringLiteral("1")};

    void addTo(QCommandLineParser &parser) const
    {
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOption(Translators::languageOption());
        parser.addOptions({sim, port, tcp, baud, id});
    }
};

// --help, --version and a mistyped command line are answered in the terminal and need no
// display: deciding before QApplication exists keeps them working over ssh and in packaging
// checks (a QApplication without a display aborts).
bool answersWithoutWindow(const QStringList &arguments)
{
    QCommandLineParser probe;
    Options().addTo(probe);
    if (!probe.parse(arguments))
        return true;
    return probe.isSet(QStringLiteral("help")) || probe.isSet(QStringLiteral("help-all")) ||
           probe.isSet(QStringLiteral("version"));
}

} // namespace

int main(int argc, char *argv[])
{
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    const bool terminalOnly = answersWithoutWindow(arguments);
    std::unique_ptr<QCoreApplication> app;
    if (terminalOnly)
        app = std::make_unique<QCoreApplication>(argc, argv);
    else
        app = std::make_unique<QApplication>(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("StepCom"));
    QCoreApplication::setApplicationName(QStringLiteral("stepcom"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));
    if (!terminalOnly) {
        QGuiApplication::setApplicationDisplayName(QStringLiteral("StepCom"));
        // Matches the installed org.stepcom.StepCom.desktop (the window's icon and name on
        // Wayland).
        QGuiApplication::setDesktopFileName(QStringLiteral("org.stepcom.StepCom"));
        QGuiApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/stepcom.svg")));
    }

    // The language must be known before any translated text is built, help included.
    const QString language = Translators::languageFromArguments(arguments);
    if (!Translators::available().contains(language)) {
        QTextStream(stderr) << QStringLiteral("stepcom: ")
                            << Translators::unknownLanguageMessage(language) << Qt::endl;
        return 2;
    }
    Language::instance().setLanguage(language);

    QCommandLineParser parser;
    const Options options;
    options.addTo(parser);
    parser.setApplicationDescription(QCoreApplication::translate(
        "stepcom", "Commissioning window for a 2-axis stepper controller (Modbus RTU/TCP)."));
    parser.process(*app); // --help, --version and mistakes end here

    DeviceSession session;
    session.setSimulator(std::make_unique<BuiltinSimulator>()); // the Connection page offers it
    MainWindow window(&session);
    window.show();
    if (parser.isSet(options.sim)) {
        session.connectSimulator();
    } else if (parser.isSet(options.port) || parser.isSet(options.tcp)) {
        LinkSettings s;
        s.baud = parser.value(options.baud).toInt();
        s.deviceId = parser.value(options.id).toInt();
        if (parser.isSet(options.port)) {
            s.portName = parser.value(options.port);
        } else {
            s.transport = LinkSettings::Transport::Tcp;
            const QString value = parser.value(options.tcp);
            const qsizetype colon = value.lastIndexOf(QLatin1Char(':'));
            s.host = colon < 0 ? value : value.left(colon);
            s.tcpPort = colon < 0 ? 502 : value.mid(colon + 1).toInt();
        }
        session.connectTo(s); // a bad value is reported by the session, in the window
    }
    return QCoreApplication::exec();
}
