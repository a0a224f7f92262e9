#include "motion/interpolationtiming.h"
#include "motion/motorderived.h"
#include "motion/trapezoid.h"

#include <QPointF>
#include <QTest>

#include <cmath>

using namespace stepcom;
using namespace stepcom::interpolation;
namespace md = stepcom::motorderived;

namespace {

// The known answers were recorded from the code before it moved to core/motion.
constexpr double kTimingTol = 1e-9;

MotorParameters factoryMotor()
{
    MotorParameters m;
    m.stepAngle = 1.8;
    m.microsteps = 8;
    m.startHz = 400;
    m.accelHzPerMs = 80;
    m.rpm = 300;
    m.pitch = 5;
    m.distance = 10;
    return m;
}

MotorParameters oddMotor()
{
    MotorParameters m;
    m.stepAngle = 0.9;
    m.microsteps = 4;
    m.startHz = 333;
    m.accelHzPerMs = 17;
    m.rpm = 137;
    m.pitch = 3.17;
    m.distance = 12.34;
    return m;
}

MotorParameters motorNamed(const QString &name)
{
    if (name == QLatin1String("odd"))
        return oddMotor();
    MotorParameters m = factoryMotor();
    if (name == QLatin1String("no pitch"))
        m.pitch.reset();
    return m;
}

} // namespace

