#include "motion/motorderived.h"
#include "sim/model/simdevice.h"

#include <QTest>

#include <cmath>

using namespace stepcom;
namespace md = stepcom::motorderived;

// Known answers for the values a technician derives by hand, and the move time against a real
// move on the simulator.
class TstMotorDerived : public QObject
{
    Q_OBJECT

private:
    static void compareOptional(const std::optional<double> &got, double expected)
    {
        if (expected < 0) {
            QVERIFY2(!got,
                     qPrintable(QStringLiteral("expected nothing, got %1").arg(got.value_or(0))));
            return;
        }
        QVERIFY(got.has_value());
        QVERIFY2(std::abs(*got - expected) < 1e-9, qPrintable(QStringLiteral("got %1").arg(*got)));
    }

private Q_SLOTS:
    void pulsesPerRevolution_data()
    {
        QTest::addColumn<double>("stepAngle");
        QTest::addColumn<double>("microsteps");
        QTest::addColumn<double>("expected"); // -1: unknown
        QTest::newRow("1.8°, 8 microsteps") << 1.8 << 8.0 << 1600.0;
        QTest::newRow("1.8°, full steps") << 1.8 << 1.0 << 200.0;
        QTest::newRow("0.9°, 16 microsteps") << 0.9 << 16.0 << 6400.0;
        QTest::newRow("step angle 0") << 0.0 << 8.0 << -1.0;
        QTest::newRow("microsteps 0") << 1.8 << 0.0 << -1.0;
    }
    void pulsesPerRevolution()
    {
        QFETCH(double, stepAngle);
        QFETCH(double, microsteps);
        QFETCH(double, expected);
        compareOptional(md::pulsesPerRevolution(stepAngle, microsteps), expected);
    }

    void speeds_data()
    {
        QTest::addColumn<double>("rpm");
        QTest::addColumn<double>("pulsesPerRev");
        QTest::addColumn<double>("pitch");
        QTest::addColumn<double>("hz");
        QTest::addColumn<double>("perSecond");
        QTest::newRow("300 rpm, 1600 pulses, 5 mm") << 300.0 << 1600.0 << 5.0 << 8000.0 << 25.0;
        QTest::newRow("60 rpm, 200 pulses, 1 mm") << 60.0 << 200.0 << 1.0 << 200.0 << 1.0;
        QTest::newRow("1 rpm, 3200 pulses, 2.5 mm")
            << 1.0 << 3200.0 << 2.5 << 3200.0 / 60 << 2.5 / 60;
        QTest::newRow("speed 0") << 0.0 << 1600.0 << 5.0 << -1.0 << -1.0;
        QTest::newRow("pitch 0") << 300.0 << 1600.0 << 0.0 << 8000.0 << -1.0;
    }
    void speeds()
    {
        QFETCH(double, rpm);
        QFETCH(double, pulsesPerRev);
        QFETCH(double, pitch);
        QFETCH(double, hz);
        QFETCH(double, perSecond);
        compareOptional(md::pulseRateHz(rpm, pulsesPerRev), hz);
        compareOptional(md::unitsPerSecond(rpm, pitch), perSecond);
    }

    void moves_data()
    {
        QTest::addColumn<double>("distance");
        QTest::addColumn<double>("pitch");
        QTest::addColumn<double>("pulsesPerRev");
        QTest::addColumn<double>("revolutions");
        QTest::addColumn<qint64>("pulses"); // 0: none
        QTest::newRow("10 mm on a 5 mm pitch") << 10.0 << 5.0 << 1600.0 << 2.0 << qint64(3200);
        QTest::newRow("manual: pitch 1.00, distance 2.00")
            << 2.0 << 1.0 << 200.0 << 2.0 << qint64(400);
        QTest::newRow("1.01 mm on 4 mm, 6400 pulses")
            << 1.01 << 4.0 << 6400.0 << 0.2525 << qint64(1616);
        // 3.2 pulses: the controller sends whole pulses.
        QTest::newRow("below a pulse") << 0.01 << 5.0 << 1600.0 << 0.002 << qint64(3);
        QTest::newRow("distance 0") << 0.0 << 5.0 << 1600.0 << -1.0 << qint64(0);
        QTest::newRow("pitch 0") << 10.0 << 0.0 << 1600.0 << -1.0 << qint64(0);
    }
    void moves()
    {
        QFETCH(double, distance);
        QFETCH(double, pitch);
        QFETCH(double, pulsesPerRev);
        QFETCH(double, revolutions);
        QFETCH(qint64, pulses);
        compareOptional(md::revolutionsPerMove(distance, pitch), revolutions);
        const auto got = md::pulsesPerMove(distance, pitch, pulsesPerRev);
        QCOMPARE(got.value_or(0), pulses);
    }

    void ramp()
    {
        QCOMPARE(*md::rampTimeMs(400, 80, 8000), 95.0); // docs/simulator.md: 400 → 8000 Hz in 95 ms
        QCOMPARE(*md::rampTimeMs(10000, 80, 8000), 0.0); // start above the speed: no ramp
        QVERIFY(!md::rampTimeMs(400, 0, 8000));
    }

