#include "map/registermap.h"
#include "motion/motionjudge.h"
#include "motion/motionwatch.h"
#include "motion/referencetracker.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;
using namespace Qt::StringLiterals;

// The verdicts StepCom gives a motion from the controller's registers: "done" only at the end
// point, "referenced" only on the home input at 0, and the cause it saw otherwise.
class TstMotionJudge : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();

    // Motor 1 at 0 with a 10 mm forward move; limits IN1 (+) and IN2 (-), home IN2; motor 2
    // the same on IN3/IN4. Nothing running, no input on, mode 0. Both motors as they leave the
    // factory (1.8°, 8 microsteps, 5 mm pitch: 320 pulses per mm, every 0.01 mm a whole pulse
    // away), which the arc's and line's end points in whole pulses need.
    static StatusValues idleMachine()
    {
        return {{u"motor1.position"_s, 0},
                {u"motor1.step_angle"_s, 180},
                {u"motor1.microsteps"_s, 8},
                {u"motor1.pitch"_s, 500},
                {u"motor2.step_angle"_s, 180},
                {u"motor2.microsteps"_s, 8},
                {u"motor2.pitch"_s, 500},
                {u"motor1.running"_s, 0},
                {u"motor1.move_distance"_s, 1000},
                {u"motor1.direction"_s, 0},
                {u"motor1.limit_positive"_s, 1},
                {u"motor1.limit_negative"_s, 2},
                {u"motor1.home_input"_s, 2},
                {u"motor2.position"_s, 0},
                {u"motor2.running"_s, 0},
                {u"motor2.move_distance"_s, 500},
                {u"motor2.direction"_s, 1},
                {u"motor2.limit_positive"_s, 3},
                {u"motor2.limit_negative"_s, 4},
                {u"motor2.home_input"_s, 4},
                {u"io.in1"_s, 0},
                {u"io.in2"_s, 0},
                {u"io.in3"_s, 0},
                {u"io.in4"_s, 0},
                {u"mode.system"_s, 0},
                {u"homing.first"_s, 2},
                {u"homing.second"_s, 1},
                {u"arc.mode"_s, 0},
                {u"arc.start_x"_s, 0},
                {u"arc.start_y"_s, 0},
                {u"arc.end_x"_s, 2000},
                {u"arc.end_y"_s, 0},
                {u"arc.center_x"_s, 1000},
                {u"arc.center_y"_s, 0},
                {u"arc.direction"_s, 0},
                {u"line.start_x"_s, 0},
                {u"line.start_y"_s, -1000},
                {u"line.end_x"_s, 500},
                {u"line.end_y"_s, -1000}};
    }
    static StatusValues with(StatusValues v, const StatusValues &changes)
    {
        for (auto it = changes.cbegin(); it != changes.cend(); ++it)
            v.insert(it.key(), it.value());
        return v;
    }

