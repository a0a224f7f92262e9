#include "motion/interpolationpath.h"
#include "sim/model/simdevice.h"

#include <QTest>

#include <cmath>

using namespace stepcom;

// Arc and line interpolation: approach first, then the path, ending at the end point.
class TstSimInterpolation : public QObject
{
    Q_OBJECT

private:
    struct Sample
    {
        double x;
        double y;
    };

    static void set(SimDevice &d, const char *key, qint64 raw)
    {
        QString error;
        QVERIFY2(d.setValue(QLatin1String(key), raw, &error), qPrintable(error));
    }
    static void cmd(SimDevice &d, const char *key)
    {
        QString error;
        QVERIFY2(d.command(QLatin1String(key), &error), qPrintable(error));
    }
    // Runs until both motors are idle, sampling the positions (mm) every millisecond.
    static QList<Sample> run(SimDevice &d, int limitMs = 60000)
    {
        QList<Sample> samples;
        for (int t = 0; t < limitMs && (d.running(1) || d.running(2)); ++t) {
            d.advance(1);
            samples.append({d.position(1) / 100.0, d.position(2) / 100.0});
        }
        return samples;
    }
    static bool visited(const QList<Sample> &s, double x, double y, double tol)
    {
        return std::any_of(s.cbegin(), s.cend(),
                           [&](const Sample &p) { return std::hypot(p.x - x, p.y - y) <= tol; });
    }

private Q_SLOTS:
    void geometry()
    {
        using P = InterpolationPath::Point;
        const auto centre = InterpolationPath::circleCentre(P{0, 0}, P{1, 1}, P{2, 0});
        QVERIFY(centre);
        QCOMPARE(centre->x, 1.0);
        QVERIFY(std::abs(centre->y) < 1e-12);
        QVERIFY(!InterpolationPath::circleCentre(P{0, 0}, P{1, 1}, P{2, 2}));
        const auto ccw = InterpolationPath::arcAroundCentre(P{1, 0}, P{0, 1}, P{0, 0}, true);
        QVERIFY(ccw);
        QVERIFY(std::abs(ccw->length() - M_PI / 2) < 1e-9);
        const auto cw = InterpolationPath::arcAroundCentre(P{1, 0}, P{0, 1}, P{0, 0}, false);
        QVERIFY(std::abs(cw->length() - 3 * M_PI / 2) < 1e-9);
        const auto full = InterpolationPath::arcAroundCentre(P{1, 0}, P{1, 0}, P{0, 0}, false);
        QVERIFY(std::abs(full->length() - 2 * M_PI) < 1e-9);
        QCOMPARE(ccw->pointAt(100).x, 0.0);
        QVERIFY(!InterpolationPath::arcAroundCentre(P{0, 0}, P{1, 1}, P{0, 0}, true));
    }

