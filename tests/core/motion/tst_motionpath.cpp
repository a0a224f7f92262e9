#include "map/registermap.h"
#include "motion/interpolationtiming.h"
#include "motion/pathsetup.h"

#include <QHash>
#include <QPointF>
#include <QTest>

#include <cmath>

using namespace stepcom;
using namespace stepcom::interpolation;

namespace {

// The known answers were recorded from the code before it moved to core/motion (the
// simulator's InterpolationPath and the editor's checks); the end counts from simulator runs.
constexpr double kTol = 1e-9;

Point pt(const QPointF &p)
{
    return {p.x(), p.y()};
}

bool near(Point got, const QPointF &want)
{
    return std::abs(got.x - want.x()) <= kTol && std::abs(got.y - want.y()) <= kTol;
}

QString text(Point p)
{
    return QStringLiteral("(%1, %2)").arg(p.x, 0, 'g', 17).arg(p.y, 0, 'g', 17);
}

MotorParameters motor(double stepAngle, double microsteps, double pitch)
{
    MotorParameters m;
    m.stepAngle = stepAngle;
    m.microsteps = microsteps;
    m.startHz = 400;
    m.accelHzPerMs = 80;
    m.rpm = 300;
    m.pitch = pitch;
    return m;
}

} // namespace

// The path of an arc or line from its registers: both arc modes, both directions, the line, and
// where the position registers end up.
class TstMotionPath : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void arcs_data()
    {
        QTest::addColumn<int>("mode"); // register 40183
        QTest::addColumn<QPointF>("start");
        QTest::addColumn<QPointF>("end");
        QTest::addColumn<QPointF>("given"); // the centre (mode 0) or the middle point (mode 1)
        QTest::addColumn<bool>("ccw");
        QTest::addColumn<QPointF>("centre");
        QTest::addColumn<double>("length");
        QTest::addColumn<double>("sweep");    // radians, signed
        QTest::addColumn<QPointF>("quarter"); // the points at 1/4, 1/2 and 3/4 of the length
        QTest::addColumn<QPointF>("half");
        QTest::addColumn<QPointF>("threeQuarters");

        QTest::newRow("centre, counter-clockwise quarter")
            << 0 << QPointF(10, 0) << QPointF(0, 10) << QPointF(0, 0) << true << QPointF(0, 0)
            << 15.707963267948966 << 1.5707963267948966
            << QPointF(9.2387953251128678, 3.8268343236508979)
            << QPointF(7.0710678118654755, 7.0710678118654746)
            << QPointF(3.8268343236509001, 9.2387953251128661);
        QTest::newRow("centre, clockwise three quarters")
            << 0 << QPointF(10, 0) << QPointF(0, 10) << QPointF(0, 0) << false << QPointF(0, 0)
            << 47.123889803846893 << -4.7123889803846897
            << QPointF(3.8268343236508984, -9.2387953251128678)
            << QPointF(-7.0710678118654746, -7.0710678118654755)
            << QPointF(-9.2387953251128696, 3.8268343236508922);
        QTest::newRow("centre, radii differ: a spiral, counter-clockwise")
            << 0 << QPointF(12.5, -3.25) << QPointF(-4.75, 8.5) << QPointF(1.25, 2) << true
            << QPointF(1.25, 2) << 29.263563098990122 << 2.7528429628825961
            << QPointF(12.409772327748488, 4.8683899713389671)
            << QPointF(7.521392720230951, 10.583300021657138)
            << QPointF(0.69319919028263854, 11.722173228921452);
        QTest::newRow("centre, radii differ: a spiral, clockwise")
            << 0 << QPointF(12.5, -3.25) << QPointF(-4.75, 8.5) << QPointF(1.25, 2) << false
            << QPointF(1.25, 2) << 37.528619447726079 << -3.5303423442969901
            << QPointF(4.1183899713389671, -9.1597723277484882)
            << QPointF(-5.0213927202309483, -6.5833000216571396)
            << QPointF(-8.4721732289214522, 1.4431991902826344);
        QTest::newRow("centre, full circle clockwise")
            << 0 << QPointF(5, 0) << QPointF(5, 0) << QPointF(0, 0) << false << QPointF(0, 0)
            << 31.415926535897931 << -6.2831853071795862 << QPointF(0, -5) << QPointF(-5, 0)
            << QPointF(0, 5);
        QTest::newRow("centre, full circle counter-clockwise")
            << 0 << QPointF(5, 0) << QPointF(5, 0) << QPointF(0, 0) << true << QPointF(0, 0)
            << 31.415926535897931 << 6.2831853071795862 << QPointF(0, 5) << QPointF(-5, 0)
            << QPointF(0, -5);
        // Three points: the direction register still chooses the way round.
        QTest::newRow("three points, clockwise through the middle")
            << 1 << QPointF(0, 0) << QPointF(20, 0) << QPointF(10, 10) << false << QPointF(10, 0)
            << 31.415926535897931 << -3.1415926535897931
            << QPointF(2.9289321881345254, 7.0710678118654755) << QPointF(10, 10)
            << QPointF(17.071067811865472, 7.0710678118654782);
        QTest::newRow("three points, counter-clockwise the other way round")
            << 1 << QPointF(0, 0) << QPointF(20, 0) << QPointF(10, 10) << true << QPointF(10, 0)
            << 31.415926535897931 << 3.1415926535897931
            << QPointF(2.9289321881345227, -7.0710678118654746) << QPointF(9.9999999999999982, -10)
            << QPointF(17.071067811865468, -7.0710678118654835);
        QTest::newRow("three odd points, counter-clockwise")
            << 1 << QPointF(1.5, -2.25) << QPointF(-4, 6.5) << QPointF(7.75, 3.5) << true
            << QPointF(1.5980267921795801, 3.9151882693700215) << 26.487250920312881
            << 4.2957168956602221 << QPointF(6.9709951927288873, 0.89023104397635144)
            << QPointF(6.8183602689770844, 7.1965407404998807)
            << QPointF(1.2018509336077716, 10.068415092578119);
        QTest::newRow("three odd points, clockwise")
            << 1 << QPointF(1.5, -2.25) << QPointF(-4, 6.5) << QPointF(7.75, 3.5) << false
            << QPointF(1.5980267921795801, 3.9151882693700215) << 12.254665703247712
            << -1.9874684115193642 << QPointF(-1.4269304332140909, -1.4577801311792853)
            << QPointF(-3.6223066846179219, 0.63383579824015968)
            << QPointF(-4.5552000310285177, 3.5190124107982159);
    }
    void arcs()
    {
        QFETCH(int, mode);
        QFETCH(QPointF, start);
        QFETCH(QPointF, end);
        QFETCH(QPointF, given);
        QFETCH(bool, ccw);
        QFETCH(QPointF, centre);
        QFETCH(double, length);
        QFETCH(double, sweep);
        QFETCH(QPointF, quarter);
        QFETCH(QPointF, half);
        QFETCH(QPointF, threeQuarters);

        ArcSetup a;
        a.mode = mode == 1 ? ArcMode::ThreePoints : ArcMode::Centre;
        a.start = pt(start);
        a.end = pt(end);
        (mode == 1 ? a.middle : a.centre) = pt(given);
        a.counterClockwise = ccw;
        const std::optional<Point> c = arcCentre(a);
        QVERIFY(c);
        QVERIFY2(near(*c, centre), qPrintable(text(*c)));

        const ArcPath p = arcPath(a);
        QCOMPARE(p.problem, ArcProblem::None);
        QVERIFY(p.path && p.path->isArc());
        QVERIFY(std::abs(p.path->length() - length) <= kTol);
        QVERIFY(std::abs(p.path->sweep() - sweep) <= kTol);
        QVERIFY(near(p.path->pointAt(0), start));
        QVERIFY(near(p.path->pointAt(p.path->length()), end)); // the end point exactly
        const QList<QPointF> along{quarter, half, threeQuarters};
        for (int i = 0; i < along.size(); ++i) {
            const Point got = p.path->pointAt(length * (i + 1) / 4);
            QVERIFY2(near(got, along.at(i)), qPrintable(text(got)));
        }
    }

    void arcsThatCannotRun()
    {
        ArcSetup onALine;
        onALine.mode = ArcMode::ThreePoints;
        onALine.start = {0, 0};
        onALine.middle = {1, 1};
        onALine.end = {2.5, 2.5};
        QVERIFY(!arcCentre(onALine));
        QCOMPARE(arcPath(onALine).problem, ArcProblem::PointsOnALine);
        QVERIFY(!arcPath(onALine).path);

        ArcSetup startOnCentre;
        startOnCentre.start = {1, 1};
        startOnCentre.centre = {1, 1};
        startOnCentre.end = {5, 0};
        QCOMPARE(arcPath(startOnCentre).problem, ArcProblem::OnTheCentre);
        ArcSetup endOnCentre = startOnCentre;
        endOnCentre.start = {5, 0};
        endOnCentre.end = {1, 1};
        QCOMPARE(arcPath(endOnCentre).problem, ArcProblem::OnTheCentre);
        QVERIFY(!arcPath(endOnCentre).path);
    }

    void line()
    {
        LineSetup l;
        l.start = {1, 2};
        l.end = {-3.5, 7.25};
        const InterpolationPath p = linePath(l);
        QVERIFY(!p.isArc());
        QVERIFY(std::abs(p.length() - 6.9146583429696653) <= kTol);
        QVERIFY(near(p.pointAt(p.length() / 4), QPointF(-0.125, 3.3125)));
        QVERIFY(near(p.pointAt(p.length() / 2), QPointF(-1.25, 4.625)));
        QVERIFY(near(p.pointAt(p.length() * 3 / 4), QPointF(-2.375, 5.9375)));
        QVERIFY(near(p.pointAt(-1), QPointF(1, 2))); // clamped to the path
        QVERIFY(near(p.pointAt(100), QPointF(-3.5, 7.25)));
    }

    // The way each axis leaves the start: the tangent's signs; an axis the tangent leaves alone
    // (a rounding residue of cos/sin included) reads 0, and a spiral adds its radial part.
    void startDirections()
    {
        using Dir = std::pair<int, int>;
        QCOMPARE(InterpolationPath::line({1, 2}, {-3.5, 7.25}).startDirection(), Dir(-1, 1));
        QCOMPARE(InterpolationPath::line({1, 2}, {1, -5}).startDirection(), Dir(0, -1));
        // From (0, 0) around (10, 0): clockwise first up, counter-clockwise first down.
        const auto cw = InterpolationPath::arcAroundCentre({0, 0}, {20, 0}, {10, 0}, false);
        QVERIFY(cw);
        QCOMPARE(cw->startDirection(), Dir(0, 1));
        const auto ccw = InterpolationPath::arcAroundCentre({0, 0}, {20, 0}, {10, 0}, true);
        QCOMPARE(ccw->startDirection(), Dir(0, -1));
        // From (10, 0) around (0, 0) counter-clockwise, ending further out at (0, 20): the
        // radius grows from the start, so x moves outwards too.
        const auto spiral = InterpolationPath::arcAroundCentre({10, 0}, {0, 20}, {0, 0}, true);
        QCOMPARE(spiral->startDirection(), Dir(1, 1));
        const auto circle = InterpolationPath::arcAroundCentre({10, 0}, {0, 10}, {0, 0}, true);
        QCOMPARE(circle->startDirection(), Dir(0, 1));
    }

    void setupsFromRegisters()
    {
        const RegisterMap &map = RegisterMap::builtin();
        const QHash<QString, qint64> values{
            {"arc.enabled", 1},    {"arc.mode", 1},         {"arc.start_x", 150},
            {"arc.start_y", -225}, {"arc.end_x", -400},     {"arc.end_y", 650},
            {"arc.center_x", 12},  {"arc.center_y", -34},   {"arc.middle_x", 775},
            {"arc.middle_y", 350}, {"arc.direction", 1},    {"arc.speed", 200},
            {"line.enabled", 0},   {"line.start_x", 123},   {"line.start_y", -456},
            {"line.end_x", 1001},  {"line.end_y", 777},     {"line.speed", 60},
            {"motor2.pitch", 317}, {"motor2.microsteps", 4}};
        const RawValue raw = [&values](const QString &k) -> std::optional<qint64> {
            const auto it = values.constFind(k);
            return it == values.cend() ? std::nullopt : std::optional<qint64>(*it);
        };
        const ArcSetup a = arcSetup(map, raw);
        QVERIFY(a.enabled);
        QCOMPARE(a.mode, ArcMode::ThreePoints);
        QVERIFY(near(a.start, QPointF(1.5, -2.25)));
        QVERIFY(near(a.end, QPointF(-4, 6.5)));
        QVERIFY(near(a.centre, QPointF(0.12, -0.34)));
        QVERIFY(near(a.middle, QPointF(7.75, 3.5)));
        QVERIFY(a.counterClockwise);
        QCOMPARE(a.speedRpm, 200.0);
        // The same arc as "three odd points, counter-clockwise" above.
        QVERIFY(std::abs(arcPath(a).path->length() - 26.487250920312881) <= kTol);

        const LineSetup l = lineSetup(map, raw);
        QVERIFY(!l.enabled);
        QVERIFY(near(l.start, QPointF(1.23, -4.56)));
        QVERIFY(near(l.end, QPointF(10.01, 7.77)));
        QCOMPARE(l.speedRpm, 60.0);

        const MotorParameters m2 = motorParameters(map, 2, raw);
        QCOMPARE(m2.pitch.value_or(0), 3.17);
        QCOMPARE(m2.microsteps.value_or(0), 4.0);
        QVERIFY(!m2.stepAngle && !m2.rpm); // not known: not guessed

        // Nothing known: a disabled arc in centre mode, everything at 0.
        const RawValue none = [](const QString &) { return std::optional<qint64>(); };
        const ArcSetup empty = arcSetup(map, none);
        QVERIFY(!empty.enabled && empty.mode == ArcMode::Centre && !empty.counterClockwise);
        QVERIFY(near(empty.end, QPointF(0, 0)) && empty.speedRpm == 0);
        QCOMPARE(arcPath(empty).problem, ArcProblem::OnTheCentre);
    }

    // Where the position registers stand after the approach and after the path, in whole pulses
    // (the end counts as the simulator showed them after a run).
    void targets_data()
    {
        QTest::addColumn<QPointF>("start");
        QTest::addColumn<QPointF>("end");
        QTest::addColumn<double>("pitch1");
        QTest::addColumn<double>("microsteps1");
        QTest::addColumn<double>("stepAngle2");
        QTest::addColumn<double>("microsteps2");
        QTest::addColumn<double>("pitch2");
        QTest::addColumn<QPointF>("approachCounts");
        QTest::addColumn<QPointF>("endCounts");
        QTest::newRow("line, pitch 3 and 7")
            << QPointF(1.23, -4.56) << QPointF(10.01, 7.77) << 3.0 << 8.0 << 0.9 << 4.0 << 7.0
            << QPointF(123, -456) << QPointF(1001, 777);
        QTest::newRow("line, coarse pulses round the end")
            << QPointF(0.01, 0) << QPointF(10.03, -0.02) << 7.0 << 1.0 << 1.8 << 1.0 << 7.0
            << QPointF(0, 0) << QPointF(1005, -3);
        QTest::newRow("arc, factory motors")
            << QPointF(10, 0) << QPointF(0, 10) << 5.0 << 8.0 << 1.8 << 8.0 << 5.0
            << QPointF(1000, 0) << QPointF(0, 1000);
        QTest::newRow("three-point arc, factory motors")
            << QPointF(1.5, -2.25) << QPointF(-4, 6.5) << 5.0 << 8.0 << 1.8 << 8.0 << 5.0
            << QPointF(150, -225) << QPointF(-400, 650);
    }
    void targets()
    {
        QFETCH(QPointF, start);
        QFETCH(QPointF, end);
        QFETCH(double, pitch1);
        QFETCH(double, microsteps1);
        QFETCH(double, stepAngle2);
        QFETCH(double, microsteps2);
        QFETCH(double, pitch2);
        QFETCH(QPointF, approachCounts);
        QFETCH(QPointF, endCounts);
        const auto t = pathTargets(pt(start), pt(end), motor(1.8, microsteps1, pitch1),
                                   motor(stepAngle2, microsteps2, pitch2));
        QVERIFY(t);
        QCOMPARE(t->approach, (Counts{qint64(approachCounts.x()), qint64(approachCounts.y())}));
        QCOMPARE(t->end, (Counts{qint64(endCounts.x()), qint64(endCounts.y())}));
    }

    void targetsNeedTheMotors()
    {
        MotorParameters unknown = motor(1.8, 8, 5);
        unknown.pitch.reset();
        QVERIFY(!pathTargets({0, 0}, {1, 1}, motor(1.8, 8, 5), unknown));
        QVERIFY(!pathTargets({0, 0}, {1, 1}, motor(0, 8, 5), motor(1.8, 8, 5)));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstMotionPath, Guiless)
#include "tst_motionpath.moc"
