#include "i18n/translators.h"
#include "language.h"
#include "listenmode.h"
#include "mainwindow.h"
#include "pages/connectionpage.h"
#include "session/devicesession.h"
#include "sim/builtinsimulator.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
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

    void addTo(QCommandLineParser &parser) const
    {
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOption(Translators::languageOption());
        parser.addOptions({sim, port, tcp, rtuTcp, baud, parity, id, echo, listen});
    }
};

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
    return probe.isSet(QStringLiteral("help")) || probe.isSet(QStringLiteral("help-all")) ||
           probe.isSet(QStringLiteral("version")) ||
           !linkFromArguments(probe, options, &link).isEmpty();
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

    DeviceSession session;
    session.setSimulator(std::make_unique<BuiltinSimulator>()); // the Connection page offers it
    MainWindow window(&session);
    window.showOnScreen();
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
        session.connectSimulator();
    else if (startLink)
        session.connectTo(*startLink); // an unusable port is reported by the session, in the window
    return QCoreApplication::exec();
}
