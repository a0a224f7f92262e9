// stepcom-sim: the simulated controller as a program of its own.
#include "consolereader.h"
#include "i18n/translators.h"
#include "session/idlist.h"
#include "signalwatcher.h"
#include "sim/host/simcommandline.h"
#include "sim/host/simconsole.h"
#include "sim/host/simhost.h"
#include "sim/host/truthwriter.h"
#include "sim/model/simdevice.h"
#include "sim/serve/linehub.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

#include <memory>

using namespace stepcom;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stepcom-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));
    QTextStream out(stdout);
    QTextStream err(stderr);

    // The language first: the help and every message are translated when they are built.
    Translators translators;
    const QString language = Translators::languageFromArguments(QCoreApplication::arguments());
    if (!Translators::available().contains(language)) {
        err << QStringLiteral("stepcom-sim: ") << Translators::unknownLanguageMessage(language)
            << Qt::endl;
        return 2;
    }
    translators.install(language);

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "stepcom-sim",
        "A simulated 2-axis stepper controller speaking Modbus RTU on a pseudo-terminal "
        "and/or Modbus TCP. Without --pty or --tcp it serves a pseudo-terminal."));
    parser.addHelpOption();
    parser.addVersionOption();
    SimCommandLine::addOptions(parser);
    const QCommandLineOption consoleOption(
        QStringLiteral("console"),
        QCoreApplication::translate(
            "stepcom-sim",
            "Read console commands from standard input even when it is not a terminal."));
    parser.addOption(consoleOption);
    parser.addOption(Translators::languageOption());
    parser.process(app);

    SimOptions options;
    QString error;
    if (!SimCommandLine::toOptions(parser, &options, &error)) {
        err << QCoreApplication::translate("stepcom-sim", "stepcom-sim: %1").arg(error) << Qt::endl;
        return 2;
    }
    if (!options.rtu && !options.tcp && !options.rtuTcp && options.serialPort.isEmpty())
        options.rtu = true;

    // Before anything is opened, so Ctrl-C during start-up still ends cleanly.
    SignalWatcher watcher;
    QObject::connect(&watcher, &SignalWatcher::terminationRequested, &app, &QCoreApplication::quit);

    // --line N: the controller's pty is one party of the line; the N ptys are the programs'.
    const QString lineLink =
        options.line > 0 ? std::exchange(options.linkPath, QString()) : QString();
    SimHost host;
    LineHub hub;
    QObject::connect(&host, &SimHost::message, &app,
                     [&err](const QString &text) { err << text << Qt::endl; });
    QObject::connect(&host, &SimHost::hungUp, &app, [&out] {
        out << QCoreApplication::translate("stepcom-sim", "port hung up") << Qt::endl;
    });
    QObject::connect(&host, &SimHost::reopened, &app, [&](const QString &path) {
        if (hub.isOpen()) {
            QString attachError;
            if (!hub.reattach(path, &attachError))
                err << attachError << Qt::endl;
            return; // the line's ptys stay as they were
        }
        out << QCoreApplication::translate("stepcom-sim", "port back: %1").arg(path) << Qt::endl;
    });
    if (!host.start(options, &error)) {
        err << QCoreApplication::translate("stepcom-sim", "stepcom-sim: %1").arg(error) << Qt::endl;
        return 1;
    }
    SimDevice *device = host.device();
    out << QCoreApplication::translate("stepcom-sim",
                                       "stepcom-sim %1: device id %2, %3 baud, %4 motors")
               .arg(QStringLiteral(STEPCOM_VERSION))
               .arg(device->deviceId())
               .arg(device->baud())
               .arg(device->motorCount())
        << Qt::endl;
    if (host.devices().size() > 1) {
        QList<int> ids;
        for (const SimDevice *d : host.devices())
            ids << d->deviceId();
        out << QCoreApplication::translate(
                   "stepcom-sim", "%1 controllers on the line, ids %2 (the console acts on "
                                  "the first)")
                   .arg(ids.size())
                   .arg(IdList::format(ids))
            << Qt::endl;
    }
    if (options.line > 0) {
        if (!hub.open(options.line, &error) || !hub.attach(host.ptyPath(), &error)) {
            err << QCoreApplication::translate("stepcom-sim", "stepcom-sim: %1").arg(error)
                << Qt::endl;
            host.stop();
            return 1;
        }
        for (const int party : std::as_const(options.lineEcho))
            hub.setEcho(party - 1, true);
        const QStringList paths = hub.paths();
        for (int i = 0; i < paths.size(); ++i) {
            out << QStringLiteral("line %1: %2%3")
                       .arg(i + 1)
                       .arg(paths.at(i), options.lineEcho.contains(i + 1)
                                             ? QStringLiteral(" (echo)")
                                             : QString())
                << Qt::endl;
            const QString link = QStringLiteral("%1.%2").arg(lineLink).arg(i + 1);
            if (!lineLink.isEmpty() && !hub.createLink(i, link, &error)) {
                err << QCoreApplication::translate("stepcom-sim", "stepcom-sim: %1").arg(error)
                    << Qt::endl;
                host.stop();
                return 1;
            }
            if (!lineLink.isEmpty())
                out << QStringLiteral("link %1: %2").arg(i + 1).arg(link) << Qt::endl;
        }
    } else if (options.rtu) {
        out << QStringLiteral("pty: %1").arg(host.ptyPath()) << Qt::endl;
        if (!options.linkPath.isEmpty())
            out << QStringLiteral("link: %1").arg(options.linkPath) << Qt::endl;
    }
    if (!options.serialPort.isEmpty())
        out << QStringLiteral("serial: %1").arg(options.serialPort) << Qt::endl;
    if (options.tcp)
        out << QStringLiteral("tcp: %1:%2").arg(host.tcpAddress().toString()).arg(host.tcpPort())
            << Qt::endl;
    if (options.rtuTcp)
        out << QStringLiteral("rtu-tcp: %1:%2")
                   .arg(host.tcpAddress().toString())
                   .arg(host.rtuTcpPort())
            << Qt::endl;

    std::unique_ptr<TruthWriter> truth;
    if (!options.truthOut.isEmpty()) {
        truth = std::make_unique<TruthWriter>(device, options.truthOut);
        QObject::connect(truth.get(), &TruthWriter::failed, &app,
                         [&err](const QString &why) { err << why << Qt::endl; });
        if (!truth->start(&error)) {
            err << QCoreApplication::translate("stepcom-sim", "stepcom-sim: %1").arg(error)
                << Qt::endl;
            host.stop();
            return 1;
        }
        out << QStringLiteral("truth: %1").arg(options.truthOut) << Qt::endl;
    }

    SimConsole console(&host);
    ConsoleReader *reader = nullptr;
    if (parser.isSet(consoleOption) || ConsoleReader::stdinIsTerminal()) {
        reader = new ConsoleReader(&app);
        out << QCoreApplication::translate("stepcom-sim", "type 'help' for the console commands")
            << Qt::endl;
        QObject::connect(reader, &ConsoleReader::lineRead, &app, [&](const QString &line) {
            const SimConsole::Result r = console.execute(line);
            if (!r.text.isEmpty())
                (r.ok ? out : err) << r.text << Qt::endl;
            if (r.quit)
                QCoreApplication::quit();
        });
    }
    const int rc = app.exec();
    if (hub.isOpen()) {
        // What each program sent onto the line: a listener's count proves it sent nothing.
        for (int i = 0; i < hub.paths().size(); ++i)
            err << QCoreApplication::translate("stepcom-sim", "line %1 sent %2 bytes")
                       .arg(i + 1)
                       .arg(hub.bytesSent(i))
                << Qt::endl;
        hub.close();
    }
    if (truth && !truth->flush(&error))
        err << error << Qt::endl;
    host.stop();
    return rc;
}
