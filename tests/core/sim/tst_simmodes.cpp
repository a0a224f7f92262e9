#include "sim/model/simdevice.h"

#include <QTest>

using namespace stepcom;

// Special modes 1-5 (register 40300) driven by inputs, as the manual describes them.
class TstSimModes : public QObject
{
    Q_OBJECT

private:
    using F = SimDevice::InputForce;

    static void set(SimDevice &d, const char *key, qint64 raw)
    {
        QString error;
        QVERIFY2(d.setValue(QLatin1String(key), raw, &error), qPrintable(error));
    }
    static void pulse(SimDevice &d, int input)
    {
        d.setInput(input, F::Pulse);
        d.advance(SimMachine::kPulseMs + 1);
    }
    static int direction(SimDevice &d)
    {
        const qint64 a = d.steps(1);
        d.advance(20);
        const qint64 b = d.steps(1);
        return b > a ? 1 : (b < a ? -1 : 0);
    }

private Q_SLOTS:
    void mode1RoundTrips()
    {
        SimDevice d;
        set(d, "mode.system", 1);
        set(d, "mode.round_trips", 2);
        set(d, "motor1.speed", 1200);       // 0.1 mm/ms: 2 s for the 200 mm travel
        set(d, "motor1.limit_positive", 0); // mode 1 ignores the limit registers
        d.advance(1000);
        QVERIFY(!d.running(1)); // waits for IN4
        pulse(d, 4);
        QVERIFY(d.running(1));
        QCOMPARE(direction(d), 1);
        double top = 0;
        int reversals = 0;
        int last = 1;
        for (int t = 0; t < 20000 && d.running(1); t += 10) {
            const int dir = direction(d);
            if (dir != 0 && dir != last) {
                ++reversals;
                last = dir;
            }
            top = std::max(top, d.machinePosition(1));
        }
        QVERIFY(!d.running(1));
        QCOMPARE(reversals, 3); // fwd, rev, fwd, rev
        QVERIFY(top >= 200.0);
        QVERIFY(d.machinePosition(1) <= 0.0); // ended on the negative limit (IN2)
        QVERIFY(d.input(2));
    }

    void mode1EndlessAndIn3Stops()
    {
        SimDevice d;
        set(d, "mode.system", 1);
        set(d, "motor1.speed", 1200);
        pulse(d, 4);
        d.advance(15000); // several trips
        QVERIFY(d.running(1));
        pulse(d, 3);
        QVERIFY(!d.running(1));
        d.advance(1000);
        QVERIFY(!d.running(1));
    }

    void mode2SingleTrigger()
    {
        SimDevice d;
        set(d, "mode.system", 2);
        pulse(d, 1);
        QCOMPARE(direction(d), 1); // forward the first time
        pulse(d, 2);
        QVERIFY(!d.running(1));
        pulse(d, 1);
        QCOMPARE(direction(d), 1); // IN2: same as last time
        pulse(d, 3);
        QVERIFY(!d.running(1));
        pulse(d, 1);
        QCOMPARE(direction(d), -1); // IN3: reverse of last time
        pulse(d, 3);
        pulse(d, 1);
        QCOMPARE(direction(d), 1); // reverse of reverse
        pulse(d, 2);
        pulse(d, 1);
        QCOMPARE(direction(d), 1);
        pulse(d, 3);
        pulse(d, 1);
        QCOMPARE(direction(d), -1);
        pulse(d, 4);
        QVERIFY(!d.running(1));
        pulse(d, 1);
        QCOMPARE(direction(d), 1); // IN4: forward
    }

    void mode2IgnoresLimits()
    {
        SimDevice d;
        set(d, "mode.system", 2);
        set(d, "motor1.speed", 1200);
        pulse(d, 1);
        d.advance(3000);
        QVERIFY(d.running(1)); // past the switch at 200: nothing stops it
        QCOMPARE(d.machinePosition(1), 205.0);
    }

