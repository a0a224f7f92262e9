// Any controller, any adapter: a controller that answers in 2, 5, 15 or 35 ms, on a modelled
// wire at 9600 and 38400 baud, with and without an echoing adapter. Every read, write and
// command works the first time; nothing is taken for an echo that is none; no answer is thrown
// away as "too soon"; the line learns the answer times and fits its timeout to them.
#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "device/readplanner.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

class TestAnyController : public QObject
{
    Q_OBJECT

    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    QStringList said;
    bool noWire = false; // a pseudo-terminal whose bytes take no time

    ModbusLink *link() const { return SessionInternals::link(*session); }

    bool start(int delayMs, int baud, bool adapterEchoes, bool echoSetting,
               const QHash<int, int> &slowCoils = {})
    {
        SimOptions o;
        o.slowCoils = slowCoils;
        o.rtu = true;
        o.answerDelayMs = delayMs;
        o.wireBaud = noWire ? 0 : baud;
        o.checkBaud = false;
        o.echo = adapterEchoes;
        host = std::make_unique<SimHost>();
        QString error;
        if (!host->start(o, &error)) {
            qWarning() << error;
            return false;
        }
        session = std::make_unique<DeviceSession>();
        said.clear();
        connect(session.get(), &DeviceSession::message, this,
                [this](DeviceSession::Severity, const QString &text) { said << text; });
        LinkSettings s;
        s.portName = host->rtuPath();
        s.baud = baud;
        s.echo = echoSetting;
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        if (!read.wait(10000) && read.isEmpty())
            return false;
        return read.at(0).at(0).toBool();
    }
    QString heard() const { return said.join(QLatin1Char('\n')); }
    bool commandDone(const QString &key)
    {
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        if (key == QLatin1String("estop"))
            session->emergencyStop();
        else
            session->command(key);
        if (!done.wait(8000) && done.isEmpty())
            return false;
        return done.at(0).at(0).toString() == key && done.at(0).at(1).toBool();
    }

private Q_SLOTS:
    void cleanup()
    {
        session.reset();
        host.reset();
        noWire = false;
    }

