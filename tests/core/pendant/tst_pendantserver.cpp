#include "bus/modbuslink.h"
#include "pendant/pendantcontrol.h"
#include "pendant/pendantserver.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "testregistry.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QSignalSpy>
#include <QTest>
#include <QWebSocket>

#include <memory>

using namespace stepcom;

namespace {

// A phone: Qt's own WebSocket client speaking the page's protocol.
class Phone : public QObject
{
public:
    explicit Phone(const QUrl &page)
    {
        QUrl ws = page;
        ws.setScheme(QStringLiteral("ws"));
        ws.setPath(page.path() + QStringLiteral("/ws"));
        connect(&socket, &QWebSocket::textMessageReceived, this, [this](const QString &text) {
            received << QJsonDocument::fromJson(text.toUtf8()).object();
        });
        connect(&socket, &QWebSocket::disconnected, this, [this] { closed = true; });
        socket.open(ws);
    }
    void send(const QJsonObject &m)
    {
        socket.sendTextMessage(QString::fromUtf8(QJsonDocument(m).toJson(QJsonDocument::Compact)));
    }
    void say(const char *type, int motor = 0, const char *dir = nullptr)
    {
        QJsonObject m{{QStringLiteral("t"), QLatin1String(type)}};
        if (motor)
            m.insert(QStringLiteral("motor"), motor);
        if (dir)
            m.insert(QStringLiteral("dir"), QLatin1String(dir));
        send(m);
    }
    QList<QJsonObject> of(const char *type) const
    {
        QList<QJsonObject> list;
        for (const QJsonObject &m : received)
            if (m.value(QStringLiteral("t")).toString() == QLatin1String(type))
                list << m;
        return list;
    }
    QWebSocket socket;
    QList<QJsonObject> received;
    bool closed = false;
};

} // namespace