    void mode3ForwardReverseTrigger()
    {
        SimDevice d;
        set(d, "mode.system", 3);
        set(d, "motor1.speed", 1200);
        pulse(d, 1);
        QCOMPARE(direction(d), 1);
        pulse(d, 2); // immediately reverse
        QCOMPARE(direction(d), -1);
        d.advance(5000);
        QVERIFY(!d.running(1)); // IN4 (negative limit) stopped the reverse run
        QVERIFY(d.input(4));
        QVERIFY(d.machinePosition(1) <= 0);
        pulse(d, 2);
        QVERIFY(!d.running(1)); // only forward allowed now
        pulse(d, 1);
        QCOMPARE(direction(d), 1);
        d.advance(5000);
        QVERIFY(!d.running(1)); // IN3 (positive limit)
        QVERIFY(d.input(3));
        QVERIFY(!d.input(1)); // the limit registers (IN1) are not used
        pulse(d, 1);
        QVERIFY(!d.running(1));
        pulse(d, 2);
        QCOMPARE(direction(d), -1);
    }

    void mode3LimitByHand()
    {
        SimDevice d;
        set(d, "mode.system", 3);
        pulse(d, 1);
        QVERIFY(d.running(1));
        d.setInput(3, F::On);
        QVERIFY(!d.running(1));
    }

    void mode4HoldToJog()
    {
        SimDevice d;
        set(d, "mode.system", 4);
        d.setInput(1, F::On);
        QCOMPARE(direction(d), 1);
        d.advance(500);
        QVERIFY(d.running(1));
        d.setInput(1, F::Off);
        QVERIFY(!d.running(1)); // released: stop
        d.setInput(2, F::On);
        QCOMPARE(direction(d), -1);
        d.setInput(2, F::Off);
        QVERIFY(!d.running(1));
        // Held into the positive limit (IN3): stops and stays stopped while still held.
        set(d, "motor1.speed", 1200);
        d.setInput(1, F::On);
        d.advance(5000);
        QVERIFY(!d.running(1));
        QVERIFY(d.input(3));
        d.advance(100);
        QVERIFY(!d.running(1));
        d.setInput(1, F::Off);
        d.setInput(2, F::On);
        QCOMPARE(direction(d), -1);
    }

    void mode5FixedDistance()
    {
        SimDevice d;
        set(d, "mode.system", 5);
        pulse(d, 1);
        QVERIFY(d.running(1));
        pulse(d, 2); // ignored during the move
        d.advance(2000);
        QCOMPARE(d.position(1), 1000);
        pulse(d, 2);
        d.advance(2000);
        QCOMPARE(d.position(1), 0);
        pulse(d, 2);
        d.advance(2000);
        QCOMPARE(d.position(1), -1000);
        // Near the positive end a triggered move stops at the limit (IN3).
        d.setMachinePosition(1, 195);
        pulse(d, 1);
        d.advance(2000);
        QVERIFY(d.input(3));
        QVERIFY(d.position(1) < 0 && d.position(1) > -600);
    }

    void enteringAModeIsNoTrigger()
    {
        SimDevice d;
        d.setInput(1, F::On); // held before the mode is chosen
        set(d, "mode.system", 3);
        QVERIFY(!d.running(1));
        d.setInput(1, F::Off);
        pulse(d, 1);
        QVERIFY(d.running(1));
        d.command(QStringLiteral("estop"));
        QVERIFY(!d.running(1));
        pulse(d, 1); // the first trigger after an emergency stop counts
        QVERIFY(d.running(1));
    }

    void modeChangeStopsModeMotion()
    {
        SimDevice d;
        set(d, "mode.system", 2);
        pulse(d, 1);
        QVERIFY(d.running(1));
        set(d, "mode.system", 0);
        QVERIFY(!d.running(1));
        // In mode 0 inputs do nothing by themselves.
        pulse(d, 4);
        pulse(d, 1);
        QVERIFY(!d.running(1));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimModes, Guiless)
#include "tst_simmodes.moc"