// The approach, ramps and move times, and the derived values of a motor.
class TstMotionTiming : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void approaches_data()
    {
        QTest::addColumn<QPointF>("from");
        QTest::addColumn<QPointF>("to");
        QTest::addColumn<QString>("motor1");
        QTest::addColumn<QString>("motor2");
        QTest::addColumn<bool>("exact");
        QTest::addColumn<double>("timeMs"); // -1: not known
        QTest::addColumn<QList<QPointF>>("points");
        QTest::newRow("x arrives first, then y alone")
            << QPointF(0, 0) << QPointF(20, 5) << "factory"
            << "factory" << true << 886.0
            << QList<QPointF>{{0, 0}, {6.0218749999999996, 5}, {20, 5}};
        QTest::newRow("different motors, y last")
            << QPointF(-3, 12.5) << QPointF(7.25, -1) << "factory"
            << "odd" << true << 2039.0
            << QList<QPointF>{{-3, 12.5}, {7.25, 9.5522962564746727}, {7.25, -1}};
        QTest::newRow("only x moves: no corner")
            << QPointF(0, 0) << QPointF(15, 0) << "factory"
            << "odd" << true << 686.0 << QList<QPointF>{{0, 0}, {15, 0}};
        QTest::newRow("within half a count: already there")
            << QPointF(2, 3) << QPointF(2.001, 3.002) << "factory"
            << "odd" << false << -1.0 << QList<QPointF>{{2, 3}};
        QTest::newRow("motor 2 unknown: equal speeds, y last")
            << QPointF(0, 0) << QPointF(20, 5) << "factory"
            << "no pitch" << false << -1.0 << QList<QPointF>{{0, 0}, {5, 5}, {20, 5}};
        QTest::newRow("motor 1 unknown: equal speeds, x last")
            << QPointF(0, 0) << QPointF(4, 20) << "no pitch"
            << "factory" << false << -1.0 << QList<QPointF>{{0, 0}, {4, 4}, {4, 20}};
    }
    void approaches()
    {
        QFETCH(QPointF, from);
        QFETCH(QPointF, to);
        QFETCH(QString, motor1);
        QFETCH(QString, motor2);
        QFETCH(bool, exact);
        QFETCH(double, timeMs);
        QFETCH(QList<QPointF>, points);
        const Approach a = approach({from.x(), from.y()}, {to.x(), to.y()}, motorNamed(motor1),
                                    motorNamed(motor2));
        QCOMPARE(a.exact, exact);
        QCOMPARE(a.timeMs.value_or(-1), timeMs);
        QCOMPARE(a.points.size(), points.size());
        for (int i = 0; i < points.size(); ++i) {
            QVERIFY2(std::abs(a.points.at(i).x - points.at(i).x()) <= kTimingTol &&
                         std::abs(a.points.at(i).y - points.at(i).y()) <= kTimingTol,
                     qPrintable(QStringLiteral("point %1: (%2, %3)")
                                    .arg(i)
                                    .arg(a.points.at(i).x, 0, 'g', 17)
                                    .arg(a.points.at(i).y, 0, 'g', 17)));
        }
    }

    // Move times in the simulator's 1 ms ticks.
    void moveTimes_data()
    {
        QTest::addColumn<qint64>("pulses");
        QTest::addColumn<double>("startHz");
        QTest::addColumn<double>("accel");
        QTest::addColumn<double>("topHz");
        QTest::addColumn<double>("ms");
        QTest::newRow("trapezoid: ramp, cruise, brake")
            << 3200LL << 400.0 << 80.0 << 8000.0 << 486.0;
        QTest::newRow("triangle: too short for the top rate")
            << 160LL << 400.0 << 80.0 << 8000.0 << 80.0;
        QTest::newRow("start above the top rate: no ramp")
            << 3200LL << 10000.0 << 80.0 << 8000.0 << 400.0;
        QTest::newRow("odd numbers") << 3893LL << 333.0 << 17.0 << 2283.3333333333335 << 1801.0;
        QTest::newRow("one pulse") << 1LL << 400.0 << 80.0 << 8000.0 << 3.0;
        QTest::newRow("minutes of ramp: the continuous trapezoid")
            << 2000000000LL << 1.0 << 1.0 << 1000000.0 << 2999998.0000010002;
    }
    void moveTimes()
    {
        QFETCH(qint64, pulses);
        QFETCH(double, startHz);
        QFETCH(double, accel);
        QFETCH(double, topHz);
        QFETCH(double, ms);
        const std::optional<double> got = md::moveTimeMs(pulses, startHz, accel, topHz);
        QVERIFY(got);
        QVERIFY2(std::abs(*got - ms) <= kTimingTol * std::max(1.0, ms),
                 qPrintable(QString::number(*got, 'g', 17)));
    }

    void rampTimes_data()
    {
        QTest::addColumn<double>("startHz");
        QTest::addColumn<double>("accel");
        QTest::addColumn<double>("topHz");
        QTest::addColumn<double>("ms");
        QTest::newRow("factory") << 400.0 << 80.0 << 8000.0 << 95.0;
        QTest::newRow("odd") << 333.0 << 17.0 << 2283.3333333333335 << 114.72549019607844;
        QTest::newRow("start above the top: none") << 10000.0 << 80.0 << 8000.0 << 0.0;
    }
    void rampTimes()
    {
        QFETCH(double, startHz);
        QFETCH(double, accel);
        QFETCH(double, topHz);
        QFETCH(double, ms);
        QVERIFY(std::abs(md::rampTimeMs(startHz, accel, topHz).value_or(-1) - ms) <= kTimingTol);
    }

    // The continuous trapezoid, worked by hand: 400 Hz → 8000 Hz at 80 Hz/ms is 0.4 → 8 pulses
    // per ms in 95 ms over 399 pulses each way.
    void trapezoid()
    {
        const RampRates r = RampRates::fromHz(400, 8000, 80);
        const Trapezoid t(3200, r);
        QVERIFY(t.reachesTop());
        QCOMPARE(t.rampMs(), 95.0);
        QCOMPARE(t.cruiseMs(), 300.25); // (3200 - 2 × 399) / 8
        QCOMPARE(t.durationMs(), 490.25);
        QCOMPARE(t.travelledAt(95), 399.0);
        QCOMPARE(t.travelledAt(95 + 300.25), 3200.0 - 399.0);
        QCOMPARE(t.travelledAt(t.durationMs()), 3200.0);

        const Trapezoid tri(160, r); // peak √(0.4² + 0.08 × 160) = 3.6 pulses per ms
        QVERIFY(!tri.reachesTop());
        QVERIFY(std::abs(tri.peakRate() - 3.6) <= kTimingTol);
        QVERIFY(std::abs(tri.durationMs() - 80) <= kTimingTol);
        QVERIFY(std::abs(tri.travelledAt(40) - 80) <= kTimingTol); // half way at half time

        const Trapezoid flat(3200, RampRates::fromHz(10000, 8000, 80)); // start above the top
        QCOMPARE(flat.rampMs(), 0.0);
        QCOMPARE(flat.durationMs(), 400.0);
        const RampRates mm = r.scaled(1.0 / 320); // factory motor: 320 pulses per mm
        QCOMPARE(mm.top, 8.0 / 320);
        QCOMPARE(mm.effectiveStart(), 0.4 / 320);
    }

    void pathTimes()
    {
        const MotorParameters f = factoryMotor();
        QCOMPARE(pathTimeMs(5 * 3.14159265358979323846, 120, f).value_or(-1), 1602.0);
        QCOMPARE(pathTimeMs(72.111025509279784, 300, f).value_or(-1), 2972.0);
        QCOMPARE(pathTimeMs(0.5, 300, oddMotor()).value_or(-1), 205.0);
        QVERIFY(std::abs(pathUnitsPerSecond(120, oddMotor()).value_or(-1) - 6.34) <= kTimingTol);
        QVERIFY(!pathTimeMs(10, 300, motorNamed("no pitch")));
        QVERIFY(!pathTimeMs(0, 300, f));
    }

    void derived_data()
    {
        QTest::addColumn<QString>("motor");
        QTest::addColumn<double>("pulsesPerRev");
        QTest::addColumn<double>("pulseRateHz");
        QTest::addColumn<double>("unitsPerSecond");
        QTest::addColumn<double>("unitsPerMinute");
        QTest::addColumn<double>("revolutionsPerMove");
        QTest::addColumn<qint64>("pulsesPerMove");
        QTest::addColumn<double>("rampMs");
        QTest::addColumn<double>("moveTimeMs");
        QTest::newRow("factory") << "factory" << 1600.0 << 8000.0 << 25.0 << 1500.0 << 2.0 << 3200LL
                                 << 95.0 << 486.0;
        QTest::newRow("odd") << "odd" << 1600.0 << 3653.3333333333335 << 7.2381666666666664
                             << 434.28999999999996 << 3.8927444794952684 << 6228LL
                             << 195.31372549019608 << 1880.0;
    }
    void derived()
    {
        QFETCH(QString, motor);
        QFETCH(double, pulsesPerRev);
        QFETCH(double, pulseRateHz);
        QFETCH(double, unitsPerSecond);
        QFETCH(double, unitsPerMinute);
        QFETCH(double, revolutionsPerMove);
        QFETCH(qint64, pulsesPerMove);
        QFETCH(double, rampMs);
        QFETCH(double, moveTimeMs);
        const MotorDerived d = md::derive(motorNamed(motor));
        auto near = [](const std::optional<double> &got, double want) {
            return got && std::abs(*got - want) <= kTimingTol * std::max(1.0, want);
        };
        QVERIFY(near(d.pulsesPerRev, pulsesPerRev));
        QVERIFY(near(d.pulseRateHz, pulseRateHz));
        QVERIFY(near(d.unitsPerSecond, unitsPerSecond));
        QVERIFY(near(d.unitsPerMinute, unitsPerMinute));
        QVERIFY(near(d.revolutionsPerMove, revolutionsPerMove));
        QCOMPARE(d.pulsesPerMove.value_or(-1), pulsesPerMove);
        QVERIFY(near(d.rampMs, rampMs));
        QVERIFY(near(d.moveTimeMs, moveTimeMs));
    }

    // Whole pulses and the position register, as the controller counts them.
    void pulsesAndCounts()
    {
        QCOMPARE(md::pulsesPerUnit(1600, 5).value_or(0), 320.0);
        QVERIFY(!md::pulsesPerUnit(1600, 0));
        const double spu = 1600.0 / 3; // 1.8°, 8 microsteps, pitch 3
        QCOMPARE(md::wholePulses(10.01, spu), 5339.0);
        QCOMPARE(md::positionCounts(5339, spu), qint64(1001));
        QCOMPARE(md::wholePulses(-0.02, 200.0 / 7), -1.0);
        QCOMPARE(md::positionCounts(-1, 200.0 / 7), qint64(-3)); // the simulator showed -3
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstMotionTiming, Guiless)
#include "tst_motiontiming.moc"
