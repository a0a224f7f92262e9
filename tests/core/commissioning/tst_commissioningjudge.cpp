#include "commissioning/directioncheck.h"
#include "commissioning/inputtest.h"
#include "commissioning/travelcalibration.h"
#include "map/registermap.h"

#include <QTest>

#include <cmath>
#include <limits>

using namespace stepcom;

namespace {

const Parameter &pitch()
{
    return *RegisterMap::builtin().find(QStringLiteral("motor1.pitch"));
}

// Motor 1: + on IN1, − and home on IN2; motor 2: + on IN3, − and home on IN4.
QList<MotorWiring> wiring()
{
    return {{1, 1, 2, 2}, {2, 3, 4, 4}};
}

} // namespace

// The pure judgements of the checklist's steps: calibration, inputs, direction.
class TestCommissioningJudge : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void calibration_data()
    {
        QTest::addColumn<qint64>("pitchRaw");
        QTest::addColumn<double>("commanded");
        QTest::addColumn<double>("measured");
        QTest::addColumn<qint64>("expected"); // -1: refused
        QTest::addColumn<QString>("message");
        QTest::newRow("short") << qint64(500) << 100.0 << 99.2 << qint64(496) << "";
        QTest::newRow("long") << qint64(500) << 100.0 << 100.8 << qint64(504) << "";
        QTest::newRow("exact") << qint64(500) << 100.0 << 100.0 << qint64(500) << "";
        // 5.00 × 10.03 ÷ 10 = 5.015 → 5.02 (in doubles it would be 5.0149999… → 5.01).
        QTest::newRow("half rounds away") << qint64(500) << 10.0 << 10.03 << qint64(502) << "";
        QTest::newRow("4 mm lead") << qint64(400) << 50.0 << 50.5 << qint64(404) << "";
        QTest::newRow("micrometres") << qint64(1000) << 123.456 << 123.0 << qint64(996) << "";
        QTest::newRow("zero commanded") << qint64(500) << 0.0 << 10.0 << qint64(-1)
                                        << "the commanded distance must be more than 0 mm, found 0";
        QTest::newRow("negative measured")
            << qint64(500) << 10.0 << -10.0 << qint64(-1)
            << "the measured distance must be more than 0 mm, found -10";
        QTest::newRow("not a number")
            << qint64(500) << 10.0 << std::nan("") << qint64(-1)
            << "the measured distance must be more than 0 mm, found not a number";
        QTest::newRow("infinite") << qint64(500) << std::numeric_limits<double>::infinity() << 10.0
                                  << qint64(-1) << "the commanded distance must be more than 0 mm";
        QTest::newRow("absurd")
            << qint64(500) << 2.0e6 << 2.0e6 << qint64(-1)
            << "the commanded distance 2000000 mm is not a distance on a machine";
        QTest::newRow("factor 2")
            << qint64(500) << 100.0 << 200.0 << qint64(-1)
            << "200 mm measured for 100 mm commanded is off by a factor of 2.000: "
               "that is not a calibration error";
        QTest::newRow("factor 1/8")
            << qint64(500) << 80.0 << 10.0 << qint64(-1) << "off by a factor of 0.125";
        QTest::newRow("pitch zero") << qint64(0) << 10.0 << 10.0 << qint64(-1)
                                    << "the current pitch (0.00) cannot be corrected";
        QTest::newRow("beyond the register") << qint64(2147483600) << 100.0 << 101.0 << qint64(-1)
                                             << "the corrected pitch would be 21689584.36 mm: ";
        QTest::newRow("to the resolution") << qint64(1) << 100.0 << 70.0 << qint64(1) << "";
    }
    void calibration()
    {
        QFETCH(qint64, pitchRaw);
        QFETCH(double, commanded);
        QFETCH(double, measured);
        QFETCH(qint64, expected);
        QFETCH(QString, message);
        const CalibrationProposal p =
            TravelCalibration::propose(pitch(), pitchRaw, commanded, measured);
        if (expected < 0) {
            QVERIFY(!p.ok());
            QVERIFY2(p.error.contains(message), qPrintable(p.error));
            return;
        }
        QVERIFY2(p.ok(), qPrintable(p.error));
        QCOMPARE(*p.raw, expected);
        QCOMPARE(pitch().checkRaw(*p.raw), QString());
    }

    void observationSeesAPressBetweenPolls()
    {
        InputObservation o;
        o.add({{1, true}}); // before start: ignored
        QVERIFY(!o.started());
        const QMap<int, bool> idle{{1, false}, {2, true}, {3, false}, {4, false}};
        o.start(idle);
        o.add(idle);
        QVERIFY(o.changed().isEmpty());
        QMap<int, bool> pressed = idle;
        pressed[3] = true;
        o.add(pressed);
        o.add(idle); // released again: the change stays recorded
        QCOMPARE(o.changed(), QList<int>{3});
        QMap<int, bool> released = idle;
        released[2] = false; // a normally-closed switch opens
        o.add(released);
        QCOMPARE(o.changed(), (QList<int>{2, 3}));

        QHash<QString, qint64> values{{"io.in1", 0}, {"io.in2", 1}, {"io.in3", 0}, {"io.in4", 1}};
        QCOMPARE(*InputObservation::inputs(RegisterMap::builtin(), values),
                 (QMap<int, bool>{{1, false}, {2, true}, {3, false}, {4, true}}));
        values.remove("io.in4");
        QVERIFY(!InputObservation::inputs(RegisterMap::builtin(), values));
    }

    void inputTest_data()
    {
        QTest::addColumn<int>("motor");
        QTest::addColumn<int>("role");
        QTest::addColumn<QList<int>>("changed");
        QTest::addColumn<int>("verdict");
        QTest::addColumn<QStringList>("fixes"); // key=raw
        QTest::addColumn<QString>("message");
        QTest::addColumn<QString>("note");
        using V = InputJudgement::Verdict;
        using R = InputTest::Role;
        QTest::newRow("as configured")
            << 1 << int(R::PositiveLimit) << QList<int>{1} << int(V::Matches) << QStringList{}
            << "IN1 answered for the positive limit of motor 1, as configured."
            << "";
        QTest::newRow("home shares the negative limit")
            << 1 << int(R::Home) << QList<int>{2} << int(V::Matches) << QStringList{}
            << "as configured"
            << "";
        // Motor 1's limit switches swapped at the terminals: the negative one answers on IN1.
        QTest::newRow("miswired negative limit")
            << 1 << int(R::NegativeLimit) << QList<int>{1} << int(V::OtherInput)
            << QStringList{"motor1.limit_negative=1", "motor1.home_input=1"}
            << "IN1 answered for the negative limit of motor 1, but IN2 is configured: the wiring "
               "and the configuration disagree. Proposed: motor1.limit_negative = IN1, "
               "motor1.home_input = IN1 (or rewire the switch to IN2)."
            << "IN1 is also configured as the positive limit of motor 1";
        QTest::newRow("other motor's input")
            << 2 << int(R::PositiveLimit) << QList<int>{1} << int(V::OtherInput)
            << QStringList{"motor2.limit_positive=1"} << "but IN3 is configured"
            << "IN1 is also configured as the positive limit of motor 1";
        QTest::newRow("none answered")
            << 1 << int(R::PositiveLimit) << QList<int>{} << int(V::NoneAnswered) << QStringList{}
            << "No input changed while the positive limit of motor 1 was pressed (configured: IN1)"
            << "";
        QTest::newRow("several")
            << 1 << int(R::PositiveLimit) << QList<int>{2, 1} << int(V::Several) << QStringList{}
            << "Several inputs changed while the positive limit of motor 1 was pressed (IN1, IN2)"
            << "";
    }
    void inputTest()
    {
        QFETCH(int, motor);
        QFETCH(int, role);
        QFETCH(QList<int>, changed);
        QFETCH(int, verdict);
        QFETCH(QStringList, fixes);
        QFETCH(QString, message);
        QFETCH(QString, note);
        const InputJudgement j = InputTest::judge(RegisterMap::builtin(), motor,
                                                  InputTest::Role(role), wiring(), changed);
        QCOMPARE(int(j.verdict), verdict);
        QCOMPARE(j.passed(), verdict == int(InputJudgement::Verdict::Matches));
        QStringList got;
        for (const InputFix &f : j.fixes)
            got << QStringLiteral("%1=%2").arg(f.key).arg(f.raw);
        QCOMPARE(got, fixes);
        QVERIFY2(j.message.contains(message), qPrintable(j.message));
        if (note.isEmpty())
            QVERIFY2(j.notes.isEmpty(), qPrintable(j.notes.join('\n')));
        else
            QVERIFY2(j.notes.join('\n').contains(note), qPrintable(j.notes.join('\n')));
    }

    void proposedFixMakesTheTestPass()
    {
        // Not configured at all: the switch answers on IN3; the fix names IN3, and with it
        // written the same press matches.
        QList<MotorWiring> w{{1, 0, 2, 2}, {2, 0, 4, 4}};
        InputJudgement j =
            InputTest::judge(RegisterMap::builtin(), 1, InputTest::Role::PositiveLimit, w, {3});
        QCOMPARE(j.verdict, InputJudgement::Verdict::OtherInput);
        QVERIFY2(j.message.contains("which is not configured (none)"), qPrintable(j.message));
        QCOMPARE(j.fixes, (QList<InputFix>{{"motor1.limit_positive", 3}}));
        w[0].positive = int(j.fixes.first().raw);
        j = InputTest::judge(RegisterMap::builtin(), 1, InputTest::Role::PositiveLimit, w, {3});
        QVERIFY(j.passed());
    }

    void direction_data()
    {
        QTest::addColumn<int>("motor");
        QTest::addColumn<qint64>("current");
        QTest::addColumn<bool>("towardPlus");
        QTest::addColumn<qint64>("to"); // -1: no change
        QTest::addColumn<QString>("error");
        QTest::newRow("yes") << 1 << qint64(0) << true << qint64(-1) << "";
        QTest::newRow("no, forward") << 1 << qint64(0) << false << qint64(1) << "";
        QTest::newRow("no, reverse") << 2 << qint64(1) << false << qint64(0) << "";
        QTest::newRow("no such motor")
            << 3 << qint64(0) << false << qint64(-1) << "motor 3 has no direction register";
        QTest::newRow("bad value") << 1 << qint64(7) << false << qint64(-1) << "motor1.direction";
    }
    void direction()
    {
        QFETCH(int, motor);
        QFETCH(qint64, current);
        QFETCH(bool, towardPlus);
        QFETCH(qint64, to);
        QFETCH(QString, error);
        const DirectionAnswer a =
            DirectionCheck::answer(RegisterMap::builtin(), motor, current, towardPlus);
        QVERIFY2(error.isEmpty() ? a.error.isEmpty() : a.error.contains(error),
                 qPrintable(a.error));
        QCOMPARE(a.to.value_or(-1), to);
        if (error.isEmpty())
            QCOMPARE(a.key, QStringLiteral("motor%1.direction").arg(motor));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCommissioningJudge, Guiless)
#include "tst_commissioningjudge.moc"