    void deriveFactoryMotor()
    {
        MotorParameters p;
        p.stepAngle = 1.8;
        p.microsteps = 8;
        p.startHz = 400;
        p.accelHzPerMs = 80;
        p.rpm = 300;
        p.pitch = 5;
        p.distance = 10;
        const MotorDerived d = md::derive(p);
        QCOMPARE(*d.pulsesPerRev, 1600.0);
        QCOMPARE(*d.pulseRateHz, 8000.0);
        QCOMPARE(*d.unitsPerSecond, 25.0);
        QCOMPARE(*d.unitsPerMinute, 1500.0);
        QCOMPARE(*d.revolutionsPerMove, 2.0);
        QCOMPARE(*d.pulsesPerMove, qint64(3200));
        QCOMPARE(*d.rampMs, 95.0);
        QVERIFY(d.moveTimeMs && *d.moveTimeMs > 400 && *d.moveTimeMs < 600);

        p.microsteps.reset(); // unknown: everything that needs it is unknown too
        const MotorDerived u = md::derive(p);
        QVERIFY(!u.pulsesPerRev && !u.pulseRateHz && !u.pulsesPerMove && !u.moveTimeMs &&
                !u.rampMs);
        QCOMPARE(*u.unitsPerSecond, 25.0);
        QCOMPARE(*u.revolutionsPerMove, 2.0);
    }

    // The estimate against an actual single move on the simulator (manual clock).
    void moveTimeMatchesTheSimulator_data()
    {
        QTest::addColumn<qint64>("stepAngle"); // raw, ×100
        QTest::addColumn<qint64>("microsteps");
        QTest::addColumn<qint64>("startHz");
        QTest::addColumn<qint64>("accel");
        QTest::addColumn<qint64>("rpm");
        QTest::addColumn<qint64>("pitch");    // raw, ×100
        QTest::addColumn<qint64>("distance"); // raw, ×100
        QTest::newRow("factory: 10 mm")
            << 180LL << 8LL << 400LL << 80LL << 300LL << 500LL << 1000LL;
        QTest::newRow("short move, no cruise")
            << 180LL << 8LL << 400LL << 80LL << 300LL << 500LL << 50LL;
        QTest::newRow("start above the speed: no ramp")
            << 180LL << 8LL << 10000LL << 80LL << 300LL << 500LL << 1000LL;
        QTest::newRow("slow ramp") << 180LL << 8LL << 100LL << 5LL << 600LL << 500LL << 2000LL;
        QTest::newRow("long move, 100 mm")
            << 180LL << 16LL << 500LL << 40LL << 450LL << 400LL << 10000LL;
        QTest::newRow("odd numbers") << 90LL << 4LL << 333LL << 17LL << 137LL << 317LL << 1234LL;
        QTest::newRow("one pulse") << 180LL << 1LL << 400LL << 80LL << 300LL << 500LL << 3LL;
    }
    void moveTimeMatchesTheSimulator()
    {
        QFETCH(qint64, stepAngle);
        QFETCH(qint64, microsteps);
        QFETCH(qint64, startHz);
        QFETCH(qint64, accel);
        QFETCH(qint64, rpm);
        QFETCH(qint64, pitch);
        QFETCH(qint64, distance);
        SimDevice sim;
        const QList<std::pair<const char *, qint64>> values = {{"motor1.step_angle", stepAngle},
                                                               {"motor1.microsteps", microsteps},
                                                               {"motor1.start_frequency", startHz},
                                                               {"motor1.accel_frequency", accel},
                                                               {"motor1.speed", rpm},
                                                               {"motor1.pitch", pitch},
                                                               {"motor1.move_distance", distance},
                                                               {"motor1.limit_positive", 0},
                                                               {"motor1.limit_negative", 0},
                                                               {"motor1.home_input", 0}};
        for (const auto &[key, raw] : values) {
            QString error;
            QVERIFY2(sim.setValue(QLatin1String(key), raw, &error), qPrintable(error));
        }
        QVERIFY(sim.command(QStringLiteral("motor1.move")));
        QVERIFY(sim.running(1));
        qint64 simulated = 0;
        while (sim.running(1) && simulated < 600000) {
            sim.advance(1);
            ++simulated;
        }

        MotorParameters p;
        p.stepAngle = stepAngle / 100.0;
        p.microsteps = double(microsteps);
        p.startHz = double(startHz);
        p.accelHzPerMs = double(accel);
        p.rpm = double(rpm);
        p.pitch = pitch / 100.0;
        p.distance = distance / 100.0;
        const MotorDerived d = md::derive(p);
        QCOMPARE(d.pulsesPerMove.value_or(-1), sim.steps(1));
        QVERIFY(d.moveTimeMs);
        const double estimate = *d.moveTimeMs;
        QVERIFY2(
            std::abs(estimate - double(simulated)) <= 2,
            qPrintable(
                QStringLiteral("estimate %1 ms, simulator %2 ms").arg(estimate).arg(simulated)));
    }

    void hugeMovesStayQuick()
    {
        // A ramp of minutes and a move of hours: estimated, not simulated tick by tick (done
        // tick by tick it would run for hours and hit the test's timeout; no timed assertion).
        const auto slow = md::moveTimeMs(2'000'000'000LL, 1, 1, 1'000'000);
        QVERIFY(slow && std::isfinite(*slow) && *slow > 1e6);
        const auto longCruise = md::moveTimeMs(2'000'000'000LL, 400, 80, 8000);
        QVERIFY(longCruise && std::abs(*longCruise - 2e9 / 8.0) < 200);
        QVERIFY(!md::moveTimeMs(0, 400, 80, 8000));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstMotorDerived, Guiless)
#include "tst_motorderived.moc"
