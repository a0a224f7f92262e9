#include "base/language.h"
#include "i18n/translators.h"
#include "pages/connectionpage.h"
#include "pendant/pendantcontrol.h"
#include "pendant/pendantserver.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "sim/host/builtinsimulator.h"
#include "window/listenmode.h"
#include "window/mainwindow.h"
#include "window/pendantactions.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QIcon>
#include <QSettings>
#include <QStatusBar>
#include <QTextStream>

#include <memory>
#include <optional>

using namespace stepcom;

namespace {

// The program's own options; texts are translated when the translators are installed first.
struct Options
{
    QCommandLineOption sim{
        QStringLiteral("sim"),
        QCoreApplication::translate("stepcom", "Start connected to the built-in simulator.")};
    QCommandLineOption simReset{
        QStringLiteral("sim-reset"),
        QCoreApplication::translate("stepcom", "Start the built-in simulator from the factory "
                                               "again: forget what it saved to flash.")};
    QCommandLineOption machine{
        QStringLiteral("machine"),
        QCoreApplication::translate("stepcom", "With --sim: the simulated machine's mechanics "
                                               "from this machine file (stalls, backlash, "
                                               "switches; default: the setting "
                                               "simulator/machineFile)."),
        QCoreApplication::translate("stepcom", "file")};
    QCommandLineOption port{
        QStringLiteral("port"),
        QCoreApplication::translate("stepcom", "Connect to this serial port at start."),
        QCoreApplication::translate("stepcom", "path")};
    QCommandLineOption tcp{
        QStringLiteral("tcp"),
        QCoreApplication::translate("stepcom", "Connect to this Modbus TCP gateway at start."),
        QCoreApplication::translate("stepcom", "host:port")};
    QCommandLineOption rtuTcp{
        QStringLiteral("rtu-tcp"),
        QCoreApplication::translate("stepcom", "Connect at start to this RS-485/Ethernet "
                                               "converter in transparent mode (RTU over TCP)."),
        QCoreApplication::translate("stepcom", "host:port")};
    QCommandLineOption echo{
        QStringLiteral("echo"),
        QCoreApplication::translate("stepcom", "The adapter echoes what it sends.")};
    QCommandLineOption parity{
        QStringLiteral("parity"),
        QCoreApplication::translate("stepcom", "Parity: none, even or odd (default none)."),
        QCoreApplication::translate("stepcom", "parity"), QStringLiteral("none")};
    QCommandLineOption baud{QStringLiteral("baud"),
                            QCoreApplication::translate("stepcom", "Baud rate (default 9600)."),
                            QCoreApplication::translate("stepcom", "rate"), QStringLiteral("9600")};
    QCommandLineOption listen{
        QStringLiteral("listen"),
        QCoreApplication::translate("stepcom", "With --port: listen only, another master drives "
                                               "the line (nothing is sent but the E-STOP).")};
    QCommandLineOption id{QStringLiteral("id"),
                          QCoreApplication::translate("stepcom", "Device id (default 1)."),
                          QCoreApplication::translate("stepcom", "id"), QStringLiteral("1")};

    QCommandLineOption pendant{
        QStringLiteral("pendant"),
        QCoreApplication::translate("stepcom",
                                    "Start the phone pendant at launch (watch only) on this "
                                    "port, 0 for any free one; prints its address."),
        QCoreApplication::translate("stepcom", "[address:]port")};
    QCommandLineOption pendantJog{
        QStringLiteral("pendant-allow-jog"),
        QCoreApplication::translate("stepcom", "Allow jogging from the pendant from launch.")};

