#include "sim/model/machinefile.h"
#include "sim/model/simdevice.h"

#include "simdevicechecks.h"

#include <QJsonArray>
#include <QTest>

#include <cmath>

using namespace stepcom;
using namespace stepcom::test;

namespace {

// Motor 1 on its factory values: 1.8°, 8 µsteps, 5 mm pitch: 1600 pulses a turn, 320 a mm,
// an electrical cycle (4 full steps) of 32 pulses = 0.1 mm.
constexpr qint64 kPhysicsChunk = 32;

// A machine whose motor 1 has these keys (a JSON object's inside).
MachineSettings physicsMachine(const QString &motor1, const QString &global = QString())
{
    const QString json =
        QStringLiteral(R"({"format": "stepcom-sim-machine", "version": 1%1,
        "axes": {"motor1": {%2}}})")
            .arg(global.isEmpty() ? QString() : QStringLiteral(", ") + global, motor1);
    QString error;
    const auto m = MachineFile::parse(json.toUtf8(), QStringLiteral("test"), &error);
    if (!m)
        qFatal("%s", qPrintable(error));
    return *m;
}

SimTruth::Axis physicsTruth(const SimDevice &d, int motor = 1)
{
    return d.truth().axes.at(motor - 1);
}

// Runs until motor 1 stops (at most `ms`).
void runOutPhysics(SimDevice &d, int ms = 60000)
{
    for (int t = 0; t < ms && d.running(1); t += 10)
        d.advance(10);
}

} // namespace

