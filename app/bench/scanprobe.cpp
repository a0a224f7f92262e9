#include "scanprobe.h"

#include "benchrunner.h"

#include "line/busscanner.h"
#include "sim/host/simhost.h"

#include <QElapsedTimer>

namespace stepcom::bench {

ScanResult measureScan(int baud, int ids)
{
    ScanResult r;
    r.baud = baud;
    r.ids = ids;
    SimHost sim;
    SimOptions o;
    o.rtu = true;
    o.ids = {250}; // outside 1-247: every probe is a silent one
    o.wireBaud = baud;
    QString error;
    if (!sim.start(o, &error)) {
        r.error = error;
        return r;
    }
    BusScanner::Plan plan;
    plan.base.portName = sim.rtuPath();
    plan.bauds = {baud};
    for (int id = 1; id <= r.ids; ++id)
        plan.ids << id;
    LinkSettings line = plan.base;
    line.baud = baud;
    r.probeTimeoutMs = BusScanner::probeTimeoutMs(line, 0);
    // 10 bits a character: the 8-byte request, the 35 ms answer delay, the 7-byte answer.
    r.limitMs = r.ids * ((8 + 7) * 10000.0 / baud + line.answerDelayMs);
    BusScanner scanner;
    bool finished = false;
    QObject::connect(&scanner, &BusScanner::finished, &scanner, [&](bool, const QString &why) {
        finished = true;
        r.error = why;
    });
    QElapsedTimer clock;
    clock.start();
    scanner.start(plan);
    if (!waitUntil([&] { return finished; }, 120000))
        r.error = QStringLiteral("the scan did not end within 120 s");
    r.elapsedMs = double(clock.nsecsElapsed()) / 1e6;
    r.found = int(scanner.found().size());
    r.measured = r.error.isEmpty();
    return r;
}

} // namespace stepcom::bench