private Q_SLOTS:
    void onlyMotionCommandsAreJudged()
    {
        QCOMPARE(MotionJudge::kindOf(map, u"motor1.move"_s), MotionKind::SingleMove);
        QCOMPARE(MotionJudge::kindOf(map, u"motor2.home"_s), MotionKind::Home);
        QCOMPARE(MotionJudge::kindOf(map, u"home_all"_s), MotionKind::HomeInOrder);
        QCOMPARE(MotionJudge::kindOf(map, u"return_to_zero"_s), MotionKind::ReturnToZero);
        QCOMPARE(MotionJudge::kindOf(map, u"arc.start"_s), MotionKind::Arc);
        QCOMPARE(MotionJudge::kindOf(map, u"line.start"_s), MotionKind::Line);
        // Forward and reverse run until stopped: no end to judge.
        QVERIFY(!MotionJudge::kindOf(map, u"motor1.forward"_s));
        QVERIFY(!MotionJudge::kindOf(map, u"estop"_s));
        QVERIFY(!MotionJudge::kindOf(map, u"motor1.speed"_s));
    }

    void plansTheEndPoints()
    {
        const StatusValues v = with(idleMachine(), {{u"motor1.position"_s, 250}});
        const auto move1 = MotionJudge::plan(map, u"motor1.move"_s, v);
        QVERIFY(move1);
        QCOMPARE(move1->motors, QList<int>{1});
        QCOMPARE(move1->target.value(1), 1250); // forward by 10.00 mm from 2.50
        const auto move2 = MotionJudge::plan(map, u"motor2.move"_s, v);
        QCOMPARE(move2->target.value(2), -500); // direction 1: reverse
        const auto order = MotionJudge::plan(map, u"home_all"_s, v);
        QCOMPARE(order->motors, (QList<int>{2, 1}));
        const auto arc = MotionJudge::plan(map, u"arc.start"_s, v);
        QCOMPARE(arc->target.value(1), 2000);
        QCOMPARE(arc->target.value(2), 0);
        // A running motor is not driven back by "return to data zero".
        const auto back =
            MotionJudge::plan(map, u"return_to_zero"_s, with(v, {{u"motor2.running"_s, 1}}));
        QCOMPARE(back->motors, QList<int>{1});
        // Unknown values: no plan rather than a guessed end point.
        QVERIFY(!MotionJudge::plan(map, u"motor1.move"_s, {{u"motor1.position"_s, 0}}));
        QVERIFY(!MotionJudge::plan(map, u"home_all"_s,
                                   with(v, {{u"homing.first"_s, 0}, {u"homing.second"_s, 0}})));
        // The arc's end in whole pulses needs the motors' step angle, microsteps and pitch.
        StatusValues noPitch = v;
        noPitch.remove(u"motor2.pitch"_s);
        QVERIFY(!MotionJudge::plan(map, u"arc.start"_s, noPitch));
        StatusValues noEnd = v;
        noEnd.remove(u"line.end_y"_s);
        QVERIFY(!MotionJudge::plan(map, u"line.start"_s, noEnd));
    }

    void aMoveIsDoneOnlyAtItsEndPoint_data()
    {
        QTest::addColumn<qint64>("end");
        QTest::addColumn<int>("cause");
        QTest::addColumn<bool>("limitOn");
        QTest::addColumn<QString>("verdict");
        QTest::addColumn<QString>("causeWord");
        QTest::addColumn<QString>("text");
        QTest::newRow("at the end") << qint64(1000) << int(MotionCause::None) << false << "done"
                                    << "none"
                                    << "Single move of motor 1: done at 10.00 mm";
        QTest::newRow("one count short") << qint64(999) << int(MotionCause::None) << false << "done"
                                         << "none"
                                         << "Single move of motor 1: done at 9.99 mm";
        QTest::newRow("stopped") << qint64(512) << int(MotionCause::Stop) << false << "stopped"
                                 << "stop"
                                 << "Single move of motor 1: stopped at 5.12 mm, not at the end "
                                    "point 10.00 mm (stop)";
        QTest::newRow("limit") << qint64(700) << int(MotionCause::None) << true << "stopped"
                               << "limit"
                               << "Single move of motor 1: stopped at 7.00 mm, not at the end "
                                  "point 10.00 mm (motor 1's positive limit (IN1) is ON)";
        QTest::newRow("nothing seen") << qint64(700) << int(MotionCause::None) << false << "stopped"
                                      << "unknown"
                                      << "Single move of motor 1: stopped at 7.00 mm, not at the "
                                         "end point 10.00 mm (no stop, limit or E-STOP seen)";
        QTest::newRow("link lost")
            << qint64(300) << int(MotionCause::LinkLost) << false << "stopped"
            << "link_lost"
            << "Single move of motor 1: stopped at 3.00 mm, not at the end "
               "point 10.00 mm (link lost)";
    }
    void aMoveIsDoneOnlyAtItsEndPoint()
    {
        QFETCH(qint64, end);
        QFETCH(int, cause);
        QFETCH(bool, limitOn);
        QFETCH(QString, verdict);
        QFETCH(QString, causeWord);
        QFETCH(QString, text);
        const auto start = MotionJudge::plan(map, u"motor1.move"_s, idleMachine());
        QVERIFY(start);
        const StatusValues after =
            with(idleMachine(), {{u"motor1.position"_s, end}, {u"io.in1"_s, limitOn ? 1 : 0}});
        const MotionOutcome o = MotionJudge::judge(map, *start, after, MotionCause(cause));
        QCOMPARE(o.verdictWord(), verdict);
        QCOMPARE(o.ok(), verdict == QLatin1String("done"));
        QCOMPARE(o.causeWord(), causeWord);
        QCOMPARE(MotionJudge::text(map, o), text);
    }

    // A move stopped short is put down to a limit only on the side it was going: the switch it
    // just left may still read ON behind it (an E-STOP right after leaving the home switch).
    void onlyTheLimitAheadStoppedAMove_data()
    {
        QTest::addColumn<qint64>("direction");
        QTest::addColumn<QString>("input");
        QTest::addColumn<QString>("causeWord");
        QTest::newRow("toward +, the negative limit behind ON")
            << qint64(0) << u"io.in2"_s << u"unknown"_s;
        QTest::newRow("toward +, the positive limit ahead ON")
            << qint64(0) << u"io.in1"_s << u"limit"_s;
        QTest::newRow("toward −, the negative limit ahead ON")
            << qint64(1) << u"io.in2"_s << u"limit"_s;
        QTest::newRow("toward −, the positive limit behind ON")
            << qint64(1) << u"io.in1"_s << u"unknown"_s;
    }
    void onlyTheLimitAheadStoppedAMove()
    {
        QFETCH(qint64, direction);
        QFETCH(QString, input);
        QFETCH(QString, causeWord);
        const StatusValues before = with(idleMachine(), {{u"motor1.direction"_s, direction}});
        const auto start = MotionJudge::plan(map, u"motor1.move"_s, before);
        QVERIFY(start);
        const qint64 end = direction ? -300 : 300; // short of ±10.00 mm
        const MotionOutcome o =
            MotionJudge::judge(map, *start, with(before, {{u"motor1.position"_s, end}, {input, 1}}),
                               MotionCause::None);
        QCOMPARE(o.verdictWord(), u"stopped"_s);
        QCOMPARE(o.causeWord(), causeWord);
    }

    // What inputKeys() names is all a front-end needs to read: plan, warning and verdict from
    // those registers alone are the ones from everything.
    void theInputKeysAreEnoughToJudge_data()
    {
        QTest::addColumn<QString>("command");
        for (const char *c : {"motor1.move", "motor2.home", "home_all", "return_to_zero",
                              "arc.start", "line.start"})
            QTest::newRow(c) << QString::fromLatin1(c);
    }
    void theInputKeysAreEnoughToJudge()
    {
        QFETCH(QString, command);
        // Limits ON everywhere, axes away from 0: warnings and limits to name.
        const StatusValues all = with(idleMachine(), {{u"io.in1"_s, 1},
                                                      {u"io.in2"_s, 1},
                                                      {u"io.in3"_s, 1},
                                                      {u"io.in4"_s, 1},
                                                      {u"motor1.position"_s, 300},
                                                      {u"motor2.position"_s, -200}});
        StatusValues read;
        for (const QString &k : MotionJudge::inputKeys(map, command)) {
            if (all.contains(k))
                read.insert(k, all.value(k));
        }
        QCOMPARE(MotionJudge::limitWarning(map, command, read),
                 MotionJudge::limitWarning(map, command, all));
        const auto fromAll = MotionJudge::plan(map, command, all);
        const auto fromRead = MotionJudge::plan(map, command, read);
        QCOMPARE(bool(fromRead), bool(fromAll));
        if (!fromAll)
            return;
        QCOMPARE(fromRead->motors, fromAll->motors);
        QCOMPARE(fromRead->target, fromAll->target);
        QCOMPARE(
            MotionJudge::text(map, MotionJudge::judge(map, *fromRead, read, MotionCause::None)),
            MotionJudge::text(map, MotionJudge::judge(map, *fromAll, all, MotionCause::None)));
    }

    void aSpecialModeNamesNoLimit()
    {
        // Modes 1-5 give IN1-IN4 other meanings: an input ON is no limit there.
        const auto start = MotionJudge::plan(map, u"motor1.move"_s, idleMachine());
        QVERIFY(start);
        const StatusValues after = with(
            idleMachine(), {{u"motor1.position"_s, 700}, {u"io.in1"_s, 1}, {u"mode.system"_s, 3}});
        const MotionOutcome o = MotionJudge::judge(map, *start, after, MotionCause::None);
        QCOMPARE(o.causeWord(), u"unknown"_s);
        QVERIFY(!MotionJudge::text(map, o).contains(u"limit (IN1) is ON"_s));
    }

    void homingIsReferencedOnlyOnTheHomeInputAtZero_data()
    {
        QTest::addColumn<qint64>("end");
        QTest::addColumn<int>("cause");
        QTest::addColumn<bool>("homeOn");
        QTest::addColumn<QString>("verdict");
        QTest::addColumn<QString>("text");
        QTest::newRow("referenced") << qint64(0) << int(MotionCause::None) << true << "referenced"
                                    << "Homing motor 1: referenced at 0.00 mm";
        QTest::newRow("e-stop") << qint64(-2066) << int(MotionCause::EmergencyStop) << false
                                << "interrupted"
                                << "Homing motor 1 interrupted at -20.66 mm (E-STOP): not "
                                   u"referenced"_s;
        // An E-STOP that came after the switch still leaves the axis unreferenced: something
        // stopped the sequence, and the next homing is cheap.
        QTest::newRow("e-stop on the switch")
            << qint64(0) << int(MotionCause::EmergencyStop) << true << "interrupted"
            << "Homing motor 1 interrupted at 0.00 mm (E-STOP): "
               "not referenced";
        QTest::newRow("no home input")
            << qint64(-500) << int(MotionCause::None) << false << "not_referenced"
            << "Homing motor 1 ended without the home input at -5.00 "
               "mm: not referenced";
        QTest::newRow("input on, not zeroed")
            << qint64(-500) << int(MotionCause::None) << true << "not_referenced"
            << "Homing motor 1 ended without the home input at "
               "-5.00 mm: not referenced";
    }
    void homingIsReferencedOnlyOnTheHomeInputAtZero()
    {
        QFETCH(qint64, end);
        QFETCH(int, cause);
        QFETCH(bool, homeOn);
        QFETCH(QString, verdict);
        QFETCH(QString, text);
        const auto start = MotionJudge::plan(map, u"motor1.home"_s, idleMachine());
        const StatusValues after =
            with(idleMachine(), {{u"motor1.position"_s, end}, {u"io.in2"_s, homeOn ? 1 : 0}});
        const MotionOutcome o = MotionJudge::judge(map, *start, after, MotionCause(cause));
        QCOMPARE(o.verdictWord(), verdict);
        QCOMPARE(o.axis(1)->referenced, verdict == QLatin1String("referenced"));
        QCOMPARE(MotionJudge::text(map, o), text);
    }

    void homingInOrderNamesTheMotorsNotReferenced()
    {
        const auto start = MotionJudge::plan(map, u"home_all"_s, idleMachine());
        const StatusValues after =
            with(idleMachine(),
                 {{u"motor2.position"_s, 0}, {u"io.in4"_s, 1}, {u"motor1.position"_s, 300}});
        const MotionOutcome o = MotionJudge::judge(map, *start, after, MotionCause::None);
        QCOMPARE(o.verdict, MotionOutcome::Verdict::NoHomeInput);
        QVERIFY(o.axis(2)->referenced);
        QVERIFY(!o.axis(1)->referenced);
        QCOMPARE(MotionJudge::text(map, o),
                 QStringLiteral("Homing in order ended without the home input at (0.00, 3.00) "
                                "mm: motor 1 not referenced"));
    }

    void anArcIsDoneAtItsEndPointOnly()
    {
        const auto start = MotionJudge::plan(map, u"arc.start"_s, idleMachine());
        const MotionOutcome done = MotionJudge::judge(
            map, *start, with(idleMachine(), {{u"motor1.position"_s, 2000}}), MotionCause::None);
        QCOMPARE(MotionJudge::text(map, done), QStringLiteral("Arc: done at (20.00, 0.00) mm"));
        const MotionOutcome stopped = MotionJudge::judge(
            map, *start,
            with(idleMachine(),
                 {{u"motor1.position"_s, 0}, {u"motor2.position"_s, 0}, {u"io.in4"_s, 1}}),
            MotionCause::None);
        QCOMPARE(stopped.verdictWord(), QStringLiteral("stopped"));
        QCOMPARE(MotionJudge::text(map, stopped),
                 QStringLiteral("Arc: stopped at (0.00, 0.00) mm, not at the end point (20.00, "
                                "0.00) mm (motor 2's negative limit (IN4) is ON)"));
    }

    void warnsBeforeDrivingIntoAnActiveLimit()
    {
        const StatusValues v = idleMachine();
        QVERIFY(MotionJudge::limitWarning(map, u"motor1.move"_s, v).isEmpty());
        // Forward into the positive limit.
        QVERIFY(MotionJudge::limitWarning(map, u"motor1.move"_s, with(v, {{u"io.in1"_s, 1}}))
                    .contains(QLatin1String("Motor 1's positive limit (IN1) is already ON")));
        // Motor 2 moves in reverse: its negative limit matters, not its positive one.
        QVERIFY(MotionJudge::limitWarning(map, u"motor2.move"_s, with(v, {{u"io.in3"_s, 1}}))
                    .isEmpty());
        QVERIFY(!MotionJudge::limitWarning(map, u"motor2.move"_s, with(v, {{u"io.in4"_s, 1}}))
                     .isEmpty());
        // The line's approach drives motor 2 in reverse to -10.00.
        const QString approach =
            MotionJudge::limitWarning(map, u"line.start"_s, with(v, {{u"io.in4"_s, 1}}));
        QVERIFY2(approach.contains(QLatin1String("Motor 2's negative limit (IN4)")) &&
                     approach.contains(QLatin1String("approach")),
                 qPrintable(approach));
        // Already at the arc's start: the clockwise arc around (10, 0) from (0, 0) first goes
        // up (+y), so motor 2's positive limit matters, and counter-clockwise its negative one.
        QVERIFY(MotionJudge::limitWarning(map, u"arc.start"_s, with(v, {{u"io.in3"_s, 1}}))
                    .contains(QLatin1String("the arc drives motor 2 forward")));
        QVERIFY(
            MotionJudge::limitWarning(map, u"arc.start"_s, with(v, {{u"io.in4"_s, 1}})).isEmpty());
        QVERIFY(!MotionJudge::limitWarning(map, u"arc.start"_s,
                                           with(v, {{u"io.in4"_s, 1}, {u"arc.direction"_s, 1}}))
                     .isEmpty());
        // Modes 1-5 ignore the limit registers.
        QVERIFY(MotionJudge::limitWarning(map, u"motor1.move"_s,
                                          with(v, {{u"io.in1"_s, 1}, {u"mode.system"_s, 3}}))
                    .isEmpty());
    }

    void aWatchEndsAfterTwoIdleSamplesPastTheFirst()
    {
        const auto start = MotionJudge::plan(map, u"motor1.move"_s, idleMachine());
        MotionWatch w(map, *start, 1);
        QVERIFY(!w.sample({{u"motor1.running"_s, 0}})); // may predate the command
        QVERIFY(!w.sample({{u"motor1.running"_s, 1}}));
        QCOMPARE(w.running(), QList<int>{1});
        QVERIFY(!w.sample({{u"motor1.running"_s, 0}}));
        QVERIFY(w.sample({{u"motor1.running"_s, 0}}));
        QVERIFY(w.isOver());
        w.interrupt(MotionCause::EmergencyStop);
        w.interrupt(MotionCause::Stop); // a weaker cause does not replace a stronger one
        QCOMPARE(w.cause(), MotionCause::EmergencyStop);
    }

    void referencesAreLostOnlyWhereThereWasOne()
    {
        ReferenceTracker refs(2);
        QSignalSpy changed(&refs, &ReferenceTracker::changed);
        QVERIFY(!refs.isReferenced(1));
        QCOMPARE(refs.text(1), QStringLiteral("not referenced (not homed yet)"));
        refs.setReason(1, ReferenceTracker::Reason::Homed);
        QVERIFY(refs.isReferenced(1));
        QCOMPARE(refs.text(1), QStringLiteral("referenced"));
        refs.loseAll(ReferenceTracker::Reason::EmergencyStop);
        QCOMPARE(refs.text(1), QStringLiteral("not referenced (E-STOP)"));
        QCOMPARE(refs.reason(2), ReferenceTracker::Reason::NeverHomed);
        QCOMPARE(changed.size(), 2);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstMotionJudge, Guiless)
#include "tst_motionjudge.moc"