// The open-loop axis: a rotor that stalls and relocks in 4-full-step chunks, backlash, switches
// with jitter and hysteresis at the carriage's real place, hard stops, wiring; manual clock.
class TstSimPhysics : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void stallsAbovePullOut_data()
    {
        QTest::addColumn<qint64>("speedRpm");
        QTest::addColumn<bool>("stalls");
        QTest::newRow("300 rpm past a pull-out of 200") << 300LL << true;
        QTest::newRow("200 rpm at the pull-out") << 200LL << false;
        QTest::newRow("150 rpm below it") << 150LL << false;
    }
    void stallsAbovePullOut()
    {
        QFETCH(qint64, speedRpm);
        QFETCH(bool, stalls);
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(R"("pull_out_rpm": 200, "pull_in_rpm": 60)")));
        set(d, "motor1.speed", speedRpm);
        cmd(d, "motor1.forward");
        d.advance(1000);
        QCOMPARE(physicsTruth(d).stalled, stalls);
        const SimTruth::Axis running = physicsTruth(d);
        QCOMPARE(running.lostPulses > 0, stalls);
        cmd(d, "motor1.stop");
        const SimTruth::Axis t = physicsTruth(d);
        QVERIFY(!t.stalled); // locked in again once the pulses stopped
        QCOMPARE(t.lostPulses % kPhysicsChunk, 0);
        QCOMPARE(t.lostPulses > 0, stalls);
        // The carriage is where the rotor is: the count minus what was lost.
        QVERIFY(std::abs(t.lostMm + double(t.lostPulses) / 320.0) < 1e-9);
        QCOMPARE(t.offsetMm, 50.0);
        QVERIFY(std::abs(t.carriageMm - t.offsetMm - t.rotorMm) < 1e-9);
    }

    void stallsUnderTooMuchAcceleration_data()
    {
        QTest::addColumn<qint64>("accelHzPerMs");
        QTest::addColumn<bool>("stalls");
        // 2000 rpm/s on 1600 pulses a turn: 53.3 Hz gained per ms at most.
        QTest::newRow("80 Hz/ms") << 80LL << true;
        QTest::newRow("53 Hz/ms") << 53LL << false;
        QTest::newRow("20 Hz/ms") << 20LL << false;
    }
    void stallsUnderTooMuchAcceleration()
    {
        QFETCH(qint64, accelHzPerMs);
        QFETCH(bool, stalls);
        SimDevice d;
        d.setMachine(
            physicsMachine(QStringLiteral(R"("accel_limit_rpm_per_s": 2000, "pull_in_rpm": 60)")));
        set(d, "motor1.accel_frequency", accelHzPerMs);
        set(d, "motor1.move_distance", 2000); // 20 mm
        cmd(d, "motor1.move");
        runOutPhysics(d);
        const SimTruth::Axis t = physicsTruth(d);
        QCOMPARE(t.count, 6400);
        QCOMPARE(t.lostPulses > 0, stalls);
        QCOMPARE(t.lostPulses % kPhysicsChunk, 0);
    }

    void startAbovePullInLosesTheMove_data()
    {
        QTest::addColumn<qint64>("startHz");
        QTest::addColumn<qint64>("lost");
        // Pull-in 20 rpm = 533 Hz.
        QTest::newRow("starts at 800 Hz: never in sync") << 800LL << 3200LL;
        QTest::newRow("starts at 533 Hz") << 533LL << 0LL;
        QTest::newRow("starts at 400 Hz") << 400LL << 0LL;
    }
    void startAbovePullInLosesTheMove()
    {
        QFETCH(qint64, startHz);
        QFETCH(qint64, lost);
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(R"("pull_in_rpm": 20)")));
        set(d, "motor1.start_frequency", startHz);
        cmd(d, "motor1.move");
        runOutPhysics(d);
        const SimTruth::Axis t = physicsTruth(d);
        QCOMPARE(t.count, 3200);
        QCOMPARE(t.lostPulses, lost);
        QCOMPARE(t.carriageMm, 50.0 + double(3200 - lost) / 320.0);
    }

    void relocksInWholeCyclesAtPullIn_data()
    {
        QTest::addColumn<qint64>("microsteps");
        QTest::newRow("full steps") << 1LL;
        QTest::newRow("2 µsteps") << 2LL;
        QTest::newRow("8 µsteps") << 8LL;
        QTest::newRow("16 µsteps") << 16LL;
    }
    void relocksInWholeCyclesAtPullIn()
    {
        QFETCH(qint64, microsteps);
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(R"("pull_out_rpm": 200, "pull_in_rpm": 60)")));
        set(d, "motor1.microsteps", microsteps);
        set(d, "motor1.speed", 300);
        cmd(d, "motor1.forward");
        d.advance(1000);
        QVERIFY(physicsTruth(d).stalled);
        set(d, "motor1.speed", 100); // between pull-in and pull-out: still out of sync
        d.advance(1000);
        QVERIFY(d.running(1));
        QVERIFY(physicsTruth(d).stalled);
        set(d, "motor1.speed", 60); // at pull-in: locks in while it runs
        d.advance(1000);
        QVERIFY(d.running(1));
        SimTruth::Axis t = physicsTruth(d);
        QVERIFY(!t.stalled);
        const qint64 lost = t.lostPulses;
        QVERIFY(lost > 0);
        cmd(d, "motor1.stop");
        t = physicsTruth(d);
        QCOMPARE(t.lostPulses, lost); // in sync: nothing more lost
        QCOMPARE(t.lostPulses % (4 * microsteps), 0);
    }

    void defaultsNeverStall_data()
    {
        QTest::addColumn<bool>("machineFile");
        QTest::newRow("no machine file") << false;
        QTest::newRow("a machine file's defaults") << true;
    }
    void defaultsNeverStall()
    {
        QFETCH(bool, machineFile);
        SimDevice d;
        if (machineFile)
            d.setMachine(physicsMachine(QString()));
        set(d, "motor1.speed", 3000);
        set(d, "motor1.accel_frequency", 65535);
        set(d, "motor1.start_frequency", 65535);
        set(d, "motor1.move_distance", 10000); // 100 mm
        cmd(d, "motor1.move");
        d.advance(5);
        QVERIFY(!physicsTruth(d).stalled);
        runOutPhysics(d);
        const SimTruth::Axis t = physicsTruth(d);
        QCOMPARE(t.count, 32000);
        QCOMPARE(t.lostPulses, 0);
        QCOMPARE(t.carriageMm, 150.0);
    }

    void backlashLagsOnReversal()
    {
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(R"("backlash_mm": 0.05)")));
        set(d, "motor1.move_distance", 1000);
        cmd(d, "motor1.move"); // +10 mm: approach 10 from below
        runOutPhysics(d);
        const SimTruth::Axis below = physicsTruth(d);
        cmd(d, "motor1.move"); // on to 20
        runOutPhysics(d);
        set(d, "motor1.direction", 1);
        cmd(d, "motor1.move"); // back to 10: approached from above
        runOutPhysics(d);
        const SimTruth::Axis above = physicsTruth(d);
        QCOMPARE(above.count, below.count); // the count knows nothing of it
        QCOMPARE(above.lostPulses, 0);
        QVERIFY(std::abs(above.carriageMm - below.carriageMm - 0.05) < 1e-9);
        QVERIFY(std::abs(above.lostMm - below.lostMm - 0.05) < 1e-9);
        // A short reversal inside the band does not move the carriage at all.
        set(d, "motor1.move_distance", 4); // 0.04 mm
        set(d, "motor1.direction", 0);
        cmd(d, "motor1.move");
        runOutPhysics(d);
        QCOMPARE(physicsTruth(d).carriageMm, above.carriageMm);
    }

    void switchJitterDiffersPerApproach()
    {
        auto trips = [](quint32 seed) {
            SimDevice d;
            d.setMachine(
                physicsMachine(QStringLiteral(R"("switch_jitter_mm": 0.02, "start_mm": 5)"),
                               QStringLiteral(R"("seed": %1)").arg(seed)));
            set(d, "motor1.speed", 30);
            set(d, "motor1.move_distance", 100); // 1 mm off the switch and back
            QList<double> list;
            for (int i = 0; i < 6; ++i) {
                cmd(d, "motor1.home");
                runOutPhysics(d);
                const SimTruth::Axis t = physicsTruth(d);
                if (!t.negativeSwitch || t.carriageMm > t.negativeTripMm)
                    return QList<double>();
                list << t.negativeTripMm;
                cmd(d, "motor1.move");
                runOutPhysics(d);
                if (physicsTruth(d).negativeSwitch)
                    return QList<double>();
            }
            return list;
        };
        const QList<double> a = trips(7);
        QCOMPARE(a.size(), 6);
        for (double trip : a)
            QVERIFY2(std::abs(trip) <= 0.01, qPrintable(QString::number(trip)));
        QVERIFY(*std::max_element(a.begin(), a.end()) - *std::min_element(a.begin(), a.end()) >
                0.001);
        QCOMPARE(trips(7), a); // the seed makes it reproducible
        QVERIFY(trips(8) != a);
    }

    void hysteresisReleasesLater()
    {
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(
            R"("switch_jitter_mm": 0, "switch_hysteresis_mm": 0.5, "start_mm": 3)")));
        cmd(d, "motor1.home");
        runOutPhysics(d);
        QVERIFY(physicsTruth(d).negativeSwitch);
        set(d, "motor1.move_distance", 30); // 0.3 mm
        cmd(d, "motor1.move");
        runOutPhysics(d);
        QVERIFY(physicsTruth(d).negativeSwitch); // within the hysteresis
        cmd(d, "motor1.move");
        runOutPhysics(d);
        QVERIFY(!physicsTruth(d).negativeSwitch); // 0.6 mm out: released
    }

    void hardStopLosesWholeCycles()
    {
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(R"("hard_stop_mm": 2, "travel_mm": 100)")));
        set(d, "motor1.limit_positive", 0); // nothing stops the pulses at the switch
        cmd(d, "motor1.forward");
        d.advance(10000);
        QVERIFY(d.running(1));
        SimTruth::Axis t = physicsTruth(d);
        QCOMPARE(t.carriageMm, 102.0); // against the hard stop
        QVERIFY(t.stalled);
        cmd(d, "motor1.stop");
        t = physicsTruth(d);
        QVERIFY(!t.stalled);
        QVERIFY(t.lostPulses > 0);
        QCOMPARE(t.lostPulses % kPhysicsChunk, 0);
        QVERIFY(t.carriageMm <= 102.0 && t.carriageMm > 101.9);
        // Away from the stop the carriage follows the count again, pulse for pulse.
        set(d, "motor1.direction", 1);
        cmd(d, "motor1.move");
        runOutPhysics(d);
        const SimTruth::Axis back = physicsTruth(d);
        QCOMPARE(back.lostPulses, t.lostPulses);
        QVERIFY(std::abs(t.carriageMm - back.carriageMm - 10.0) < 1e-9);
    }

    void homingZeroesTheCountOrNot_data()
    {
        QTest::addColumn<bool>("zeroes");
        QTest::newRow("zeroes") << true;
        QTest::newRow("leaves the count") << false;
    }
    void homingZeroesTheCountOrNot()
    {
        QFETCH(bool, zeroes);
        SimDevice d;
        d.setMachine(
            physicsMachine(QStringLiteral(R"("switch_jitter_mm": 0, "start_mm": 20)"),
                           QStringLiteral(R"("homing_zeroes_count": %1)")
                               .arg(zeroes ? QStringLiteral("true") : QStringLiteral("false"))));
        cmd(d, "motor1.home");
        runOutPhysics(d);
        const SimTruth::Axis t = physicsTruth(d);
        QVERIFY(t.negativeSwitch);
        if (zeroes) {
            QCOMPARE(d.position(1), 0);
        } else {
            // 20 mm down to the switch, within the last millisecond's pulses.
            QVERIFY2(d.position(1) <= -2000 && d.position(1) > -2003,
                     qPrintable(QString::number(d.position(1))));
            QCOMPARE(t.count, d.steps(1));
        }
        QCOMPARE(t.lostPulses, 0);
    }

    void wiringDrivesItsInput()
    {
        SimDevice d;
        d.setMachine(physicsMachine(QStringLiteral(
            R"("switch_jitter_mm": 0, "start_mm": 0, "wiring": {"home": 3, "positive": 1})")));
        QVERIFY(d.input(3));  // the home switch lights IN3 ...
        QVERIFY(!d.input(2)); // ... not the negative limit the register names
        // Homing looks at the register's input (IN2): a wrong register finds no switch.
        d.setMachinePosition(1, 10);
        QVERIFY(!d.input(3));
        cmd(d, "motor1.home");
        d.advance(3000);
        QVERIFY(d.running(1));
        QVERIFY(d.input(3));
        cmd(d, "motor1.stop");
        set(d, "motor1.home_input", 3);
        d.setMachinePosition(1, 10);
        cmd(d, "motor1.home");
        runOutPhysics(d);
        QCOMPARE(d.position(1), 0);
        QVERIFY(physicsTruth(d).carriageMm <= 0.0 && physicsTruth(d).carriageMm > -0.03);
    }

    void truthJsonNamesEveryField()
    {
        SimDevice d;
        const QJsonObject json = d.truthJson();
        QVERIFY(json.contains(QStringLiteral("time_ms")));
        const QJsonArray axes = json.value(QStringLiteral("axes")).toArray();
        QCOMPARE(axes.size(), d.motorCount());
        const QJsonObject a = axes.at(0).toObject();
        for (const char *key :
             {"motor", "count", "count_mm", "rotor_mm", "carriage_mm", "offset_mm", "lost_pulses",
              "lost_mm", "stalled", "negative_switch", "positive_switch"})
            QVERIFY2(a.contains(QLatin1String(key)), key);
        QCOMPARE(a.value(QStringLiteral("carriage_mm")).toDouble(), 50.0);
        QCOMPARE(a.value(QStringLiteral("offset_mm")).toDouble(), 50.0);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimPhysics, Guiless)
#include "tst_simphysics.moc"
