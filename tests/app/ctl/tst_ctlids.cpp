#include "programrun.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

// A controller's id and baud as stepcomctl gives them: saved to flash when asked (and said when
// not), the options for the next command, a converter's baud; the built-in simulator as faithful
// as stepcom-sim (silent at another id or baud, its flash kept between runs) and named on
// everything made of it; the computer's serial ports.
class TestCtlIds : public QObject
{
    Q_OBJECT
    QTemporaryDir m_home;

    // Every run in this suite's own data folder: the built-in simulator's flash lives there.
    ProgramRun ctl(const QStringList &args, const QStringList &environment = {})
    {
        ProgramOptions options;
        options.environment = QStringList{QStringLiteral("XDG_DATA_HOME=") +
                                          m_home.filePath(QStringLiteral("data"))} +
                              environment;
        return runProgram(QStringLiteral("stepcomctl"), args, options);
    }
    // The simulated controllers answer after 5 ms: a write's answer repeats the request, so with
    // the manual's 35 ms it would arrive too soon to be one.
    static QStringList rtu(const QString &path)
    {
        return {QStringLiteral("--port"),         path,
                QStringLiteral("--timeout"),      QStringLiteral("300"),
                QStringLiteral("--retries"),      QStringLiteral("1"),
                QStringLiteral("--answer-delay"), QStringLiteral("5")};
    }
    static bool start(SimHost &host, const SimOptions &options)
    {
        QString error;
        const bool ok = host.start(options, &error);
        if (!ok)
            qWarning("%s", qPrintable(error));
        return ok;
    }
    static SimOptions rtuOptions(const QString &statePath = {})
    {
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        o.statePath = statePath;
        return o;
    }
    static void powerCycle(SimDevice *device)
    {
        device->powerCycle(1);
        QTRY_VERIFY_WITH_TIMEOUT(!device->isPoweredOff(), 10000);
    }
    static void writeFile(const QString &path, const QByteArray &data)
    {
        QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }
    static void link(const QString &target, const QString &path)
    {
        QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
        QVERIFY2(QFile::link(target, path), qPrintable(path));
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_home.isValid()); }
    // Each test starts the built-in simulator from the factory.
    void init() { QDir(m_home.filePath(QStringLiteral("data"))).removeRecursively(); }

    // stepcom-sim on a pseudo-terminal, its flash in a file, switched off from its console.
    void assignIdSavedToFlashSurvivesAPowerCycle()
    {
        QProcess sim;
        sim.setProgram(programPath(QStringLiteral("stepcom-sim")));
        const QString line = m_home.filePath(QStringLiteral("line"));
        sim.setArguments({QStringLiteral("--link"), line, QStringLiteral("--state"),
                          m_home.filePath(QStringLiteral("flash.json")),
                          QStringLiteral("--answer-delay"), QStringLiteral("5"),
                          QStringLiteral("--console")});
        sim.start();
        QVERIFY(sim.waitForStarted(10000));
        QByteArray banner;
        while (!banner.contains("pty:") && sim.waitForReadyRead(10000))
            banner += sim.readAllStandardOutput();
        QVERIFY2(banner.contains("pty:"), banner.constData());

        ProgramRun r = ctl(rtu(line) + QStringList{"assign-id", "--to", "2", "--save-to-flash"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("saved to flash")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("next commands: stepcomctl --port %1 --baud 9600 "
                                               "--id 2")
                                    .arg(line)),
                 qPrintable(r.out));

        sim.write("power-cycle 0.3\n");
        QByteArray console;
        while (!console.contains("24 V off") && sim.waitForReadyRead(10000))
            console += sim.readAllStandardOutput();
        QVERIFY2(console.contains("24 V off"), console.constData());
        // While the power is off nothing answers; once back it answers at the id it saved.
        QTRY_VERIFY_WITH_TIMEOUT(
            (r = ctl(rtu(line) + QStringList{"--id", "2", "read", "device.id"})).exitCode == 0,
            30000);
        QVERIFY2(r.out.contains(QStringLiteral("device.id = 2")), qPrintable(r.out));
        sim.write("quit\n");
        QVERIFY(sim.waitForFinished(10000));
    }

    void assignIdWithoutSavingSaysTheIdIsLostAtPowerOff()
    {
        SimHost host;
        QVERIFY(start(host, rtuOptions()));
        const ProgramRun r = ctl(rtu(host.rtuPath()) + QStringList{"assign-id", "--to", "3"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("not saved to flash: lost at power-off\nid 3 lasts "
                                               "until the power is "
                                               "switched off")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("--save-to-flash")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("next commands: stepcomctl --port %1 --baud 9600 "
                                               "--id 3")
                                    .arg(host.rtuPath())),
                 qPrintable(r.out));
        QCOMPARE(host.device()->deviceId(), 3);
        powerCycle(host.device());
        QCOMPARE(host.device()->deviceId(), 1);
    }

    void writeIdAndBaudSaysWhatTheNextCommandNeeds()
    {
        SimHost host;
        QVERIFY(start(host, rtuOptions()));
        ProgramRun r =
            ctl(rtu(host.rtuPath()) + QStringList{"write", "device.id=7", "device.baud=19200"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("not saved to flash")), qPrintable(r.out));
        const QString next =
            QStringLiteral("next commands: stepcomctl --port %1 --baud 19200 --id 7")
                .arg(host.rtuPath());
        QVERIFY2(r.out.contains(next), qPrintable(r.out));

        // With --save-to-flash it is saved at the new id and baud, and stays after a power cycle.
        r = ctl(rtu(host.rtuPath()) + QStringList{"--id", "7", "--baud", "19200", "write",
                                                  "device.id=8", "--save-to-flash"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("saved to flash")), qPrintable(r.out));
        QVERIFY2(!r.out.contains(QStringLiteral("not saved to flash")), qPrintable(r.out));
        powerCycle(host.device());
        QCOMPARE(host.device()->deviceId(), 8);
        QCOMPARE(host.device()->baud(), 19200);
    }

    // apply --include-link moves the controller too: the next command is named.
    void applyWithTheLinkSaysWhatTheNextCommandNeeds()
    {
        SimHost host;
        QVERIFY(start(host, rtuOptions()));
        const QString path = m_home.filePath(QStringLiteral("with-link.json"));
        ProgramRun r = ctl(rtu(host.rtuPath()) + QStringList{"dump", path, "--include-link"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject top = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QJsonObject values = top.value("values").toObject();
        values.insert("device.id", 4);
        top.insert("values", values);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QJsonDocument(top).toJson());
        f.close();
        r = ctl(rtu(host.rtuPath()) + QStringList{"apply", path, "--include-link", "--yes"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("next commands: stepcomctl --port %1 --baud 9600 "
                                               "--id 4")
                                    .arg(host.rtuPath())),
                 qPrintable(r.out));
        QCOMPARE(host.device()->deviceId(), 4);
    }

    // The next failure names the command that finds a controller.
    void noAnswerNamesTheScanCommand()
    {
        SimHost host;
        QVERIFY(start(host, rtuOptions()));
        const ProgramRun r =
            ctl(rtu(host.rtuPath()) + QStringList{"--id", "9", "read", "device.id"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("stepcomctl scan")), qPrintable(r.err));
    }

    void aGatewaysBaudIsNamed()
    {
        SimHost host;
        SimOptions o;
        o.tcp = true;
        QVERIFY(start(host, o));
        const ProgramRun r = ctl({"--tcp", QStringLiteral("127.0.0.1:%1").arg(host.tcpPort()),
                                  "write", "device.baud=19200"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("set the converter's (gateway's) serial side to "
                                               "19200 baud too")),
                 qPrintable(r.out));
        QVERIFY2(
            r.out.contains(QStringLiteral("next commands: stepcomctl --tcp 127.0.0.1:%1 --id 1")
                               .arg(host.tcpPort())),
            qPrintable(r.out));
    }

    // As a real controller: nobody answers at another id or baud.
    void theBuiltinSimulatorIsSilentAtAnotherIdOrBaud_data()
    {
        QTest::addColumn<QStringList>("link");
        QTest::newRow("id 42") << QStringList{"--id", "42"};
        QTest::newRow("19200 baud") << QStringList{"--baud", "19200"};
    }
    void theBuiltinSimulatorIsSilentAtAnotherIdOrBaud()
    {
        QFETCH(QStringList, link);
        const QStringList quick{"--sim", "--timeout", "200", "--retries", "0"};
        ProgramRun r = ctl(quick + link + QStringList{"read", "device.id"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(!r.out.contains(QStringLiteral("device.id =")), qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("no answer")), qPrintable(r.err));
        r = ctl(quick + QStringList{"read", "device.id"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("device.id = 1")), qPrintable(r.out));
    }

    // What it saved is there on the next run, as after a power cycle; --sim-reset forgets it.
    void theBuiltinSimulatorKeepsItsFlashBetweenRuns()
    {
        ProgramRun r =
            ctl({"--sim", "write", "motor1.speed=450", "device.id=5", "--save-to-flash"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(
            r.out.contains(QStringLiteral("next commands: stepcomctl --sim --baud 9600 --id 5")),
            qPrintable(r.out));
        r = ctl({"--sim", "--id", "5", "read", "motor1.speed", "device.id"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("motor1.speed = 450")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("device.id = 5")), qPrintable(r.out));
        // Written but not saved: gone on the next run.
        r = ctl({"--sim", "--id", "5", "write", "motor1.speed=300"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = ctl({"--sim", "--id", "5", "read", "motor1.speed"});
        QVERIFY2(r.out.contains(QStringLiteral("motor1.speed = 450")), qPrintable(r.out));

        r = ctl({"--sim-reset"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = ctl({"--sim", "read", "motor1.speed", "device.id"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("device.id = 1")), qPrintable(r.out));
        QVERIFY2(!r.out.contains(QStringLiteral("motor1.speed = 450")), qPrintable(r.out));
    }

    // The guide's practice for a forgotten id and baud, on the built-in simulator.
    void theScanFindsTheBuiltinSimulatorsSavedIdAndBaud()
    {
        ProgramRun r =
            ctl({"--sim", "write", "device.id=7", "device.baud=19200", "--save-to-flash"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = ctl({"--sim", "--timeout", "200", "--retries", "0", "read", "device.id"});
        QCOMPARE(r.exitCode, 1);
        r = ctl({"--sim", "scan", "--ids", "6-8", "--bauds", "9600,19200", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray found =
            QJsonDocument::fromJson(r.out.toUtf8()).object().value("result").toArray();
        QCOMPARE(found.size(), 1);
        QCOMPARE(found.at(0).toObject().value("id").toInt(), 7);
        QCOMPARE(found.at(0).toObject().value("baud").toInt(), 19200);
        r = ctl({"--sim", "--id", "7", "--baud", "19200", "read", "device.id"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("device.id = 7")), qPrintable(r.out));
    }

    void whatIsMadeOfTheSimulatorSaysSo()
    {
        const QString report = m_home.filePath(QStringLiteral("sim-report.html"));
        const QString profile = m_home.filePath(QStringLiteral("sim-profile.json"));
        const QString log = m_home.filePath(QStringLiteral("sim.log"));
        ProgramRun r = ctl({"--sim", "--log", log, "report", report});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile html(report);
        QVERIFY(html.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(html.readAll());
        QVERIFY2(text.contains(QStringLiteral("SIMULATOR -- NOT A MACHINE")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("<title>Commissioning report -- simulator, not a "
                                             "machine</title>")));
        // Above the signatures too.
        QVERIFY(text.contains(QStringLiteral("nothing here can be signed for a machine")));

        r = ctl({"--sim", "dump", profile});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile json(profile);
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonObject metadata =
            QJsonDocument::fromJson(json.readAll()).object().value("metadata").toObject();
        QCOMPARE(metadata.value("source").toString(), QStringLiteral("simulator"));
        // A report of that profile, with no controller, still says it.
        const QString fromFile = m_home.filePath(QStringLiteral("from-profile.html"));
        r = ctl({"report", fromFile, "--from", profile});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile second(fromFile);
        QVERIFY(second.open(QIODevice::ReadOnly));
        QVERIFY(second.readAll().contains("SIMULATOR -- NOT A MACHINE"));

        QFile logFile(log);
        QVERIFY(logFile.open(QIODevice::ReadOnly));
        const QByteArray logText = logFile.readAll();
        QVERIFY2(logText.contains("simulator=built-in"), logText.left(800).constData());
    }

    // A report of a machine never says simulator.
    void aMachinesReportDoesNotSayTheSimulator()
    {
        SimHost host;
        QVERIFY(start(host, rtuOptions()));
        const QString report = m_home.filePath(QStringLiteral("machine.html"));
        const ProgramRun r = ctl(rtu(host.rtuPath()) + QStringList{"report", report});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile html(report);
        QVERIFY(html.open(QIODevice::ReadOnly));
        QVERIFY(!html.readAll().contains("SIMULATOR"));
    }

    // A fake system: an FTDI adapter held by minicom's lock file, a CH340 opened by picocom
    // under a lock file as Qt writes it (the pid, the program, the host).
    void portsListsAdaptersAndWhoHoldsThem()
    {
        const QString root = m_home.filePath(QStringLiteral("system"));
        QDir(root).removeRecursively();
        const QString usb = root + QStringLiteral("/sys/devices/pci0000:00/usb1");
        for (const auto &[tty, dev, vendor, product, maker, name, serial] :
             {std::tuple{"ttyUSB0", "1-1", "0403", "6001", "FTDI", "FT232R USB UART", "A10K3B5Q"},
              std::tuple{"ttyUSB1", "1-2", "1a86", "7523", "", "USB Serial", ""}}) {
            const QString device = QStringLiteral("%1/%2").arg(usb, QLatin1String(dev));
            writeFile(device + "/idVendor", vendor);
            writeFile(device + "/idProduct", product);
            if (*maker)
                writeFile(device + "/manufacturer", maker);
            writeFile(device + "/product", name);
            if (*serial)
                writeFile(device + "/serial", serial);
            const QString port = device + QStringLiteral("/%1:1.0/%2").arg(dev, tty);
            QVERIFY(QDir().mkpath(port));
            link(port, root + QStringLiteral("/sys/class/tty/%1/device").arg(tty));
            writeFile(root + QStringLiteral("/dev/%1").arg(tty), {});
        }
        QVERIFY(QDir().mkpath(root + "/sys/class/tty/tty0")); // a console: no device, left out
        link("../../ttyUSB0",
             root + "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A10K3B5Q-if00-port0");
        writeFile(root + "/run/lock/LCK..ttyUSB0", "   4194301\n");
        writeFile(root + "/proc/4194301/comm", "minicom\n");
        QVERIFY(QDir().mkpath(root + "/proc/4194301/fd"));
        writeFile(root + "/proc/4194302/comm", "picocom\n");
        link("/dev/ttyUSB1", root + "/proc/4194302/fd/3");
        writeFile(root + "/var/lock/LCK..ttyUSB1", "4194302\npicocom\nbench\n");

        const QStringList env{QStringLiteral("STEPCOMCTL_SYSTEM_ROOT=") + root};
        ProgramRun r = ctl({"ports", "--json"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray ports =
            QJsonDocument::fromJson(r.out.toUtf8()).object().value("result").toArray();
        QCOMPARE(ports.size(), 2);
        const QJsonObject ftdi = ports.at(0).toObject();
        QCOMPARE(ftdi.value("path").toString(), QStringLiteral("/dev/ttyUSB0"));
        QCOMPARE(ftdi.value("by_id").toString(),
                 QStringLiteral("/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A10K3B5Q-if00-port0"));
        QCOMPARE(ftdi.value("vendor").toString(), QStringLiteral("FTDI"));
        QCOMPARE(ftdi.value("product").toString(), QStringLiteral("FT232R USB UART"));
        QCOMPARE(ftdi.value("serial_number").toString(), QStringLiteral("A10K3B5Q"));
        QCOMPARE(ftdi.value("vendor_id").toString(), QStringLiteral("0403"));
        QCOMPARE(ftdi.value("held").toBool(), true);
        const QJsonObject holder = ftdi.value("holders").toArray().at(0).toObject();
        QCOMPARE(holder.value("program").toString(), QStringLiteral("minicom"));
        QCOMPARE(holder.value("pid").toInteger(), 4194301);
        QCOMPARE(holder.value("how").toString(),
                 QStringLiteral("lock file /run/lock/LCK..ttyUSB0"));
        const QJsonObject ch340 = ports.at(1).toObject();
        QCOMPARE(ch340.value("path").toString(), QStringLiteral("/dev/ttyUSB1"));
        QVERIFY(ch340.value("by_id").isNull());
        QCOMPARE(ch340.value("product_id").toString(), QStringLiteral("7523"));
        const QJsonArray ch340Holders = ch340.value("holders").toArray();
        QCOMPARE(ch340Holders.size(), 1);
        QCOMPARE(ch340Holders.at(0).toObject().value("program").toString(),
                 QStringLiteral("picocom"));
        QCOMPARE(ch340Holders.at(0).toObject().value("how").toString(),
                 QStringLiteral("lock file /var/lock/LCK..ttyUSB1, has it open"));

        // A stale lock (its process is gone) holds nothing.
        QVERIFY(QDir(root + "/proc/4194301").removeRecursively());
        r = ctl({"ports"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("/dev/ttyUSB0  FTDI, FT232R USB UART, 0403:6001, "
                                               "S/N A10K3B5Q  free")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("held by picocom (pid 4194302, lock file "
                                               "/var/lock/LCK..ttyUSB1, has it open)")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("open it with: stepcomctl --port "
                                               "/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_"
                                               "A10K3B5Q-if00-port0")),
                 qPrintable(r.out));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlIds, Guiless)
#include "tst_ctlids.moc"