    void arc_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("direction");
        QTest::addColumn<double>("passY"); // y at x = 40 on the way
        // Factory arc: start (20, 20), end (60, 20), centre (40, 20), middle (40, 40).
        QTest::newRow("centre, clockwise") << 0 << 0 << 40.0;
        QTest::newRow("centre, counter-clockwise") << 0 << 1 << 0.0;
        QTest::newRow("three points, clockwise") << 1 << 0 << 40.0;
        QTest::newRow("three points, counter-clockwise") << 1 << 1 << 0.0;
    }
    void arc()
    {
        QFETCH(int, mode);
        QFETCH(int, direction);
        QFETCH(double, passY);
        SimDevice d;
        set(d, "arc.enabled", 1);
        set(d, "arc.mode", mode);
        set(d, "arc.direction", direction);
        if (mode == 1) // a centre register that would be wrong proves mode 1 ignores it
            set(d, "arc.center_x", -5000);
        d.setMachinePosition(2, 100); // room below the start point for the CCW arc
        cmd(d, "arc.start");
        QVERIFY(d.running(1) && d.running(2));
        const QList<Sample> s = run(d);
        QVERIFY(!s.isEmpty());
        QVERIFY(!d.running(1) && !d.running(2));
        QCOMPARE(d.position(1), 6000);
        QCOMPARE(d.position(2), 2000);
        QVERIFY(visited(s, 20, 20, 0.001)); // the approach reached the start point first
        QVERIFY(visited(s, 40, passY, 0.05));
        // On the circle (radius 20 around (40, 20)) once the path began.
        const auto begin = std::find_if(s.cbegin(), s.cend(), [](const Sample &p) {
            return std::hypot(p.x - 20, p.y - 20) < 0.001;
        });
        double worst = 0;
        for (auto it = begin; it != s.cend(); ++it)
            worst = std::max(worst, std::abs(std::hypot(it->x - 40, it->y - 20) - 20));
        QVERIFY2(worst < 0.02, qPrintable(QString::number(worst)));
        // Half a circle of radius 20 at 60 rpm x 5 mm = 5 mm/s: 12.57 s plus the ramps.
        const qint64 pathMs = s.cend() - begin;
        QVERIFY2(pathMs > 12500 && pathMs < 12800, qPrintable(QString::number(pathMs)));
    }

    void fullCircle()
    {
        SimDevice d;
        set(d, "arc.enabled", 1);
        set(d, "arc.end_x", 2000);
        set(d, "arc.direction", 1);
        set(d, "arc.speed", 600);
        d.setMachinePosition(2, 100);
        cmd(d, "arc.start");
        const QList<Sample> s = run(d);
        QCOMPARE(d.position(1), 2000);
        QCOMPARE(d.position(2), 2000);
        QVERIFY(visited(s, 60, 20, 0.05));
        QVERIFY(visited(s, 40, 0, 0.05));
        QVERIFY(visited(s, 40, 40, 0.05));
    }

    void line()
    {
        SimDevice d;
        set(d, "line.enabled", 1);
        set(d, "line.speed", 300);
        cmd(d, "line.start");
        const QList<Sample> s = run(d);
        QCOMPARE(d.position(1), 8000);
        QCOMPARE(d.position(2), 6000);
        QVERIFY(visited(s, 20, 20, 0.001));
        // Straight from (20, 20) to (80, 60) after the start point.
        const auto begin = std::find_if(s.cbegin(), s.cend(), [](const Sample &p) {
            return std::hypot(p.x - 20, p.y - 20) < 0.001;
        });
        double worst = 0;
        for (auto it = begin; it != s.cend(); ++it)
            worst = std::max(worst,
                             std::abs((it->x - 20) * 40 - (it->y - 20) * 60) / std::hypot(60, 40));
        QVERIFY2(worst < 0.01, qPrintable(QString::number(worst)));
    }

    void disabledOrDegenerateDoesNothing()
    {
        SimDevice d;
        cmd(d, "arc.start"); // arc.enabled is 0 from the factory
        cmd(d, "line.start");
        QVERIFY(!d.running(1) && !d.running(2));
        set(d, "arc.enabled", 1);
        set(d, "arc.mode", 1);
        set(d, "arc.middle_y", 2000); // on the line through start and end: no circle
        cmd(d, "arc.start");
        QVERIFY(!d.running(1) && !d.running(2));
    }

    void stopsStopBoth()
    {
        SimDevice d;
        set(d, "line.enabled", 1);
        cmd(d, "line.start");
        d.advance(3000);
        cmd(d, "arc.stop"); // the arc's stop leaves a line alone
        QVERIFY(d.running(1));
        cmd(d, "line.stop");
        QVERIFY(!d.running(1) && !d.running(2));
        set(d, "arc.enabled", 1);
        cmd(d, "arc.start");
        d.advance(8000);
        QVERIFY(d.running(1) && d.running(2));
        cmd(d, "motor2.stop"); // one axis stopped stops the interpolation
        QVERIFY(!d.running(1) && !d.running(2));
        const qint64 x = d.position(1);
        d.advance(1000);
        QCOMPARE(d.position(1), x);
    }

    void limitStopsInterpolation()
    {
        SimDevice d;
        set(d, "line.enabled", 1);
        set(d, "line.end_x", 30000); // 300 mm: beyond the travel
        set(d, "line.speed", 1200);
        cmd(d, "line.start");
        run(d);
        QVERIFY(d.input(1));
        QVERIFY(d.position(1) < 30000);
        QVERIFY(d.machinePosition(1) <= 200.1);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimInterpolation, Guiless)
#include "tst_siminterpolation.moc"
