// stepcom-bench: the numbers of docs/performance.md, measured over real Modbus RTU against the
// simulator's wire-time model. `scripts/bench.sh` builds and runs it and updates the document.
#include "benchreport.h"
#include "benchrunner.h"
#include "busprobe.h"
#include "firststatusprobe.h"
#include "listenprobe.h"
#include "pendantprobe.h"
#include "replayprobe.h"
#include "replaywindowprobe.h"
#include "scanprobe.h"
#include "trafficprobe.h"
#include "windowprobe.h"

#include <QApplication>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QTextStream>

using namespace stepcom;
using namespace stepcom::bench;

int main(int argc, char *argv[])
{
    // (e) shows the Traffic dock's widgets: offscreen unless a display is asked for.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("stepcom-bench"));
    QCoreApplication::setApplicationVersion(QStringLiteral(STEPCOM_VERSION));
    QTextStream out(stdout);
    QTextStream err(stderr);

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Measures StepCom against the simulator's wire-time model at 9600, 19200 and 38400 "
        "baud: (a) the live status cycle, (b) read-all, (c) the emergency stop while polling at "
        "full rate, (d) the window's CPU and memory while polling at full rate, (e) the Traffic "
        "dock holding an hour of that polling, (f) the status of three controllers on one line "
        "in turn, (g) the E-STOP to every controller of a line of 2, 3 and 8, (h) a bus scan of "
        "ids 1-247 and 1-40 at "
        "9600 when nobody answers, (i) the status cycle and read-all on a controller that "
        "refuses reads covering reserved registers, (j) the time from the port opened to the "
        "first status, both at 9600, (k) (a) and (b) on a controller that answers in 2 ms at "
        "9600 and 38400, (l) opening and seeking a synthetic 1-hour session log at 10 Hz, (m) the "
        "same in the window's replay mode, (n) the phone pendant on loopback: press to jog frame, "
        "release to stop frame, last hold to stop frame, (o) listening beside a PLC: frames "
        "decoded per second and a frame's last byte to its decoded line. Prints a table "
        "with PASS/FAIL per target; exits 1 when a target is missed. See docs/performance.md."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOptions({
        {QStringLiteral("smoke"),
         QStringLiteral("One short round at 38400 baud; prints the table, judges nothing.")},
        {QStringLiteral("baud"), QStringLiteral("Measure only at this baud (repeatable)."),
         QStringLiteral("rate")},
        {QStringLiteral("cycles"), QStringLiteral("(a) status cycles to measure (default 50)."),
         QStringLiteral("n"), QStringLiteral("50")},
        {QStringLiteral("window-seconds"),
         QStringLiteral("(d) seconds to average the window's CPU over (default 10)."),
         QStringLiteral("s"), QStringLiteral("10")},
        {QStringLiteral("stepcom"),
         QStringLiteral("The window binary for (d) (default: next to this program)."),
         QStringLiteral("path")},
        {QStringLiteral("no-window"), QStringLiteral("Skip (d).")},
        {QStringLiteral("no-traffic"), QStringLiteral("Skip (e).")},
        {QStringLiteral("no-bus"), QStringLiteral("Skip (f) and (g).")},
        {QStringLiteral("no-scan"), QStringLiteral("Skip (h).")},
        {QStringLiteral("only-scan"), QStringLiteral("Run only (h), the bus scan.")},
        {QStringLiteral("no-replay"), QStringLiteral("Skip (l), the replay of an hour's log.")},
        {QStringLiteral("no-listen"), QStringLiteral("Skip (o), listening beside a PLC.")},
        {QStringLiteral("only-listen"), QStringLiteral("Run only (o), listening beside a PLC.")},
        {QStringLiteral("only-replay"),
         QStringLiteral("Run only (l) and (m): open a synthetic 1-hour log at 10 Hz, seek in it; "
                        "in the core, then in the window.")},
        {QStringLiteral("no-replay-window"),
         QStringLiteral("Skip (m), the replay of an hour's log in the window.")},
        {QStringLiteral("no-gaps"), QStringLiteral("Skip (i), the gap-refusing controller.")},
        {QStringLiteral("no-first-status"), QStringLiteral("Skip (j), the time to first status.")},
        {QStringLiteral("no-pendant"), QStringLiteral("Skip (n), the phone pendant's latencies.")},
        {QStringLiteral("no-fast"),
         QStringLiteral("Skip (k), (a) and (b) on a controller that answers in 2 ms.")},
        {QStringLiteral("traffic-seconds"),
         QStringLiteral(
             "(e) seconds of polling at full rate the Traffic dock holds (default 3600)."),
         QStringLiteral("s"), QStringLiteral("3600")},
        {QStringLiteral("update-doc"),
         QStringLiteral("Write the table between the bench markers of this Markdown file."),
         QStringLiteral("file")},
    });
    // (m) measures the window in a process of its own: this program, run again.
    QCommandLineOption replayChild(QStringLiteral("replay-window-child"),
                                   QStringLiteral("(m) the measured window."),
                                   QStringLiteral("log"));
    QCommandLineOption replaySeeks(QStringLiteral("replay-window-seeks"),
                                   QStringLiteral("(m) seeks to measure."), QStringLiteral("n"),
                                   QStringLiteral("20"));
    for (QCommandLineOption *o : {&replayChild, &replaySeeks}) {
        o->setFlags(QCommandLineOption::HiddenFromHelp);
        parser.addOption(*o);
    }
    parser.process(app);
    if (parser.isSet(replayChild))
        return runReplayWindowChild(parser.value(replayChild),
                                    std::max(1, parser.value(replaySeeks).toInt()));

    BenchConfig config;
    config.smoke = parser.isSet(QStringLiteral("smoke"));
    config.cycles = std::max(2, parser.value(QStringLiteral("cycles")).toInt());
    config.windowSeconds = std::max(1, parser.value(QStringLiteral("window-seconds")).toInt());
    config.traffic = !parser.isSet(QStringLiteral("no-traffic"));
    config.bus = !parser.isSet(QStringLiteral("no-bus"));
    config.trafficSeconds = std::max(1, parser.value(QStringLiteral("traffic-seconds")).toInt());
    config.gaps = !parser.isSet(QStringLiteral("no-gaps"));
    config.firstStatus = !parser.isSet(QStringLiteral("no-first-status"));
    QList<int> bauds{9600, 19200, 38400};
    if (config.smoke) {
        bauds = {38400};
        config.cycles = 5;
        config.readAlls = 1;
        config.estopRounds = 2;
        config.busRounds = 2;
        config.windowSeconds = 2;
        config.trafficSeconds = 60;
        config.firstStatusRuns = 2;
    }
    if (parser.isSet(QStringLiteral("baud"))) {
        bauds.clear();
        for (const QString &b : parser.values(QStringLiteral("baud")))
            bauds << b.toInt();
    }
    if (!parser.isSet(QStringLiteral("no-window"))) {
        config.stepcomPath =
            parser.isSet(QStringLiteral("stepcom"))
                ? parser.value(QStringLiteral("stepcom"))
                : QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("stepcom"));
    }

    QList<Verdict> rows;
    const bool onlyReplay = parser.isSet(QStringLiteral("only-replay"));
    const bool onlyListen = parser.isSet(QStringLiteral("only-listen"));
    if (parser.isSet(QStringLiteral("only-scan")) || onlyReplay || onlyListen) {
        bauds.clear();
        config.traffic = false;
        config.stepcomPath.clear();
        config.gaps = false;
        config.firstStatus = false;
    }
    int fastestBaud = 0;
    double fastestFrames = 0; // frames per second of the status poll at full rate
    for (const int baud : std::as_const(bauds)) {
        err << QStringLiteral("stepcom-bench: measuring at %1 baud ...").arg(baud) << Qt::endl;
        const BaudResult r = measureBaud(baud, config);
        rows += verdicts(r);
        if (config.bus) {
            err << QStringLiteral("stepcom-bench: several controllers at %1 baud ...").arg(baud)
                << Qt::endl;
            rows += busVerdicts(measureBus(baud, config));
        }
        if (r.error.isEmpty() && r.cycleMs.mean > 0) {
            const double frames = 2.0 * r.readsPerCycle * 1000.0 / r.cycleMs.mean;
            if (frames > fastestFrames) {
                fastestFrames = frames;
                fastestBaud = baud;
            }
        }
    }
    // (k) a controller that answers in 2 ms (fast firmware, pymodbus), at 9600 and 38400.
    if (!parser.isSet(QStringLiteral("no-fast"))) {
        for (const int baud : std::as_const(bauds)) {
            if (baud != 9600 && baud != 38400)
                continue;
            err << QStringLiteral("stepcom-bench: a controller answering in 2 ms at %1 baud ...")
                       .arg(baud)
                << Qt::endl;
            rows += answerTimeVerdicts(measureBaud(baud, config, 2, true));
        }
    }
    if (config.traffic && fastestFrames > 0) {
        err << QStringLiteral("stepcom-bench: the Traffic dock with %1 s at %2 baud ...")
                   .arg(config.trafficSeconds)
                   .arg(fastestBaud)
            << Qt::endl;
        rows +=
            trafficVerdicts(measureTrafficView(fastestBaud, fastestFrames, config.trafficSeconds));
    }
    if (!config.smoke && !config.stepcomPath.isEmpty()) {
        err << QStringLiteral("stepcom-bench: the window with its built-in simulator ...")
            << Qt::endl;
        rows += builtinWindowVerdicts(measureWindow(config, nullptr, 0));
    }

    // (i) and (j) at 9600, where a read costs most; a smoke run takes them at its own baud.
    const int startBaud = config.smoke ? 38400 : 9600;
    if (config.gaps) {
        err << QStringLiteral("stepcom-bench: a gap-refusing controller at %1 baud ...")
                   .arg(startBaud)
            << Qt::endl;
        rows += gapVerdicts(measureGapRefusing(startBaud, config));
    }
    if (config.firstStatus) {
        err << QStringLiteral("stepcom-bench: the first status after connecting at %1 baud ...")
                   .arg(startBaud)
            << Qt::endl;
        rows += firstStatusVerdicts(measureFirstStatus(startBaud, config.firstStatusRuns));
    }
    if (!parser.isSet(QStringLiteral("no-pendant")) && !onlyReplay && !onlyListen) {
        // Judged where the wire waits little (a frame waits for the one transaction in flight,
        // as the window's own buttons do): 38400 and a controller answering in 2 ms; the
        // manual's 35 ms at 9600 for information.
        const int rounds = config.smoke ? 3 : 20;
        err << QStringLiteral("stepcom-bench: the phone pendant at 38400 and 9600 baud ...")
            << Qt::endl;
        rows += pendantVerdicts(measurePendant(38400, rounds, 2), true);
        if (!config.smoke)
            rows += pendantVerdicts(measurePendant(9600, rounds, 35), false);
    }

    if (!parser.isSet(QStringLiteral("no-replay")) && !onlyListen) {
        err << QStringLiteral("stepcom-bench: replaying a synthetic session log ...") << Qt::endl;
        rows += replayVerdicts(config.smoke ? measureReplay(60, 10) : measureReplay(3600, 10));
        if (!parser.isSet(QStringLiteral("no-replay-window"))) {
            err << QStringLiteral("stepcom-bench: replaying it in the window ...") << Qt::endl;
            rows += replayWindowVerdicts(config.smoke ? measureReplayWindow(60, 10, 5)
                                                      : measureReplayWindow(3600, 10, 20));
        }
    }
    if (!parser.isSet(QStringLiteral("no-listen")) && !onlyReplay &&
        !parser.isSet(QStringLiteral("only-scan"))) {
        err << QStringLiteral("stepcom-bench: listening beside a PLC at 38400 ...") << Qt::endl;
        rows += listenVerdicts(config.smoke ? measureListen(10, 20) : measureListen(120, 200));
    }
    if (!parser.isSet(QStringLiteral("no-scan")) && !config.smoke && !onlyReplay && !onlyListen) {
        err << QStringLiteral("stepcom-bench: the bus scan of ids 1-247 and 1-40 at 9600 baud ...")
            << Qt::endl;
        rows += scanVerdicts(measureScan(9600));
        rows += scanVerdicts(measureScan(9600, 40));
    }

    const QString result =
        table(rows, !config.smoke) + QLatin1Char('\n') + machineLine() + QLatin1Char('\n');
    out << result << Qt::flush;
    if (parser.isSet(QStringLiteral("update-doc"))) {
        QString error;
        if (!replaceResults(parser.value(QStringLiteral("update-doc")), result, &error)) {
            err << QStringLiteral("stepcom-bench: %1").arg(error) << Qt::endl;
            return 2;
        }
    }
    const bool failed = std::any_of(rows.cbegin(), rows.cend(), [&](const Verdict &v) {
        // a smoke run fails only when something could not be measured at all
        return v.result == Verdict::Result::Error ||
               (!config.smoke && v.result == Verdict::Result::Fail);
    });
    return failed ? 1 : 0;
}
