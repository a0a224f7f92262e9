#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "scripteddevice.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionrisks.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

class TestDeviceSession : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    void connectSim() { test::connectToSimulator(*session); }
    SimDevice *sim() const { return test::simHost(*session)->device(); }

private Q_SLOTS:
    void init() { session = std::make_unique<DeviceSession>(); }
    void cleanup() { session.reset(); }

    void connectingReadsButNeverWrites()
    {
        connectSim();
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("motor1.step_angle")),
                 180);
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor2.pitch")),
                 ParameterStore::State::InSync);
        for (const TrafficEntry &e : session->connection()->traffic()->entries()) {
            if (e.direction == TrafficEntry::Direction::Sent)
                QCOMPARE(int(quint8(e.bytes.at(1))), 0x03); // reads only
        }
    }

    void writeChangesReachesTheController()
    {
        connectSim();
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 450).isEmpty());
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300); // held, not written
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        session->parameters()->writeChanges();
        QTRY_COMPARE(written.size(), 1);
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor1.speed")),
                 ParameterStore::State::InSync);
        QVERIFY(session->parameters()->store()->unsavedToFlash());
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        session->saveToFlash();
        QTRY_COMPARE(done.size(), 1);
        QVERIFY(done.at(0).at(1).toBool());
        QVERIFY(!session->parameters()->store()->unsavedToFlash());
    }

    void writeWhoseAnswerIsLostIsNeverTakenForTheOldValue()
    {
        // The controller takes the new speed but every answer to a write is lost (found by the
        // soak test's truth check): the write is reported failed, the edit is kept as failed,
        // and the store never goes on claiming the controller holds the old value; it reads
        // back what the controller holds.
        test::ScriptedDevice device;
        QString error;
        QVERIFY2(device.open(&error), qPrintable(error));
        device.registers = QList<quint16>(320, 0);
        const quint16 speed = session->map().find(QStringLiteral("motor1.speed"))->address;
        device.registers[speed] = 300;
        device.setResponder([&](const QByteArray &req, int) -> std::optional<QByteArray> {
            const auto word = [&](int at) {
                return quint16((quint8(req.at(at)) << 8) | quint8(req.at(at + 1)));
            };
            switch (quint8(req.at(1))) {
            case 0x03:
                return device.registerDevice(req);
            case 0x06:
                device.registers[word(2)] = word(4);
                return std::nullopt; // acted, but the answer never arrives
            case 0x10:
                for (int i = 0; i < word(4); ++i)
                    device.registers[word(2) + i] = word(7 + 2 * i);
                return std::nullopt;
            default:
                return std::nullopt;
            }
        });
        LinkSettings s;
        s.portName = device.clientPath();
        s.timeoutMs = 200;
        s.retries = 1;
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        const QString key = QStringLiteral("motor1.speed");
        QCOMPARE(*session->parameters()->store()->deviceValue(key), 300);

        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        QVERIFY(session->parameters()->store()->edit(key, 450).isEmpty());
        session->parameters()->writeChanges();
        QTRY_COMPARE_WITH_TIMEOUT(written.size(), 1, 10000);
        QCOMPARE(device.registers[speed], quint16(450)); // it did arrive
        QCOMPARE(session->parameters()->store()->state(key), ParameterStore::State::WriteFailed);
        QVERIFY(session->parameters()->store()->deviceValue(key) != std::optional<qint64>(300));
        // Read back: the controller holds what was typed, so nothing is pending any more.
        QTRY_COMPARE_WITH_TIMEOUT(session->parameters()->store()->deviceValue(key),
                                  std::optional<qint64>(450), 5000);
        QCOMPARE(session->parameters()->store()->state(key), ParameterStore::State::InSync);
    }

    void statusIsPolled()
    {
        connectSim();
        sim()->setInput(3, SimDevice::InputForce::On);
        QTRY_COMPARE_WITH_TIMEOUT(
            session->parameters()->store()->deviceValue(QStringLiteral("io.in3")).value_or(-1), 1,
            5000);
        sim()->setInput(3, SimDevice::InputForce::Off);
        QTRY_COMPARE_WITH_TIMEOUT(
            session->parameters()->store()->deviceValue(QStringLiteral("io.in3")).value_or(-1), 0,
            5000);
    }

    void emergencyStopGoesAheadAndStops()
    {
        connectSim();
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        session->command(QStringLiteral("motor1.forward"));
        QTRY_COMPARE(done.size(), 1);
        QTRY_VERIFY(sim()->running(1));
        QList<QString> order;
        connect(SessionInternals::link(*session), &ModbusLink::dispatched, this,
                [&order](quint64, const Request &r) { order << r.what; });
        session->parameters()->readAll();
        session->parameters()->readAll();
        session->emergencyStop();
        QTRY_VERIFY(order.contains(QStringLiteral("estop")));
        QVERIFY2(order.indexOf(QStringLiteral("estop")) <= 1,
                 qPrintable(order.join(QLatin1Char(','))));
        QTRY_VERIFY(!sim()->running(1));
    }

    // The risk guard a front-end installs on risks() is asked, for the device in view, before
    // what the session itself starts that cannot be undone; its refusal stops it, nothing sent.
    void theRiskGuardIsAskedFirstAndItsNoStops()
    {
        connectSim();
        QList<QPair<SessionRisks::Risk, int>> asked;
        QString refusal = QStringLiteral("no backup folder");
        session->risks()->setGuard(
            [&](SessionRisks::Risk risk, int id, SessionRisks::Proceed proceed) {
                asked.append({risk, id});
                proceed(refusal);
            });
        QVERIFY(session->risks()->hasGuard());
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        const qsizetype sent = session->connection()->traffic()->entries().size();
        session->saveToFlash();
        QTRY_COMPARE(done.size(), 1);
        QVERIFY(!done.at(0).at(1).toBool());
        QCOMPARE(asked,
                 (QList<QPair<SessionRisks::Risk, int>>{{SessionRisks::Risk::SaveToFlash, 1}}));
        for (const TrafficEntry &e : session->connection()->traffic()->entries().mid(sent))
            QVERIFY(e.direction != TrafficEntry::Direction::Sent || quint8(e.bytes.at(1)) == 0x03);
        refusal.clear(); // agreed: it goes on
        session->saveToFlash();
        QTRY_COMPARE(done.size(), 2);
        QVERIFY(done.at(1).at(1).toBool());
        session->risks()->setGuard({}); // none: at once
        QVERIFY(!session->risks()->hasGuard());
        bool proceeded = false;
        session->risks()->guard(SessionRisks::Risk::Apply, 3,
                                [&](const QString &r) { proceeded = r.isEmpty(); });
        QVERIFY(proceeded);
    }

    void idChangeIsFollowed()
    {
        connectSim();
        QSignalSpy changed(session->line(), &SessionLine::linkChanged);
        session->line()->changeLink(7, 9600);
        QTRY_COMPARE_WITH_TIMEOUT(changed.size(), 1, 5000);
        QCOMPARE(session->connection()->settings().deviceId, 7);
        QCOMPARE(sim()->deviceId(), 7);
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        QVERIFY(read.at(0).at(0).toBool());
    }

    void baudChangeIsFollowed()
    {
        connectSim();
        QSignalSpy changed(session->line(), &SessionLine::linkChanged);
        QSignalSpy failed(session->line(), &SessionLine::linkChangeFailed);
        session->line()->changeLink(1, 19200);
        QTRY_VERIFY_WITH_TIMEOUT(changed.size() + failed.size() == 1, 10000);
        QVERIFY2(changed.size() == 1,
                 failed.isEmpty() ? "" : qPrintable(failed.at(0).at(1).toString()));
        QCOMPARE(session->connection()->settings().baud, 19200);
        QCOMPARE(sim()->baud(), 19200);
    }

    void lostControllerOffersTheOldSettings()
    {
        connectSim();
        test::simHost(*session)->device()->setValue(QStringLiteral("device.id"), 1);
        QSignalSpy failed(session->line(), &SessionLine::linkChangeFailed);
        // the controller takes the new id but we stop it before it can answer there
        connect(SessionInternals::link(*session), &ModbusLink::finished, this,
                [this](quint64, const Request &r, const Result &res) {
                    if (r.what == QLatin1String("device.id") && res.ok)
                        test::simHost(*session)->stop();
                });
        session->line()->changeLink(9, 9600);
        QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 10000);
        const LinkSettings previous = failed.at(0).at(0).value<LinkSettings>();
        QCOMPARE(previous.deviceId, 1);
    }

    void withoutASimulatorConnectSimulatorSaysSo()
    {
        // The real device path has no simulator in it: a program must hand the session one.
        QSignalSpy connected(session->connection(), &SessionConnection::connected);
        QSignalSpy said(session.get(), &DeviceSession::message);
        session->connection()->connectSimulator();
        QCOMPARE(connected.size(), 1);
        QVERIFY(!connected.at(0).at(0).toBool());
        QVERIFY(said.size() >= 1);
        QVERIFY2(said.last().at(1).toString().contains(QLatin1String("no built-in simulator")),
                 qPrintable(said.last().at(1).toString()));
        QVERIFY(!session->connection()->isConnected());
    }

    void stopRulesStopEveryJogWithTheirReason_data()
    {
        QTest::addColumn<DeviceSession::JogStop>("why");
        QTest::addColumn<QString>("reason");
        QTest::newRow("page left") << DeviceSession::JogStop::PageLeft << "the page was left";
        QTest::newRow("focus lost") << DeviceSession::JogStop::FocusLost << "the window lost focus";
        QTest::newRow("closing") << DeviceSession::JogStop::WindowClosing << "the window closes";
    }
    void stopRulesStopEveryJogWithTheirReason()
    {
        QFETCH(DeviceSession::JogStop, why);
        QFETCH(QString, reason);
        connectSim();
        JogController *jog = session->jog();
        QStringList texts;
        connect(jog, &JogController::message, this,
                [&texts](DeviceSession::Severity, const QString &t) { texts << t; });
        QVERIFY(jog->press(1, JogController::Direction::Forward));
        QVERIFY(jog->press(2, JogController::Direction::Reverse));
        QTRY_VERIFY(sim()->running(1) && sim()->running(2));
        QCOMPARE(session->stopJogging(why), 2);
        QTRY_VERIFY(!sim()->running(1) && !sim()->running(2));
        QTRY_COMPARE(jog->state(1), JogController::State::Idle);
        QTRY_COMPARE(jog->state(2), JogController::State::Idle);
        QVERIFY2(texts.join(QLatin1Char('\n')).contains(reason), qPrintable(texts.join('\n')));
        QCOMPARE(session->stopJogging(why), 0); // nothing left to stop
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDeviceSession, Guiless)
#include "tst_devicesession.moc"
