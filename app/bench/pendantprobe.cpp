#include "pendantprobe.h"

#include "benchrunner.h"

#include "bus/modbuslink.h"
#include "pendant/pendantcontrol.h"
#include "pendant/pendantserver.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/sessioninternals.h" // frames are watched on the link
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QWebSocket>

#include <algorithm>

namespace stepcom::bench {

namespace {

void say(QWebSocket &socket, const char *type, const char *dir = nullptr)
{
    QJsonObject m{{QStringLiteral("t"), QLatin1String(type)}, {QStringLiteral("motor"), 1}};
    if (dir)
        m.insert(QStringLiteral("dir"), QLatin1String(dir));
    socket.sendTextMessage(QString::fromUtf8(QJsonDocument(m).toJson(QJsonDocument::Compact)));
    socket.flush();
}

} // namespace

PendantResult measurePendant(int baud, int rounds, int answerDelayMs)
{
    PendantResult r;
    r.baud = baud;
    r.answerDelayMs = answerDelayMs;
    SimHost host;
    SimOptions options;
    options.map = RegisterMap::builtin();
    options.rtu = true;
    options.wireBaud = baud;
    options.answerDelayMs = answerDelayMs;
    QString error;
    if (!host.start(options, &error)) {
        r.error = error;
        return r;
    }
    host.device()->setValue(QStringLiteral("device.baud"), baud);
    DeviceSession session;
    LinkSettings settings;
    settings.portName = host.rtuPath();
    settings.baud = baud;
    session.connection()->connectTo(settings);
    if (!waitUntil([&session] { return session.connection()->isConnected(); }, 5000)) {
        r.error = QStringLiteral("(n): the simulator did not answer");
        return r;
    }
    PendantServer server(&session);
    if (!server.start(QHostAddress::LocalHost, 0)) {
        r.error = server.error();
        return r;
    }
    server.control()->setAllowed(true);
    QElapsedTimer clock;
    clock.start();
    qint64 jogFrame = -1;
    qint64 stopFrame = -1;
    QObject::connect(SessionInternals::link(session), &ModbusLink::dispatched, &session,
                     [&](quint64, const Request &req) {
                         if (req.what == QLatin1String("motor1.forward"))
                             jogFrame = clock.nsecsElapsed();
                         else if (req.what == QLatin1String("motor1.stop"))
                             stopFrame = clock.nsecsElapsed();
                     });
    QWebSocket phone;
    QUrl url = server.url();
    url.setScheme(QStringLiteral("ws"));
    url.setPath(url.path() + QStringLiteral("/ws"));
    phone.open(url);
    if (!waitUntil([&phone] { return phone.state() == QAbstractSocket::ConnectedState; }, 5000)) {
        r.error = QStringLiteral("(n): the WebSocket did not open");
        return r;
    }
    say(phone, "take");
    if (!waitUntil([&server] { return server.control()->holder() != 0; }, 5000)) {
        r.error = QStringLiteral("(n): no control");
        return r;
    }
    const auto ms = [](qint64 from, qint64 to) { return double(to - from) / 1e6; };
    for (int round = 0; round < rounds * 2; ++round) {
        const bool byWatchdog = round % 2 == 1;
        // Idle again (the last stop read back) before the next press.
        if (!waitUntil([&session] { return !session.jog()->isBusy(); }, 5000)) {
            r.error = QStringLiteral("(n): the last jog did not settle");
            return r;
        }
        jogFrame = stopFrame = -1;
        const qint64 pressed = clock.nsecsElapsed();
        say(phone, "jog", "fwd");
        if (!waitUntil([&jogFrame] { return jogFrame >= 0; }, 5000)) {
            r.error = QStringLiteral("(n): no jog frame");
            return r;
        }
        r.pressMs << ms(pressed, jogFrame);
        // Held a while, a hold every 100 ms as the page sends them.
        qint64 lastHold = clock.nsecsElapsed();
        for (int i = 0; i < 3; ++i) {
            waitUntil([] { return false; }, 100);
            lastHold = clock.nsecsElapsed();
            say(phone, "hold");
        }
        qint64 from = lastHold;
        if (!byWatchdog) {
            from = clock.nsecsElapsed();
            say(phone, "stop");
        }
        if (!waitUntil([&stopFrame] { return stopFrame >= 0; }, 5000)) {
            r.error = QStringLiteral("(n): no stop frame");
            return r;
        }
        (byWatchdog ? r.lastHoldMs : r.releaseMs) << ms(from, stopFrame);
    }
    return r;
}

QList<Verdict> pendantVerdicts(const PendantResult &r, bool judged)
{
    const QString baud = QString::number(r.baud);
    if (!r.error.isEmpty())
        return {{baud, QStringLiteral("(n) the phone pendant"), r.error, QString(), QString(),
                 Verdict::Result::Error}};
    const QString who =
        QStringLiteral("(n) pendant, controller answering in %1 ms: ").arg(r.answerDelayMs);
    const auto row = [&](const QString &what, QList<double> ms, double target) {
        std::sort(ms.begin(), ms.end());
        const double median = ms.isEmpty() ? 0 : ms.at(ms.size() / 2);
        const double max = ms.isEmpty() ? 0 : ms.last();
        const Verdict::Result result = !judged                         ? Verdict::Result::Info
                                       : !ms.isEmpty() && max < target ? Verdict::Result::Pass
                                                                       : Verdict::Result::Fail;
        return Verdict{baud,
                       who + what,
                       QStringLiteral("median %1 ms, max %2 ms over %3")
                           .arg(median, 0, 'f', 1)
                           .arg(max, 0, 'f', 1)
                           .arg(ms.size()),
                       QStringLiteral("max < %1 ms").arg(target),
                       QString::number(max / target, 'f', 2),
                       result};
    };
    return {row(QStringLiteral("press on the page -> jog frame on the wire"), r.pressMs, 50),
            row(QStringLiteral("release -> stop frame"), r.releaseMs, 50),
            row(QStringLiteral("last hold -> stop frame (holds stopped)"), r.lastHoldMs, 350)};
}

} // namespace stepcom::bench
