#include "sim/model/simdevice.h"

#include "simdevicechecks.h"
#include "testmaps.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

// The motion model and the virtual machine, on a manual clock.
class TstSimMotion : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void factoryValues()
    {
        SimDevice d;
        QCOMPARE(value(d, "motor1.step_angle"), 180);
        QCOMPARE(value(d, "motor1.microsteps"), 8);
        QCOMPARE(value(d, "motor1.pitch"), 500);
        QCOMPARE(value(d, "motor1.move_distance"), 1000);
        QCOMPARE(value(d, "motor1.limit_positive"), 1);
        QCOMPARE(value(d, "motor1.limit_negative"), 2);
        QCOMPARE(value(d, "motor2.limit_positive"), 3);
        QCOMPARE(value(d, "motor2.home_input"), 4);
        QCOMPARE(value(d, "device.id"), 1);
        QCOMPARE(value(d, "device.baud"), 9600);
        QCOMPARE(value(d, "motor1.position"), 0);
        QCOMPARE(value(d, "motor1.running"), 0);
    }

    void singleMoveEndsWherePhysicsSays_data()
    {
        QTest::addColumn<qint64>("stepAngle");
        QTest::addColumn<qint64>("microsteps");
        QTest::addColumn<qint64>("pitch");
        QTest::addColumn<qint64>("distance");
        QTest::addColumn<qint64>("direction");
        QTest::addColumn<qint64>("steps");
        QTest::addColumn<qint64>("position");
        QTest::newRow("factory: 10 mm on 5 mm pitch")
            << 180LL << 8LL << 500LL << 1000LL << 0LL << 3200LL << 1000LL;
        QTest::newRow("manual example: pitch 1, distance 2")
            << 180LL << 1LL << 100LL << 200LL << 0LL << 400LL << 200LL;
        QTest::newRow("reverse direction")
            << 180LL << 8LL << 500LL << 1000LL << 1LL << -3200LL << -1000LL;
        QTest::newRow("0.9 deg x16, 4 mm pitch, 1.01 mm")
            << 90LL << 16LL << 400LL << 101LL << 0LL << 1616LL << 101LL;
        // 0.01 mm is 3.2 steps: the controller sends whole pulses, so 3 (0.009375 -> 0.01).
        QTest::newRow("less than a step resolution")
            << 180LL << 8LL << 500LL << 1LL << 0LL << 3LL << 1LL;
    }
    void singleMoveEndsWherePhysicsSays()
    {
        QFETCH(qint64, stepAngle);
        QFETCH(qint64, microsteps);
        QFETCH(qint64, pitch);
        QFETCH(qint64, distance);
        QFETCH(qint64, direction);
        QFETCH(qint64, steps);
        QFETCH(qint64, position);
        SimDevice d;
        set(d, "motor1.step_angle", stepAngle);
        set(d, "motor1.microsteps", microsteps);
        set(d, "motor1.pitch", pitch);
        set(d, "motor1.move_distance", distance);
        set(d, "motor1.direction", direction);
        cmd(d, "motor1.move");
        QVERIFY(d.running(1));
        QCOMPARE(value(d, "motor1.running"), 1);
        d.advance(20000);
        QVERIFY(!d.running(1));
        QCOMPARE(d.steps(1), steps);
        QCOMPARE(value(d, "motor1.position"), position);
        QCOMPARE(d.position(2), 0); // the other motor stays
    }

    void moveTakesRampAndCruiseTime()
    {
        // 300 rpm x 1600 pulses/rev = 8000 Hz; ramp 400 -> 8000 Hz at 80 Hz/ms = 95 ms each
        // way covering ~400 steps; the remaining 2400 steps at 8 steps/ms take 300 ms.
        SimDevice d;
        cmd(d, "motor1.move");
        d.advance(10);
        // After 10 ms of ramp: about 10 x (0.4 + 0.4 + 0.8) / 2 ... far below full speed.
        QVERIFY2(d.steps(1) < 10 * 8 / 2, qPrintable(QString::number(d.steps(1))));
        QVERIFY(d.steps(1) > 10 * 0.4);
        d.advance(450 - 10);
        QVERIFY(d.running(1));
        d.advance(70);
        QVERIFY(!d.running(1));
        QCOMPARE(d.position(1), 1000);
    }

    void registersFollowParameterChangesAtOnce()
    {
        SimDevice d;
        cmd(d, "motor1.move");
        d.advance(2000);
        QCOMPARE(value(d, "motor1.position"), 1000);
        set(d, "motor1.pitch", 1000); // the same pulses are twice the distance now
        QCOMPARE(value(d, "motor1.position"), 2000);
        d.setMachinePosition(2, 0); // on the negative switch of motor 2, wired to IN4
        QCOMPARE(value(d, "io.in4"), 1);
        set(d, "motor2.limit_negative", 3);
        set(d, "motor2.home_input", 3);
        QCOMPARE(value(d, "io.in4"), 0);
        QCOMPARE(value(d, "io.in3"), 1);
    }

    void speedChangeActsWhileRunning()
    {
        SimDevice d;
        cmd(d, "motor1.forward");
        d.advance(200);
        const qint64 a = d.steps(1);
        d.advance(100);
        const qint64 slow = d.steps(1) - a; // 8 steps/ms
        set(d, "motor1.speed", 150);
        d.advance(200); // ramps down
        const qint64 b = d.steps(1);
        d.advance(100);
        const qint64 slower = d.steps(1) - b;
        QCOMPARE(slow, 800);
        QCOMPARE(slower, 400);
    }

    void forwardStopsAtPositiveLimit()
    {
        SimDevice d;
        QCOMPARE(d.machinePosition(1), 50.0);
        cmd(d, "motor1.forward");
        d.advance(60000);
        QVERIFY(!d.running(1));
        QVERIFY(d.input(1));
        QCOMPARE(value(d, "io.in1"), 1);
        // Stopped within one millisecond of travel (8 steps = 0.025 mm) past the switch.
        QVERIFY(d.machinePosition(1) >= 200.0);
        QVERIFY(d.machinePosition(1) <= 200.03);
        QVERIFY(qAbs(d.position(1) - 15000) <= 3);
        // Only reverse is allowed now.
        cmd(d, "motor1.forward");
        QVERIFY(!d.running(1));
        cmd(d, "motor1.reverse");
        QVERIFY(d.running(1));
        d.advance(100);
        QVERIFY(!d.input(1));
    }

    void reverseStopsAtNegativeLimitAndForcedInput()
    {
        SimDevice d;
        cmd(d, "motor2.reverse");
        d.advance(60000);
        QVERIFY(!d.running(2));
        QVERIFY(d.input(4));
        QVERIFY(d.machinePosition(2) <= 0 && d.machinePosition(2) >= -0.03);
        // A limit input forced by hand stops a move too.
        cmd(d, "motor1.forward");
        d.advance(100);
        d.setInput(1, SimDevice::InputForce::On);
        QVERIFY(!d.running(1));
        d.setInput(1, SimDevice::InputForce::Off);
    }

    void unwiredLimitStallsAtHardStop()
    {
        SimDevice d;
        set(d, "motor1.limit_positive", 0);
        cmd(d, "motor1.forward");
        d.advance(30000); // 8 steps/ms x 30 s = 240000 steps = 750 mm of pulses
        QVERIFY(d.running(1));
        QCOMPARE(d.machinePosition(1), 205.0); // against the hard stop
        QVERIFY(d.position(1) > 70000);        // the open-loop counter went on
        cmd(d, "motor1.stop");
        QVERIFY(!d.running(1));
    }

    void homingZeroes()
    {
        SimDevice d;
        cmd(d, "motor1.move");
        d.advance(1000);
        QCOMPARE(d.position(1), 1000);
        cmd(d, "motor1.home");
        QVERIFY(d.running(1));
        d.advance(30000);
        QVERIFY(!d.running(1));
        QCOMPARE(d.position(1), 0);
        QCOMPARE(d.steps(1), 0);
        QVERIFY(d.machinePosition(1) <= 0 && d.machinePosition(1) >= -0.03);
        // Homing where the switch is already on: zero at once.
        cmd(d, "motor1.home");
        QVERIFY(!d.running(1));
        QCOMPARE(d.position(1), 0);
    }

    void homingStoppedDoesNotZero()
    {
        SimDevice d;
        cmd(d, "motor1.home");
        d.advance(1000);
        cmd(d, "motor1.stop");
        QVERIFY(!d.running(1));
        QVERIFY(d.position(1) < -1000);
    }

    void homeAllFollowsOrder()
    {
        SimDevice d;
        set(d, "homing.first", 2);
        set(d, "homing.second", 1);
        d.setMachinePosition(1, 10);
        d.setMachinePosition(2, 10);
        cmd(d, "home_all");
        d.advance(100);
        QVERIFY(d.running(2));
        QVERIFY(!d.running(1));
        d.advance(500); // 10 mm take about 450 ms
        QVERIFY(!d.running(2));
        QCOMPARE(d.position(2), 0);
        QVERIFY(d.running(1));
        d.advance(3000);
        QVERIFY(!d.running(1));
        QCOMPARE(d.position(1), 0);
        QVERIFY(d.machinePosition(1) <= 0);
    }

    void homeAllSkipsMotorsNotInOrder()
    {
        SimDevice d;
        set(d, "homing.first", 0);
        set(d, "homing.second", 2);
        cmd(d, "motor1.move");
        d.advance(1000);
        cmd(d, "home_all");
        d.advance(100);
        QVERIFY(!d.running(1));
        QVERIFY(d.running(2));
        d.advance(30000);
        QCOMPARE(d.position(1), 1000); // stayed
        QCOMPARE(d.position(2), 0);
        QVERIFY(d.machinePosition(2) <= 0);
    }

    void returnToDataZeroAndZeroCoordinates()
    {
        SimDevice d;
        cmd(d, "motor1.move");
        set(d, "motor2.direction", 1);
        cmd(d, "motor2.move");
        d.advance(2000);
        QCOMPARE(d.position(1), 1000);
        QCOMPARE(d.position(2), -1000);
        cmd(d, "return_to_zero");
        d.advance(2000);
        QCOMPARE(d.position(1), 0);
        QCOMPARE(d.position(2), 0);
        QCOMPARE(d.machinePosition(1), 50.0);
        cmd(d, "motor1.move");
        d.advance(2000);
        cmd(d, "zero_coordinates");
        QCOMPARE(d.position(1), 0);
        QCOMPARE(d.machinePosition(1), 60.0);
    }

    void emergencyStopStopsAllAndOutputsOff()
    {
        SimDevice d;
        cmd(d, "outputs_all_on");
        QVERIFY(d.output(1) && d.output(2) && d.output(3));
        QCOMPARE(value(d, "io.out3"), 1);
        cmd(d, "motor1.forward");
        cmd(d, "motor2.reverse");
        d.advance(100);
        cmd(d, "estop");
        QVERIFY(!d.running(1) && !d.running(2));
        QVERIFY(!d.output(1) && !d.output(2) && !d.output(3));
        const qint64 p = d.position(1);
        d.advance(1000);
        QCOMPARE(d.position(1), p); // immediate: no ramp down
    }

    void outputCoils()
    {
        SimDevice d;
        cmd(d, "output1_on");
        QVERIFY(d.output(1));
        QVERIFY(!d.output(2));
        QCOMPARE(value(d, "io.out1"), 1);
        cmd(d, "output1_off");
        QVERIFY(!d.output(1));
        cmd(d, "outputs_all_on");
        cmd(d, "outputs_all_off");
        QVERIFY(!d.output(1) && !d.output(2) && !d.output(3));
    }

    void commandToMovingAxisIsIgnored()
    {
        SimDevice d;
        cmd(d, "motor1.forward");
        d.advance(100);
        cmd(d, "motor1.reverse");
        d.advance(100);
        QVERIFY(d.steps(1) > 0);
        QVERIFY(d.running(1));
    }

    void threeMotorMapGivesThreeAxes()
    {
        QStringList errors;
        const auto map = stepcom::test::builtinMapWithMotors(3, &errors);
        QVERIFY2(map, qPrintable(errors.join(QLatin1Char('\n'))));
        SimDevice d(*map);
        QCOMPARE(d.motorCount(), 3);
        QCOMPARE(value(d, "motor3.limit_positive"), 0); // only four inputs for six switches
        cmd(d, "motor3.move");
        d.advance(2000);
        QCOMPARE(d.position(3), 1000);
        QCOMPARE(value(d, "motor3.position"), 1000);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimMotion, Guiless)
#include "tst_simmotion.moc"
