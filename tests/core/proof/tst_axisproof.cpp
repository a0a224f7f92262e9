#include "motion/travellimits.h"
#include "proof/axisproof.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/reconnector.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <memory>

using namespace stepcom;
using namespace stepcom::test;

// The lost-step test against the stalling simulator, judged by what the simulator really lost
// (its truth): a healthy axis keeps its steps whether homing zeroed the count or not, a speed
// and an acceleration past the motor's lose them by what the simulator lost, the registers come
// back after an E-STOP and a lost link, and a test that cannot be done moves nothing.
class TestAxisProof : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return host->device(); }
    double truthLost() const { return sim()->truth().axes.at(0).lostMm; }
    qint64 held(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }
    void boot(const AxisPhysics &physics, bool homingZeroes = true)
    {
        host = std::make_unique<SimHost>();
        QVERIFY(startProofSim(*host, physics, homingZeroes));
        session = proofSession(*host);
        QVERIFY(session->connection()->isConnected());
    }
    LostStepResult run(AxisProof::Options options,
                       const std::function<void(AxisProof &, const QString &)> &onProgress = {})
    {
        AxisProof proof(session.get());
        QSignalSpy finished(&proof, &AxisProof::finished);
        if (onProgress)
            connect(&proof, &AxisProof::progress, &proof,
                    [&proof, onProgress](const QString &t) { onProgress(proof, t); });
        if (!proof.start(options))
            return {};
        if (finished.isEmpty() && !finished.wait(120000))
            return {};
        return finished.first().first().value<LostStepResult>();
    }
    static AxisProof::Options quick()
    {
        AxisProof::Options o;
        o.cycles = 2;
        o.distance = 5;
        return o;
    }