// The pendant's server against the built-in simulator: pairing, status, the dead-man hold.
class TestPendantServer : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<PendantServer> server;
    QStringList actions; // what the session log would note
    QList<Request> sent; // every request on the wire

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    QStringList whats() const
    {
        QStringList all;
        for (const Request &r : sent)
            all << r.what;
        return all;
    }
    std::unique_ptr<Phone> pairedPhone()
    {
        auto phone = std::make_unique<Phone>(server->url());
        [&] { QTRY_VERIFY(phone->socket.state() == QAbstractSocket::ConnectedState); }();
        phone->send(
            {{QStringLiteral("t"), QStringLiteral("hello")},
             {QStringLiteral("lang"), QStringLiteral("en-US")},
             {QStringLiteral("ua"), QStringLiteral("Mozilla/5.0 (Linux; Android 14) Chrome/120")}});
        [&] { QTRY_VERIFY(!phone->of("status").isEmpty()); }();
        return phone;
    }
    void connectSim()
    {
        test::useBuiltinSimulator(*session);
        test::connectToSimulator(*session);
        connect(SessionInternals::link(*session), &ModbusLink::dispatched, this,
                [this](quint64, const Request &r) { sent.append(r); });
    }
    QUrl localUrl() const
    {
        QUrl u = server->url();
        u.setHost(QStringLiteral("127.0.0.1"));
        return u;
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        server = std::make_unique<PendantServer>(session.get());
        actions.clear();
        sent.clear();
        connect(server.get(), &PendantServer::userAction, this,
                [this](const QString &t) { actions << t; });
        QVERIFY2(server->start(QHostAddress::LocalHost, 0), qPrintable(server->error()));
        QVERIFY(server->port() != 0); // the port actually bound
    }
    void cleanup()
    {
        server.reset();
        session.reset();
    }

    void requestsWithoutTheTokenGet403AndNothingElse()
    {
        QNetworkAccessManager net;
        const auto get = [&net](const QString &path, int *status) {
            QNetworkReply *reply = net.get(QNetworkRequest(QUrl(path)));
            QSignalSpy done(reply, &QNetworkReply::finished);
            [&] { QTRY_VERIFY(done.size() == 1 || reply->isFinished()); }();
            *status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
            const QByteArray body = reply->readAll();
            reply->deleteLater();
            return body;
        };
        const QString root = QStringLiteral("http://127.0.0.1:%1").arg(server->port());
        int status = 0;
        for (const QString &path :
             {QStringLiteral("/"), QStringLiteral("/p/"),
              QStringLiteral("/p/0123456789abcdef0123456789abcdef"),
              QStringLiteral("/p/wrong/pendant.js"), QStringLiteral("/favicon.ico")}) {
            const QByteArray body = get(root + path, &status);
            QCOMPARE(status, 403);
            QVERIFY2(body.isEmpty(), qPrintable(path));
        }
        const QByteArray page = get(localUrl().toString(), &status);
        QCOMPARE(status, 200);
        QVERIFY(page.contains(QByteArray("/p/") + server->token().toLatin1() + "/pendant.js"));
        QVERIFY(page.contains("aria-label=\"Motor 1 position\""));
        get(localUrl().toString() + QStringLiteral("/pendant.js"), &status);
        QCOMPARE(status, 200);
        // A WebSocket without the token is closed and hears nothing.
        QUrl bad = localUrl();
        bad.setPath(QStringLiteral("/p/nottoken/ws"));
        Phone stranger(bad);
        QTRY_VERIFY(stranger.closed);
        QVERIFY(stranger.received.isEmpty());
        // Five wrong ones came from 127.0.0.1 above; five more and it is refused for a minute.
        for (int i = 0; i < 4; ++i)
            get(root + QStringLiteral("/p/guess"), &status);
        get(localUrl().toString(), &status);
        QCOMPARE(status, 403);
    }

    void aPairedPhoneGetsTheStatus()
    {
        connectSim();
        auto phone = pairedPhone();
        QTRY_VERIFY(!phone->of("control").isEmpty());
        QCOMPARE(phone->of("control").last().value(QStringLiteral("allowed")).toBool(), false);
        QTRY_VERIFY(phone->of("status").last().value(QStringLiteral("link")).toString() ==
                    QLatin1String("answering"));
        const QJsonObject s = phone->of("status").last();
        const QJsonArray motors = s.value(QStringLiteral("motors")).toArray();
        QCOMPARE(motors.size(), 2);
        QTRY_VERIFY(!phone->of("status")
                         .last()[QStringLiteral("motors")][0][QStringLiteral("position")]
                         .isNull());
        QCOMPARE(s.value(QStringLiteral("inputs")).toArray().size(), 4);
        QCOMPARE(s.value(QStringLiteral("outputs")).toArray().size(), 3);
        QCOMPARE(s[QStringLiteral("device")][QStringLiteral("id")].toInt(), 1);
        // Pushed again as the poll runs.
        const qsizetype seen = phone->of("status").size();
        QTRY_VERIFY(phone->of("status").size() >= seen + 3);
        QCOMPARE(server->clients().size(), 1);
        QCOMPARE(server->clients().first().browser, QStringLiteral("Chrome, Android"));
        QVERIFY2(actions.join(QLatin1Char('\n')).contains(QLatin1String("127.0.0.1: paired")),
                 qPrintable(actions.join(QLatin1Char('\n'))));
        // Disconnecting tells the phones: the link closed, the positions no longer known.
        session->connection()->disconnectFrom();
        QTRY_COMPARE(phone->of("status").last().value(QStringLiteral("link")).toString(),
                     QStringLiteral("closed"));
        QVERIFY(phone->of("status")
                    .last()[QStringLiteral("motors")][0][QStringLiteral("position")]
                    .isNull());
    }

    void jogIsRefusedUntilAllowed()
    {
        connectSim();
        auto phone = pairedPhone();
        phone->say("take");
        QTRY_COMPARE(phone->of("refused").size(), 1);
        phone->say("jog", 1, "fwd");
        QTRY_COMPARE(phone->of("refused").size(), 2);
        QVERIFY(!whats().contains(QStringLiteral("motor1.forward")));
        QCOMPARE(server->control()->holder(), 0);
        server->control()->setAllowed(true);
        phone->say("take");
        QTRY_VERIFY(server->control()->holder() != 0);
        QTRY_VERIFY(phone->of("control").last().value(QStringLiteral("you")).toBool());
        phone->say("jog", 1, "fwd");
        QTRY_VERIFY(sim()->running(1));
        phone->say("stop", 1);
        QTRY_VERIFY(!sim()->running(1));
    }

    void jogHoldAndReleaseStops()
    {
        connectSim();
        server->control()->setAllowed(true);
        auto phone = pairedPhone();
        phone->say("take");
        QTRY_VERIFY(server->control()->holder() != 0);
        phone->say("jog", 1, "fwd");
        QTRY_VERIFY(sim()->running(1));
        // Holds keep it going (sent twice as often as the page does: a loaded machine may be late).
        QTimer holds;
        connect(&holds, &QTimer::timeout, phone.get(), [&] { phone->say("hold", 1); });
        holds.start(50);
        QTest::qWait(800);
        QVERIFY2(sim()->running(1), qPrintable(actions.join(QLatin1Char('\n'))));
        QVERIFY(!whats().contains(QStringLiteral("motor1.stop")));
        holds.stop();
        phone->say("stop", 1);
        QTRY_VERIFY(whats().contains(QStringLiteral("motor1.stop")));
        QTRY_VERIFY(!sim()->running(1));
        QTRY_VERIFY(actions.join(QLatin1Char('\n'))
                        .contains(QLatin1String("motor 1 jog stopped (finger lifted)")));
        QTRY_COMPARE(session->jog()->state(1), JogController::State::Idle); // read back
    }

    void holdsThatStopComingStopTheMotor()
    {
        connectSim();
        server->control()->setAllowed(true);
        auto phone = pairedPhone();
        phone->say("take");
        QTRY_VERIFY(server->control()->holder() != 0);
        phone->say("jog", 2, "rev");
        QTRY_VERIFY(sim()->running(2));
        // No hold ever comes: the server's watchdog stops it, the phone does nothing more. The
        // cause is read from the log, not from a clock (a busy computer stretches any time).
        QTRY_VERIFY(whats().contains(QStringLiteral("motor2.stop")));
        QTRY_VERIFY(!sim()->running(2));
        QVERIFY2(actions.join(QLatin1Char('\n'))
                     .contains(QLatin1String("no hold from the pendant for 300 ms")),
                 qPrintable(actions.join(QLatin1Char('\n'))));
        QTRY_VERIFY(!phone->of("jog").isEmpty() &&
                    !phone->of("jog").last().value(QStringLiteral("jogging")).toBool());
    }

    void socketClosedMidJogStops()
    {
        connectSim();
        server->control()->setAllowed(true);
        auto phone = pairedPhone();
        phone->say("take");
        QTRY_VERIFY(server->control()->holder() != 0);
        QTimer holds; // held until the phone goes: the watchdog has no reason to stop it
        connect(&holds, &QTimer::timeout, phone.get(), [&] { phone->say("hold", 1); });
        holds.start(50);
        phone->say("jog", 1, "rev");
        QTRY_VERIFY(sim()->running(1));
        holds.stop();
        phone->socket.abort(); // the phone is gone: no stop, no close frame
        QTRY_VERIFY(whats().contains(QStringLiteral("motor1.stop")));
        // Stopped for the closed socket itself, not only later by the hold watchdog.
        QTRY_VERIFY2(actions.join(QLatin1Char('\n'))
                         .contains(QLatin1String("jog stopped (the phone's connection closed)")),
                     qPrintable(actions.join(QLatin1Char('\n'))));
        QTRY_VERIFY(!sim()->running(1));
        QTRY_COMPARE(server->control()->holder(), 0);
        QVERIFY(server->clients().isEmpty());
    }

    void aSecondPhoneCannotJogWhileTheFirstHoldsControl()
    {
        connectSim();
        server->control()->setAllowed(true);
        auto first = pairedPhone();
        auto second = pairedPhone();
        first->say("take");
        QTRY_VERIFY(server->control()->holder() != 0);
        const int holder = server->control()->holder();
        QTRY_VERIFY(!second->of("control").isEmpty() &&
                    !second->of("control").last().value(QStringLiteral("holder")).isNull());
        first->say("jog", 1, "fwd");
        QTRY_VERIFY(sim()->running(1));
        second->say("jog", 2, "fwd");
        QTRY_COMPARE(second->of("refused").size(), 1);
        QVERIFY(!whats().contains(QStringLiteral("motor2.forward")));
        second->say("stop", 1); // nor stop (or hold) the first one's jog
        // Refused again: the server takes a phone's messages in order, so it has had the stop.
        second->say("jog", 2, "fwd");
        QTRY_COMPARE(second->of("refused").size(), 2);
        QCOMPARE(server->control()->holder(), holder);
        // Taking control stops the holder's jog.
        second->say("take");
        QTRY_VERIFY(server->control()->holder() != holder);
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(
            actions.join(QLatin1Char('\n')).contains(QLatin1String("another phone took control")));
    }

    void windowStopsAndTakeBackEndThePendantJog()
    {
        connectSim();
        server->control()->setAllowed(true);
        auto phone = pairedPhone();
        phone->say("take");
        QTRY_VERIFY(server->control()->holder() != 0);
        QTimer holds;
        connect(&holds, &QTimer::timeout, phone.get(), [&] { phone->say("hold", 1); });
        holds.start(50);
        phone->say("jog", 1, "fwd");
        QTRY_VERIFY(sim()->running(1));
        session->stopJogging(DeviceSession::JogStop::PageLeft); // the window's own rule
        QTRY_VERIFY(!sim()->running(1));
        QTRY_VERIFY(!phone->of("jog").isEmpty() &&
                    !phone->of("jog").last().value(QStringLiteral("jogging")).toBool());
        server->control()->takeBack();
        QTRY_VERIFY(!phone->of("control").last().value(QStringLiteral("you")).toBool());
    }

    void emergencyStopFromThePageReachesEveryDevice()
    {
        test::useBuiltinSimulator(*session, {1, 2});
        session->line()->setDeviceIds({1, 2});
        test::connectToSimulator(*session);
        QSignalSpy finished(session.get(), &DeviceSession::emergencyStopFinished);
        auto phone = pairedPhone(); // watching only: the E-STOP is for every paired phone
        phone->say("estop");
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QCOMPARE(finished.at(0).at(0).value<QList<int>>(), (QList<int>{1, 2}));
        QVERIFY(actions.join(QLatin1Char('\n')).contains(QLatin1String("127.0.0.1: E-STOP")));
    }

    void stoppingTellsThePhones()
    {
        auto phone = pairedPhone();
        server->stop();
        QTRY_VERIFY(phone->closed);
        QCOMPARE(phone->of("bye").size(), 1);
        QVERIFY(!server->isRunning());
        QVERIFY(server->url().isEmpty());
    }
};

STEPCOM_TEST(TestPendantServer, Guiless)
#include "tst_pendantserver.moc"