    void addTo(QCommandLineParser &parser) const
    {
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOption(Translators::languageOption());
        parser.addOptions({sim, simReset, machine, port, tcp, rtuTcp, baud, parity, id, echo,
                           pendant, pendantJog, listen});
        parser.addPositionalArgument(
            QStringLiteral("file"),
            QCoreApplication::translate("stepcom",
                                        "A profile to edit without a controller, or a session "
                                        "log or support bundle to replay."),
            QStringLiteral("[FILE]"));
    }
};

// The file to open at start (what a file manager's "Open with StepCom" gives), if any.
QString fileFromArguments(const QCommandLineParser &parser, QString *file)
{
    const auto tr = [](const char *text) { return QCoreApplication::translate("stepcom", text); };
    const QStringList files = parser.positionalArguments();
    if (files.isEmpty())
        return {};
    if (files.size() > 1)
        return tr("give one file at a time, not %1").arg(files.size());
    if (!QFileInfo::exists(files.first()))
        return tr("%1: no such file").arg(files.first());
    if (parser.isSet(QStringLiteral("sim")) || parser.isSet(QStringLiteral("port")) ||
        parser.isSet(QStringLiteral("tcp")) || parser.isSet(QStringLiteral("rtu-tcp")))
        return tr("a file is opened without a controller: give it without --sim, --port, --tcp "
                  "and --rtu-tcp");
    *file = files.first();
    return {};
}

QString linkFromArguments(const QCommandLineParser &parser, const Options &options,
                          std::optional<LinkSettings> *out)
{
    const auto tr = [](const char *text) { return QCoreApplication::translate("stepcom", text); };
    const int targets = int(parser.isSet(options.sim)) + int(parser.isSet(options.port)) +
                        int(parser.isSet(options.tcp)) + int(parser.isSet(options.rtuTcp));
    if (targets > 1)
        return tr("give only one of --sim, --port, --tcp and --rtu-tcp");
    LinkSettings s;
    if (parser.isSet(options.port)) {
        s.portName = parser.value(options.port);
    } else if (parser.isSet(options.tcp)) {
        s.transport = LinkSettings::Transport::Tcp;
        if (!LinkSettings::parseHostPort(parser.value(options.tcp), 502, &s.host, &s.tcpPort))
            return tr("--tcp: '%1' is not HOST[:PORT]").arg(parser.value(options.tcp));
    } else if (parser.isSet(options.rtuTcp)) {
        s.transport = LinkSettings::Transport::RtuTcp;
        if (!LinkSettings::parseHostPort(parser.value(options.rtuTcp), 0, &s.host, &s.tcpPort))
            return tr("--rtu-tcp: '%1' is not HOST:PORT").arg(parser.value(options.rtuTcp));
    } else {
        return {};
    }
    bool ok = false;
    s.baud = parser.value(options.baud).toInt(&ok);
    if (!ok)
        return tr("--baud: '%1' is not a number").arg(parser.value(options.baud));
    s.deviceId = parser.value(options.id).toInt(&ok);
    if (!ok)
        return tr("--id: '%1' is not a number").arg(parser.value(options.id));
    if (!LinkSettings::parseParity(parser.value(options.parity), &s.parity))
        return tr("--parity: '%1' is not none, even or odd").arg(parser.value(options.parity));
    s.echo = parser.isSet(options.echo);
    if (s.echo && s.transport == LinkSettings::Transport::Tcp)
        return tr("--echo: Modbus TCP has no echo; it applies to --port and --rtu-tcp");
    if (const QString problem = s.validate(); !problem.isEmpty())
        return problem;
    *out = s;
    return {};
}

// The pendant's [ADDRESS:]PORT, if --pendant was given; a message naming what was wrong.
QString pendantFromArguments(const QCommandLineParser &parser, const Options &options,
                             std::optional<std::pair<QHostAddress, quint16>> *out)
{
    const auto tr = [](const char *text) { return QCoreApplication::translate("stepcom", text); };
    if (!parser.isSet(options.pendant)) {
        if (parser.isSet(options.pendantJog))
            return tr("--pendant-allow-jog needs --pendant [ADDRESS:]PORT");
        return {};
    }
    QHostAddress address;
    quint16 port = 0;
    QString error;
    if (!PendantServer::parseListen(parser.value(options.pendant), &address, &port, &error))
        return QStringLiteral("--pendant: ") + error;
    *out = std::make_pair(address, port);
    return {};
}

// --help, --version, a mistyped command line and a bad link value are answered in the terminal and
// need no display: deciding before QApplication exists keeps them working over ssh and in packaging
// checks (a QApplication without a display aborts).
bool answersWithoutWindow(const QStringList &arguments)
{
    QCommandLineParser probe;
    const Options options;
    options.addTo(probe);
    if (!probe.parse(arguments))
        return true;
    std::optional<LinkSettings> link;
    QString file;
    std::optional<std::pair<QHostAddress, quint16>> pendant;
    return probe.isSet(QStringLiteral("help")) || probe.isSet(QStringLiteral("help-all")) ||
           probe.isSet(QStringLiteral("version")) ||
           !linkFromArguments(probe, options, &link).isEmpty() ||
           !fileFromArguments(probe, &file).isEmpty() ||
           !pendantFromArguments(probe, options, &pendant).isEmpty();
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

    // The link to open at start, if any; a mistyped value is answered in the terminal.
    std::optional<LinkSettings> startLink;
    if (const auto problem = linkFromArguments(parser, options, &startLink); !problem.isEmpty()) {
        QTextStream(stderr) << QStringLiteral("stepcom: ") << problem << Qt::endl;
        return 2;
    }
    QString startFile;
    if (const auto problem = fileFromArguments(parser, &startFile); !problem.isEmpty()) {
        QTextStream(stderr) << QStringLiteral("stepcom: ") << problem << Qt::endl;
        return 2;
    }

    if (parser.isSet(options.simReset)) {
        QString problem;
        if (!BuiltinSimulator::resetFlash(BuiltinSimulator::defaultFlashPath(), &problem)) {
            QTextStream(stderr) << QStringLiteral("stepcom: ") << problem << Qt::endl;
            return 1;
        }
    }
    std::optional<std::pair<QHostAddress, quint16>> pendant;
    if (const auto problem = pendantFromArguments(parser, options, &pendant); !problem.isEmpty()) {
        QTextStream(stderr) << QStringLiteral("stepcom: ") << problem << Qt::endl;
        return 2;
    }

    DeviceSession session;
    // The Connection page offers it; what it saves to flash is there again on the next start.
    auto sim = std::make_unique<BuiltinSimulator>();
    sim->setFlashPath(BuiltinSimulator::defaultFlashPath());
    const QString machineFile =
        parser.isSet(options.machine)
            ? parser.value(options.machine)
            : QSettings().value(BuiltinSimulator::machineFileSettingsKey()).toString();
    QString machineProblem;
    sim->setMachineFile(machineFile, &machineProblem);
    session.setSimulator(std::move(sim));
    MainWindow window(&session);
    window.showOnScreen();
    if (!machineProblem.isEmpty()) {
        // Said, and the simulator runs as the ideal machine.
        QTextStream(stderr) << QStringLiteral("stepcom: ") << machineProblem << Qt::endl;
        window.statusBar()->showMessage(machineProblem);
    }
    if (pendant) {
        PendantServer *server = window.pendantActions()->server();
        if (!server->start(pendant->first, pendant->second)) {
            QTextStream(stderr) << QStringLiteral("stepcom: ") << server->error() << Qt::endl;
            return 2;
        }
        server->control()->setAllowed(parser.isSet(options.pendantJog));
        // The address with the port actually bound (--pendant 127.0.0.1:0), for a script.
        QTextStream(stdout) << QStringLiteral("pendant: ") << server->url().toString() << Qt::endl;
    }
    QString why;
    if (parser.isSet(options.listen)) {
        // Beside a PLC: the port heard, never driven; a refusal is said in the window. The
        // Connection page shows the port heard.
        if (auto *page = window.findChild<ConnectionPage *>(); page && startLink)
            page->applySettings(*startLink);
        if (!startLink || !window.listenMode()->start(*startLink, &why))
            window.listenMode()->finished(
                false, why.isEmpty()
                           ? QCoreApplication::translate("stepcom", "--listen needs --port")
                           : why);
    } else if (parser.isSet(options.sim))
        session.connection()->connectSimulator();
    else if (startLink)
        session.connection()->connectTo(
            *startLink); // an unusable port is reported by the session, in the window
    else if (!startFile.isEmpty())
        window.openGivenFile(startFile); // what it is, or why not, is said in the window
    return QCoreApplication::exec();
}