private Q_SLOTS:
    void cleanup()
    {
        session.reset();
        host.reset();
    }

    void healthyAxisKeepsItsSteps_data()
    {
        QTest::addColumn<bool>("homingZeroes");
        QTest::newRow("homing zeroes the count") << true;
        QTest::newRow("homing keeps the count") << false;
    }
    void healthyAxisKeepsItsSteps()
    {
        QFETCH(bool, homingZeroes);
        boot(proofAxis(), homingZeroes);
        // Homed first, so the count at the switch is 0 or whatever it counted before.
        QSignalSpy motion(session->motion(), &MotionSupervisor::finished);
        session->command(QStringLiteral("motor1.home"));
        QVERIFY(motion.wait(20000));
        const double countAtSwitch = sim()->truth().axes.at(0).countMm;
        QCOMPARE(std::abs(countAtSwitch) < 0.01, homingZeroes);
        const LostStepResult r = run(quick());
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("done"));
        QCOMPARE(r.verdictWord(), QStringLiteral("kept"));
        QVERIFY2(std::abs(r.lost()) <= 0.02, qPrintable(r.text));
        QVERIFY(r.repeatability && *r.repeatability <= 0.02);
        QCOMPARE(truthLost(), 0.0);
        QVERIFY(r.restored);
        QCOMPARE(held("motor1.speed"), 300);
        QVERIFY(r.simulator == false); // a TCP controller, not the built-in simulator
        QCOMPARE(r.toJson().value(QStringLiteral("verdict")).toString(), QStringLiteral("kept"));
    }

    void stallAtTheTestSpeedIsLost()
    {
        AxisPhysics p = proofAxis();
        p.pullOutRpm = 200;
        p.pullInRpm = 100;
        boot(p);
        const double before = truthLost();
        const LostStepResult r = run(quick());
        QCOMPARE(r.verdictWord(), QStringLiteral("lost"));
        QVERIFY(r.lostOut && r.lostBack);
        // The loss as the simulator counted it, both halves together.
        const double lost = *r.lostOut + *r.lostBack;
        const double really = truthLost() - before;
        QVERIFY2(std::abs(lost - really) <= 0.03,
                 qPrintable(QStringLiteral("%1 vs %2: %3").arg(lost).arg(really).arg(r.text)));
        QVERIFY2(*r.lostOut < -0.05, qPrintable(r.text)); // out fast: the carriage behind
        QVERIFY(r.restored);
        QCOMPARE(held("motor1.speed"), 300);
    }

    void accelerationStallIsLost()
    {
        AxisPhysics p = proofAxis();
        p.accelLimitRpmPerS = 1000;
        p.pullInRpm = 100;
        boot(p);
        const qint64 accel = held("motor1.accel_frequency");
        const double before = truthLost();
        AxisProof::Options o = quick();
        o.accel = 200; // 200 Hz a ms: 7500 rpm/s on 1600 pulses a turn
        const LostStepResult r = run(o);
        QCOMPARE(r.verdictWord(), QStringLiteral("lost"));
        const double lost = r.lostOut.value_or(0) + r.lostBack.value_or(0);
        QVERIFY2(std::abs(lost - (truthLost() - before)) <= 0.03, qPrintable(r.text));
        QVERIFY(r.restored);
        QCOMPARE(held("motor1.accel_frequency"), accel);
        QCOMPARE(held("motor1.speed"), 300);
    }

    void refusedWithoutHomeInput()
    {
        boot(proofAxis());
        QVERIFY(sim()->setValue(QStringLiteral("motor1.home_input"), 0));
        const double carriage = sim()->truth().axes.at(0).carriageMm;
        const LostStepResult r = run(quick());
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("refused"));
        QVERIFY2(r.text.contains(QLatin1String("home input")), qPrintable(r.text));
        QCOMPARE(sim()->truth().axes.at(0).carriageMm, carriage);
        QCOMPARE(r.verdictWord(), QStringLiteral("unknown"));
    }

    void refusedOutsideTheTravelLimits()
    {
        boot(proofAxis());
        const double here = sim()->truth().axes.at(0).countMm;
        TravelLimits limits;
        QCOMPARE(limits.setAxis(session->map(), 1, here - 10, here + 2), QString());
        session->setTravelLimits(limits);
        const double carriage = sim()->truth().axes.at(0).carriageMm;
        const LostStepResult r = run(quick()); // 5 mm and the clearance past the switch
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("refused"));
        QCOMPARE(sim()->truth().axes.at(0).carriageMm, carriage);
        QCOMPARE(held("motor1.speed"), 300);
    }

    void emergencyStopPutsTheRegistersBack()
    {
        boot(proofAxis());
        const LostStepResult r = run(quick(), [this](AxisProof &, const QString &text) {
            if (text.contains(QLatin1String("cycle")))
                session->emergencyStop();
        });
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("estop"));
        QVERIFY2(r.restored, qPrintable(r.text));
        QCOMPARE(held("motor1.speed"), 300);
        QVERIFY(!sim()->running(1));
    }

    void stopEndsItAndPutsTheRegistersBack()
    {
        boot(proofAxis());
        const LostStepResult r = run(quick(), [](AxisProof &proof, const QString &text) {
            if (text.contains(QLatin1String("cycle")))
                QTimer::singleShot(300, &proof, [&proof] { proof.stop(); });
        });
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("stopped"));
        QVERIFY2(r.restored, qPrintable(r.text));
        QCOMPARE(held("motor1.speed"), 300);
        QVERIFY(!sim()->running(1));
    }

    void lostLinkSaysWhatWasNotPutBack()
    {
        boot(proofAxis());
        bool cut = false;
        const LostStepResult r = run(quick(), [this, &cut](AxisProof &, const QString &text) {
            if (!cut && text.contains(QLatin1String("cycle"))) {
                cut = true;
                QTimer::singleShot(200, host.get(), [this] { host->hangUp(3000); });
            }
        });
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("link_lost"));
        QVERIFY(!r.restored);
        QVERIFY2(r.text.contains(QLatin1String("300")), qPrintable(r.text)); // names the speed
    }

    void lostLinkPutsTheRegistersBackOnceItIsUp()
    {
        boot(proofAxis());
        session->connection()->reconnector()->setDelaysMs({300, 500, 1000});
        session->connection()->reconnector()->setEnabled(true);
        bool cut = false;
        const LostStepResult r = run(quick(), [this, &cut](AxisProof &, const QString &text) {
            if (!cut && text.contains(QLatin1String("cycle"))) {
                cut = true;
                QTimer::singleShot(200, host.get(), [this] { host->hangUp(1500); });
            }
        });
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("link_lost"));
        QVERIFY2(r.restored, qPrintable(r.text));
        QCOMPARE(held("motor1.speed"), 300);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestAxisProof, Guiless)
#include "tst_axisproof.moc"
