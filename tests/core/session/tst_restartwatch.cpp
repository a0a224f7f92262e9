// RestartWatch: when the status a controller answers with says it may have restarted, and
// when it does not (moves, homing, zeroing, a short hiccup).
#include "map/registermap.h"
#include "session/restartwatch.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

namespace {

QHash<QString, qint64> status(qint64 p1, qint64 p2, bool run1 = false, bool run2 = false)
{
    return {{QStringLiteral("motor1.position"), p1},
            {QStringLiteral("motor2.position"), p2},
            {QStringLiteral("motor1.running"), run1 ? 1 : 0},
            {QStringLiteral("motor2.running"), run2 ? 1 : 0}};
}

RestartWatch::Zeros zeros(const QSignalSpy &spy, int i)
{
    return spy.at(i).at(2).value<RestartWatch::Zeros>();
}

} // namespace

class TestRestartWatch : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void positionsBackAtZeroWhileIdle()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(1250, -300), 0);
        w.statusRead(1, true, status(1250, -300), 100);
        QCOMPARE(spy.size(), 0);
        w.statusRead(1, true, status(0, 0), 200);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), 1);
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::Reset);
        // Said once: zeros after zeros are no news.
        w.statusRead(1, true, status(0, 0), 300);
        QCOMPARE(spy.size(), 1);
    }

    void aCommandExplainsTheZeros_data()
    {
        QTest::addColumn<qint64>("after");
        QTest::newRow("next sample") << qint64(100);
        QTest::newRow("a read under way when it went out") << qint64(1000);
    }
    void aCommandExplainsTheZeros()
    {
        QFETCH(qint64, after);
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(500, 500), 0);
        w.commandSent(1, 50); // zero the coordinates
        if (after > 100)
            w.statusRead(1, true, status(500, 500), 100); // read before it acted
        w.statusRead(1, true, status(0, 0), after);
        QCOMPARE(spy.size(), 0);
        QVERIFY(w.movesOrZeroes(QStringLiteral("zero_coordinates")));
        QVERIFY(w.movesOrZeroes(QStringLiteral("motor1.home")));
        QVERIFY(!w.movesOrZeroes(QStringLiteral("motor1.stop")));
        QVERIFY(!w.movesOrZeroes(QStringLiteral("estop")));
        QVERIFY(!w.movesOrZeroes(QStringLiteral("save_to_flash")));
    }

    void aMotionThatEndsAtZeroIsNoRestart()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(300, 0, true), 0);
        w.statusRead(1, true, status(0, 0), 100);
        QCOMPARE(spy.size(), 0);
    }

    void answeringAgainAfterASilence()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(2, true, status(700, 0, true), 0);
        w.statusRead(2, false, {}, 100);
        w.statusRead(2, false, {}, 2000);
        w.statusRead(2, true, status(0, 0), 3300);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), 2);
        QVERIFY2(spy.at(0).at(1).toString().contains(QLatin1String("3.3 s")),
                 qPrintable(spy.at(0).at(1).toString()));
        // Running before the silence, at 0 and idle after it: the motion may have ended at 0
        // (homing does) or the controller restarted -- not known from the positions.
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::AfterMotion);
    }

    // Idle and commanded nothing before a silence, at 0 after it: the counters began again.
    void zerosAfterASilenceWithoutMotion()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(700, 0), 0);
        w.statusRead(1, false, {}, 100);
        w.statusRead(1, true, status(0, 0), 2500);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::Reset);
        // A command that zeroes, then a silence, then zeros: not known either.
        w.statusRead(2, true, status(700, 0), 0);
        w.commandSent(2, 50);
        w.statusRead(2, false, {}, 100);
        w.statusRead(2, true, status(0, 0), 2500);
        QCOMPARE(spy.size(), 2);
        QCOMPARE(zeros(spy, 1), RestartWatch::Zeros::AfterMotion);
    }

    // Motor 1 stood still away from 0, motor 2 ran: after a silence both read 0. Motor 1 cannot
    // have gone there by itself: the counters began again, whatever motor 2 did.
    void anAxisThatStoodStillProvesARestart()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(-123456, 4000, false, true), 0);
        w.statusRead(1, true, status(-123456, 5000, false, true), 100);
        w.statusRead(1, false, {}, 200);
        w.statusRead(1, false, {}, 2000);
        w.statusRead(1, true, status(0, 0), 3400);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::Reset);
        const auto seen = spy.at(0).at(3).value<RestartWatch::Evidence>();
        QCOMPARE(seen.silentMs, 3300);
        QCOMPARE(seen.zeroed, (QList<int>{1, 2}));
        QCOMPARE(seen.stoodStill, QList<int>{1});
        QCOMPARE(seen.moving, QList<int>{2});
        QCOMPARE(seen.before.value(1), -123456);
        QVERIFY(seen.conclusive());
        const QString words = RestartWatch::describe(seen, RegisterMap::builtin());
        QVERIFY2(words.contains(QLatin1String("motor 1 stood still at -1234.56 mm and reads 0.00")),
                 qPrintable(words));
        QVERIFY2(words.contains(QLatin1String("motor 2 was moving and reads 0.00")),
                 qPrintable(words));

        // Without a silence the same (a slow background poll may miss the time it was off).
        w.statusRead(2, true, status(-500, 300, false, true), 0);
        w.statusRead(2, true, status(0, 0), 900);
        QCOMPARE(spy.size(), 2);
        QCOMPARE(zeros(spy, 1), RestartWatch::Zeros::Reset);
        QCOMPARE(spy.at(1).at(3).value<RestartWatch::Evidence>().silentMs, 0);
    }

    // Only the moving axis went to 0 (the other stood at 0 all along): a possible restart,
    // said with what was seen, never claimed.
    void onlyAMovingAxisAtZeroIsAPossibleRestart()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(0, 5000, false, true), 0);
        w.statusRead(1, false, {}, 100);
        w.statusRead(1, true, status(0, 0), 2500);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::AfterMotion);
        const auto seen = spy.at(0).at(3).value<RestartWatch::Evidence>();
        QCOMPARE(seen.silentMs, 2500);
        QCOMPARE(seen.zeroed, QList<int>{2});
        QCOMPARE(seen.stoodStill, QList<int>{1});
        QCOMPARE(seen.moving, QList<int>{2});
        QVERIFY(!seen.conclusive());
    }

    // A command to motor 1 makes its zeros its own; one to motor 2 says nothing of motor 1.
    void commandsCountForTheirOwnAxis()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        const RegisterMap &map = RegisterMap::builtin();
        QCOMPARE(RestartWatch::motorsOf(map, QStringLiteral("motor2.move")), QList<int>{2});
        QCOMPARE(RestartWatch::motorsOf(map, QStringLiteral("motor1.home")), QList<int>{1});
        QVERIFY(RestartWatch::motorsOf(map, QStringLiteral("zero_coordinates")).isEmpty());
        QVERIFY(RestartWatch::motorsOf(map, QStringLiteral("return_to_zero")).isEmpty());
        w.statusRead(1, true, status(700, 300), 0);
        w.commandSent(1, 50, {1});
        w.statusRead(1, false, {}, 100);
        w.statusRead(1, true, status(0, 0), 2500);
        w.statusRead(2, true, status(700, 300), 0);
        w.commandSent(2, 50, {2});
        w.statusRead(2, false, {}, 100);
        w.statusRead(2, true, status(0, 0), 2500);
        QCOMPARE(spy.size(), 2);
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::Reset); // motor 2 stood still
        QCOMPARE(spy.at(0).at(3).value<RestartWatch::Evidence>().stoodStill, QList<int>{2});
        QCOMPARE(zeros(spy, 1), RestartWatch::Zeros::Reset); // motor 1 stood still
        QCOMPARE(spy.at(1).at(3).value<RestartWatch::Evidence>().moving, QList<int>{2});
        // A command to every axis (zeroing) just before the last sample: nothing is proven.
        w.statusRead(3, true, status(700, 300), 0);
        w.commandSent(3, 900);
        w.statusRead(3, true, status(700, 300), 1000); // read under way when it went out
        w.statusRead(3, false, {}, 1100);
        w.statusRead(3, true, status(0, 0), 4000);
        QCOMPARE(spy.size(), 3);
        QCOMPARE(zeros(spy, 2), RestartWatch::Zeros::AfterMotion);
    }

    void aSilenceWithPositionsKeptIsOnlySuspected()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(700, 20), 0);
        w.statusRead(1, false, {}, 100);
        w.statusRead(1, true, status(700, 20), 1500);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(zeros(spy, 0), RestartWatch::Zeros::Kept);
    }

    void aShortHiccupIsNothing()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(700, 20), 0);
        w.statusRead(1, false, {}, 100);
        w.statusRead(1, true, status(700, 20), 400);
        QCOMPARE(spy.size(), 0);
    }

    void devicesAreWatchedApart()
    {
        RestartWatch w(RegisterMap::builtin());
        QSignalSpy spy(&w, &RestartWatch::suspected);
        w.statusRead(1, true, status(100, 0), 0);
        w.statusRead(2, true, status(100, 0), 0);
        w.commandSent(1, 10);
        w.statusRead(1, true, status(0, 0), 100);
        w.statusRead(2, true, status(0, 0), 100);
        QCOMPARE(spy.size(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), 2);
        w.forget();
        w.statusRead(2, true, status(0, 0), 200);
        QCOMPARE(spy.size(), 1);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestRestartWatch, Guiless)
#include "tst_restartwatch.moc"
