#include "firststatusprobe.h"

#include "benchrunner.h"

#include "bus/modbuslink.h"
#include "device/poller.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h" // requests are watched on the link
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QElapsedTimer>

namespace stepcom::bench {

FirstStatusResult measureFirstStatus(int baud, int runs)
{
    FirstStatusResult r;
    r.baud = baud;
    const RegisterMap &map = RegisterMap::builtin();
    SimHost host;
    SimOptions options;
    options.map = map;
    options.rtu = true;
    options.wireBaud = baud;
    QString error;
    if (!host.start(options, &error)) {
        r.error = error;
        return r;
    }
    host.device()->setValue(QStringLiteral("device.baud"), baud);
    QStringList positions; // what "positions shown" needs in the store
    for (const QString &key : Poller::statusKeys(map))
        if (key.endsWith(QLatin1String(".position")))
            positions << key;

    for (int run = 0; run < runs; ++run) {
        DeviceSession session(map); // fresh, as at start: the window's defaults
        QElapsedTimer clock;
        bool opened = false;
        bool shown = false;
        double ms = 0;
        QObject::connect(session.connection(), &SessionConnection::connected, &session,
                         [&](bool ok) {
                             if (ok && !opened) {
                                 clock.start();
                                 opened = true;
                             }
                         });
        QObject::connect(
            session.status(), &SessionStatus::statusCycleFinished, &session, [&](bool ok) {
                if (!ok || !opened || shown)
                    return;
                const ParameterStore *store = session.parameters()->store();
                shown =
                    std::all_of(positions.cbegin(), positions.cend(), [store](const QString &k) {
                        return store->deviceValue(k).has_value();
                    });
                if (shown)
                    ms = double(clock.nsecsElapsed()) / 1e6;
            });
        // The read-all must come after the first status, not before it.
        QObject::connect(SessionInternals::link(session), &ModbusLink::dispatched, &session,
                         [&](quint64, const Request &req) {
                             if (!shown && req.priority == Priority::Read)
                                 r.beforeReadAll = false;
                         });
        LinkSettings settings;
        settings.portName = host.rtuPath();
        settings.baud = baud;
        session.connection()->connectTo(settings);
        if (!waitUntil([&shown] { return shown; }, 5000)) {
            r.error = QStringLiteral("(j): no status with positions within 5 s of connecting "
                                     "(run %1)")
                          .arg(run + 1);
            return r;
        }
        r.ms.add(ms);
        session.connection()->disconnectFrom();
        waitUntil([] { return false; }, 300); // the simulator's last answer drains
    }
    return r;
}

} // namespace stepcom::bench
