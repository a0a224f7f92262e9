#include "device/devicesession.h"
#include "i18n/translators.h"
#include "language.h"
#include "mainwindow.h"
#include "sim/builtinsimulator.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QTextStream>

using namespace stepcom;

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("StepCom"));
    QApplication::setApplicationName(QStringLiteral("stepcom"));
    QApplication::setApplicationDisplayName(QStringLiteral("StepCom"));
    QApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));

    // Matches the installed org.stepcom.StepCom.desktop (the window's icon and name on Wayland).
    QGuiApplication::setDesktopFileName(QStringLiteral("org.stepcom.StepCom"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/stepcom.svg")));

    // The language must be known before any translated text is built, help included.
    const QString language = Translators::languageFromArguments(QApplication::arguments());
    if (!Translators::available().contains(language)) {
        QTextStream(stderr) << QStringLiteral("stepcom: ")
                            << Translators::unknownLanguageMessage(language) << Qt::endl;
        return 2;
    }
    Language::instance().setLanguage(language);

    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption(Translators::languageOption());
    parser.setApplicationDescription(QApplication::translate(
        "stepcom", "Commissioning window for a 2-axis stepper controller (Modbus RTU/TCP)."));
    const QCommandLineOption simOption(
        QStringLiteral("sim"),
        QApplication::translate("stepcom", "Start connected to the built-in simulator."));
    const QCommandLineOption portOption(
        QStringLiteral("port"),
        QApplication::translate("stepcom", "Connect to this serial port at start."),
        QApplication::translate("stepcom", "path"));
    const QCommandLineOption tcpOption(
        QStringLiteral("tcp"),
        QApplication::translate("stepcom", "Connect to this Modbus TCP gateway at start."),
        QApplication::translate("stepcom", "host:port"));
    const QCommandLineOption baudOption(
        QStringLiteral("baud"), QApplication::translate("stepcom", "Baud rate (default 9600)."),
        QApplication::translate("stepcom", "rate"), QStringLiteral("9600"));
    const QCommandLineOption idOption(
        QStringLiteral("id"), QApplication::translate("stepcom", "Device id (default 1)."),
        QApplication::translate("stepcom", "id"), QStringLiteral("1"));
    parser.addOptions({simOption, portOption, tcpOption, baudOption, idOption});
    parser.process(app);

    DeviceSession session;
    session.setSimulator(std::make_unique<BuiltinSimulator>()); // the Connection page offers it
    MainWindow window(&session);
    window.show();
    if (parser.isSet(simOption)) {
        session.connectSimulator();
    } else if (parser.isSet(portOption) || parser.isSet(tcpOption)) {
        LinkSettings s;
        s.baud = parser.value(baudOption).toInt();
        s.deviceId = parser.value(idOption).toInt();
        if (parser.isSet(portOption)) {
            s.portName = parser.value(portOption);
        } else {
            s.transport = LinkSettings::Transport::Tcp;
            const QString value = parser.value(tcpOption);
            const qsizetype colon = value.lastIndexOf(QLatin1Char(':'));
            s.host = colon < 0 ? value : value.left(colon);
            s.tcpPort = colon < 0 ? 502 : value.mid(colon + 1).toInt();
        }
        session.connectTo(s); // a bad value is reported by the session, in the window
    }
    return app.exec();
}