    void everythingWorksAtEveryAnswerTime_data() { test::addAnswerTimeRows(); }
    void everythingWorksAtEveryAnswerTime()
    {
        QFETCH(int, delayMs);
        QFETCH(int, baud);
        QVERIFY2(start(delayMs, baud, false, false), qPrintable(heard()));
        SimDevice *sim = host->device();
        // What was read is what the controller holds.
        for (const QString &key : {QStringLiteral("motor1.speed"), QStringLiteral("motor2.pitch"),
                                   QStringLiteral("device.baud")})
            QCOMPARE(session->parameters()->store()->deviceValue(key), sim->value(key));
        // A write is confirmed and held.
        const Parameter *speed = session->map().find(QStringLiteral("motor1.speed"));
        QSignalSpy wrote(session->parameters(), &SessionParameters::writeFinished);
        session->parameters()->write({{speed, 222}});
        QVERIFY(wrote.wait(8000));
        const auto outcome = wrote.at(0).at(0).value<WriteOutcome>();
        QVERIFY2(outcome.ok, qPrintable(outcome.errors.join(QLatin1Char('\n'))));
        QCOMPARE(*sim->value(QStringLiteral("motor1.speed")), 222);
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("motor1.speed")), 222);
        // Commands, the stops and the E-STOP are acknowledged and done.
        QVERIFY2(commandDone(QStringLiteral("output1_on")), qPrintable(heard()));
        QCOMPARE(*sim->value(QStringLiteral("io.out1")), 1);
        QVERIFY2(commandDone(QStringLiteral("motor1.forward")), qPrintable(heard()));
        QTRY_VERIFY(sim->running(1));
        QVERIFY2(commandDone(QStringLiteral("motor1.stop")), qPrintable(heard()));
        QTRY_VERIFY(!sim->running(1));
        QVERIFY2(commandDone(QStringLiteral("motor2.forward")), qPrintable(heard()));
        QTRY_VERIFY(sim->running(2));
        QVERIFY2(commandDone(QStringLiteral("estop")), qPrintable(heard()));
        QVERIFY(!sim->running(2));
        QCOMPARE(*sim->value(QStringLiteral("io.out1")), 0);
        QVERIFY2(commandDone(QStringLiteral("save_to_flash")), qPrintable(heard()));
        // Nothing was refused, thrown away or blamed on an echo. (A computer busy with other
        // programs may hold an answer past its timeout now and then -- its late answer is then
        // discarded -- one try in four is let pass: the defect this guards against lost every
        // answer.)
        const LinkStats &s = link()->stats();
        QVERIFY2(s.timeouts * 4 <= s.requests && s.stale <= s.timeouts,
                 qPrintable(s.summary(link()->settings().timeoutMs)));
        QCOMPARE(s.echo, 0);
        QVERIFY2(!heard().contains(QLatin1String("echo"), Qt::CaseInsensitive),
                 qPrintable(heard()));
        // The line learnt the answer times: the timeout fits them, within its bounds.
        QVERIFY(s.byUnit.value(1).count >= quint64(ModbusLink::kAdaptAfter));
        const int timeout = link()->timeoutFor(Request::read(0, 13));
        QVERIFY2(timeout < 500 && timeout >= 35, qPrintable(QString::number(timeout)));
        QVERIFY2(s.lineText(1).contains(QLatin1String("no echo")), qPrintable(s.lineText(1)));
    }

    // The reads are planned for the controller's own answer time once the line showed it
    // apart from the wire's: a 2 ms controller is read in more, shorter requests than the
    // manual's 35 ms would plan (reading across a gap then costs more than another request).
    void readsArePlannedForTheControllersOwnTime_data()
    {
        QTest::addColumn<int>("delayMs");
        QTest::addColumn<int>("baud");
        QTest::addRow("2 ms at 9600") << 2 << 9600;
        QTest::addRow("35 ms at 9600") << 35 << 9600;
        // 38400 is left to the benchmark (row k): there the two plans differ by 5 %, and a
        // computer busy with other tests for seconds on end tips the estimate.
    }
    void readsArePlannedForTheControllersOwnTime()
    {
        QFETCH(int, delayMs);
        QFETCH(int, baud);
        QVERIFY2(start(delayMs, baud, false, false), qPrintable(heard()));
        const RegisterMap &map = session->map();
        QList<const Parameter *> status;
        for (const QString &key : Poller::statusKeys(map))
            status << map.find(key);
        const QList<ReadBlock> best = ReadPlanner::plan(status, map.maxRegistersPerRequest(),
                                                        ReadCostModel::forBaud(baud, delayMs));
        const QList<ReadBlock> manual = ReadPlanner::plan(status, map.maxRegistersPerRequest(),
                                                          ReadCostModel::forBaud(baud, 35.0));
        // Read-all at connect timed reads of many lengths: the answer time is known -- unless
        // the computer is so busy with other programs that the round trips show no wire (each
        // is then mostly waiting to be scheduled) and the manual's time stays.
        (void)QTest::qWaitFor([&] { return link()->answerTimeMs(1).has_value(); }, 10000);
        const auto client = SessionInternals::client(*session);
        const std::optional<double> answerMs = link()->answerTimeMs(1);
        // The reads are planned for the time the line showed, else for the manual's.
        QCOMPARE(client->costModel(1).answerDelayMs, answerMs.value_or(35.0));
        const ReadCostModel truth = ReadCostModel::forBaud(baud, delayMs);
        const double bestMs = ReadPlanner::costMs(best, truth);
        const double manualMs = ReadPlanner::costMs(manual, truth);
        QCOMPARE(delayMs == 35, manualMs == bestMs); // the case shows what it is meant to
        if (!answerMs || std::abs(*answerMs - delayMs) > 15) {
            // How near the fit comes to the true time is measured on a quiet computer by the
            // benchmark (row k); here the plan just has to be the one for the time measured.
            qInfo("answer time %s on a busy computer (round trips %s): plan not judged",
                  answerMs ? qPrintable(QString::number(*answerMs)) : "not known",
                  qPrintable(link()->stats().byUnit.value(1).text()));
            QCOMPARE(client->planRead(status),
                     ReadPlanner::plan(status, map.maxRegistersPerRequest(),
                                       ReadCostModel::forBaud(baud, answerMs.value_or(35.0))));
            return;
        }
        // Measured near the truth: the plan comes near the best (the estimate may sit beside a
        // point where two plans cost about the same), far from the manual's plan when that one
        // is not the best.
        QTRY_VERIFY_WITH_TIMEOUT(ReadPlanner::costMs(client->planRead(status), truth) <=
                                     bestMs + 0.25 * (manualMs - bestMs),
                                 10000);
        if (delayMs == 35)
            QCOMPARE(client->planRead(status), manual);
    }

    // A pseudo-terminal without a wire (the built-in simulator): round trips do not grow with
    // the frame, the controller's own time cannot be told apart, the manual's plan stays.
    void noWireKeepsTheManualsPlan()
    {
        noWire = true;
        QVERIFY2(start(2, 9600, false, false), qPrintable(heard()));
        Poller *poller = SessionInternals::poller(*session);
        QTRY_VERIFY_WITH_TIMEOUT(poller->stats().cycles >= 5, 10000);
        QVERIFY(!link()->answerTimeMs(1).has_value());
    }

    // An echoing adapter is found on the first read whatever the setting, and from then on a
    // command's copy is skipped and its answer taken; a wrong "echoes" setting corrects itself.
    void echoIsLearntFromWhatCannotBeAnAnswer_data()
    {
        QTest::addColumn<int>("delayMs");
        QTest::addColumn<bool>("adapterEchoes");
        QTest::addColumn<bool>("echoSetting");
        for (int delay : {2, 35}) {
            QTest::addRow("%d ms, echo, option off", delay) << delay << true << false;
            QTest::addRow("%d ms, echo, option on", delay) << delay << true << true;
            QTest::addRow("%d ms, no echo, option on", delay) << delay << false << true;
        }
    }
    void echoIsLearntFromWhatCannotBeAnAnswer()
    {
        QFETCH(int, delayMs);
        QFETCH(bool, adapterEchoes);
        QFETCH(bool, echoSetting);
        QVERIFY2(start(delayMs, 9600, adapterEchoes, echoSetting), qPrintable(heard()));
        QCOMPARE(link()->stats().echo, adapterEchoes ? 1 : 0);
        SimDevice *sim = host->device();
        QVERIFY(sim->command(QStringLiteral("motor1.forward")));
        QTRY_VERIFY(sim->running(1));
        QVERIFY2(commandDone(QStringLiteral("estop")), qPrintable(heard()));
        QVERIFY(!sim->running(1));
        const Parameter *speed = session->map().find(QStringLiteral("motor2.speed"));
        QSignalSpy wrote(session->parameters(), &SessionParameters::writeFinished);
        session->parameters()->write({{speed, 150}});
        QVERIFY(wrote.wait(8000));
        QVERIFY(wrote.at(0).at(0).value<WriteOutcome>().ok);
        QCOMPARE(*sim->value(QStringLiteral("motor2.speed")), 150);
        QCOMPARE(link()->stats().timeouts, quint64(0));
    }

    // Firmware that writes its flash before it answers: save to flash gets its time, is sent
    // once, and says how long it took; a factory reset likewise.
    void slowCommandsAreGivenTheirTime()
    {
        QVERIFY2(start(5, 9600, false, false, {{96, 800}, {73, 1500}}), qPrintable(heard()));
        const LinkStats before = link()->stats();
        QVERIFY2(commandDone(QStringLiteral("save_to_flash")), qPrintable(heard()));
        QVERIFY2(heard().contains(QLatin1String("Save to flash: done; the controller answered "
                                                "after 0.8 s")) ||
                     heard().contains(QLatin1String("Save to flash: done; the controller answered "
                                                    "after 0.9 s")),
                 qPrintable(heard()));
        QCOMPARE(link()->stats().timeouts, before.timeouts);
        QCOMPARE(link()->stats().requests, before.requests + 1); // never repeated
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->factoryReset();
        QVERIFY2(read.wait(10000), qPrintable(heard())); // everything read back after it
        QVERIFY(read.at(0).at(0).toBool());
        QCOMPARE(link()->stats().timeouts, before.timeouts);
        // Compared with the factory values StepCom knows: the simulated machine's factory
        // leaves its limit and home inputs wired (SimRegisters::factoryValue), the rest is as
        // StepCom knows it.
        QVERIFY2(heard().contains(QLatin1String("Factory reset: read back; 6 value(s) differ from "
                                                "the factory values StepCom knows")),
                 qPrintable(heard()));
        QVERIFY2(heard().contains(QLatin1String("motor1.limit_positive IN1 (factory None)")),
                 qPrintable(heard()));
        QVERIFY2(!heard().contains(QLatin1String("motor1.speed")), qPrintable(heard()));
    }

    // A controller that answered a moment ago and falls silent is not blamed on the id, the
    // baud rate or the wiring.
    void silenceAfterAnswersIsNotBlamedOnTheWiring()
    {
        QVERIFY2(start(5, 9600, false, false), qPrintable(heard()));
        session->status()->stop();
        QVERIFY(host->powerCycle(4000));
        bool done = false;
        ReadOutcome outcome;
        session->parameters()->read({session->map().find(QStringLiteral("motor1.speed"))},
                                    [&](const ReadOutcome &r) {
                                        done = true;
                                        outcome = r;
                                    });
        QTRY_VERIFY_WITH_TIMEOUT(done, 10000);
        QVERIFY(!outcome.ok);
        const QString why = outcome.errors.join(QLatin1Char('\n'));
        QVERIFY2(why.contains(QLatin1String("it answered")), qPrintable(why));
        QVERIFY2(!why.contains(QLatin1String("check the device id")), qPrintable(why));
    }

    // The first request on a line whose echo is not known yet is a command: the copy is taken
    // for its answer (it may be one), the second copy shows the echo, and nothing is lost.
    void aCommandFirstLearnsTheEchoFromItsSecondCopy()
    {
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        o.echo = true;
        host = std::make_unique<SimHost>();
        QString error;
        QVERIFY2(host->start(o, &error), qPrintable(error));
        auto l = std::make_unique<ModbusLink>();
        QSignalSpy opened(l.get(), &ModbusLink::opened);
        QSignalSpy echo(l.get(), &ModbusLink::echoDetected);
        LinkSettings s;
        s.portName = host->rtuPath();
        l->open(s);
        QVERIFY(opened.wait(5000) || !opened.isEmpty());
        QVERIFY(opened.at(0).at(0).toBool());
        bool done = false;
        Result r;
        Request on = Request::coil(48, true);
        on.retryable = false;
        l->submit(on, [&](const Result &result) {
            done = true;
            r = result;
        });
        QTRY_VERIFY(done);
        QVERIFY2(r.ok, qPrintable(r.errorText));
        QCOMPARE(*host->device()->value(QStringLiteral("io.out1")), 1);
        QTRY_COMPARE(echo.size(), 1);
        QCOMPARE(l->stats().echo, 1);
        done = false;
        l->submit(Request::read(5, 1), [&](const Result &result) {
            done = true;
            r = result;
        });
        QTRY_VERIFY(done);
        QVERIFY2(r.ok, qPrintable(r.errorText));
        QCOMPARE(r.values.size(), 1);
        l.reset();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestAnyController, Guiless)
#include "tst_anycontroller.moc"
