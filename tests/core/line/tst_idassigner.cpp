#include "line/idassigner.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

// The id assistant on a new line, against the simulator: controllers are "connected" one at a
// time by moving a parked simulated controller (an id nobody asks at, 200+) to the factory id 1.
class TestIdAssigner : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    SimHost *host() const { return test::simHost(*session); }
    SimDevice *sim(int n) const { return host()->devices().at(n); }
    void plugIn(int n) { QVERIFY(sim(n)->setValue(QStringLiteral("device.id"), 1)); }
    void unplug(int n) { QVERIFY(sim(n)->setValue(QStringLiteral("device.id"), 200 + n)); }
    void connectLine(const QList<int> &ids)
    {
        test::useBuiltinSimulator(*session, ids);
        test::connectToSimulator(*session);
        QCOMPARE(session->line()->deviceInView(), 1);
    }
    static void waitWhileWorking(IdAssigner &a)
    {
        QTRY_VERIFY_WITH_TIMEOUT(a.state() != IdAssigner::State::Working, 30000);
    }
    bool answersAt(int id)
    {
        bool done = false;
        bool ok = false;
        session->line()->readAt(id, {session->map().find(QStringLiteral("device.id"))},
                                [&](const ReadOutcome &r) {
                                    ok = r.ok && r.values.value(QStringLiteral("device.id")) == id;
                                    done = true;
                                });
        if (!QTest::qWaitFor([&] { return done; }, 20000))
            return false;
        return ok;
    }

private Q_SLOTS:
    void init() { session = std::make_unique<DeviceSession>(); }
    void cleanup() { session.reset(); }

    // The id assistant asks to save each id: a power cycle then keeps it; unsaved, it is gone.
    void aSavedIdSurvivesAPowerCycle_data()
    {
        QTest::addColumn<bool>("save");
        QTest::addColumn<int>("idAfter");
        QTest::newRow("saved") << true << 2;
        QTest::newRow("not saved") << false << 1;
    }
    void aSavedIdSurvivesAPowerCycle()
    {
        QFETCH(bool, save);
        QFETCH(int, idAfter);
        connectLine({1});
        IdAssigner a(session.get());
        a.setSaveToFlash(save);
        QVERIFY(a.start());
        a.next();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QVERIFY2(a.text().contains(save ? QStringLiteral("saved to flash")
                                        : QStringLiteral("not saved to flash")),
                 qPrintable(a.text()));
        QCOMPARE(sim(0)->deviceId(), 2);
        sim(0)->powerCycle(1);
        QTRY_VERIFY_WITH_TIMEOUT(!sim(0)->isPoweredOff(), 10000);
        QCOMPARE(sim(0)->deviceId(), idAfter);
    }

    void controllersAddedOneAtATimeGetTheNextFreeIds()
    {
        connectLine({1, 201, 202, 203}); // one connected, three still in their boxes
        IdAssigner a(session.get());
        QSignalSpy added(&a, &IdAssigner::deviceAdded);
        QVERIFY(a.start());
        QCOMPARE(a.state(), IdAssigner::State::Waiting);
        QVERIFY(!session->isLive()); // no live reads while ids move
        QCOMPARE(a.nextId(), 2);

        a.next();
        QCOMPARE(a.state(), IdAssigner::State::Working);
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QCOMPARE(sim(0)->deviceId(), 2);
        QCOMPARE(added.size(), 1);
        QCOMPARE(session->line()->deviceIds(), QList<int>{2});
        QVERIFY(a.text().contains(QStringLiteral("answers at id 2")));
        QCOMPARE(a.nextId(), 3);

        plugIn(1);
        a.next();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QCOMPARE(sim(1)->deviceId(), 3);
        QCOMPARE(session->line()->deviceIds(), (QList<int>{2, 3}));

        // Two new controllers on the line at once: both answer at id 1 and garble each other.
        plugIn(2);
        plugIn(3);
        a.next();
        waitWhileWorking(a);
        QCOMPARE(a.state(), IdAssigner::State::Collision);
        QCOMPARE(a.problem(), IdChange::Problem::Collision);
        QVERIFY2(a.text().contains(QStringLiteral("garbled answers at id 1")),
                 qPrintable(a.text()));
        QVERIFY(a.text().contains(QStringLiteral("nothing was written")));
        QCOMPARE(sim(2)->deviceId(), 1); // neither was touched
        QCOMPARE(sim(3)->deviceId(), 1);
        QCOMPARE(added.size(), 2);
        QVERIFY(!session->line()->deviceIds().contains(4));
        // Asked again with both still there: still refused.
        a.next();
        waitWhileWorking(a);
        QCOMPARE(a.state(), IdAssigner::State::Collision);

        // One taken off the line again: the other gets id 4.
        unplug(3);
        a.next();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QCOMPARE(sim(2)->deviceId(), 4);
        QCOMPARE(sim(3)->deviceId(), 203);

        a.finish();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Finished, qPrintable(a.text()));
        QCOMPARE(a.assigned(), (QList<int>{2, 3, 4}));
        QVERIFY2(
            a.text().contains(QStringLiteral("every controller given an id answers: id 2,3,4")),
            qPrintable(a.text()));
        QCOMPARE(session->line()->deviceIds(), (QList<int>{2, 3, 4}));
        QCOMPARE(session->line()->deviceInView(), 2);
        QVERIFY(session->isLive());
        QVERIFY(answersAt(2));
        QVERIFY(answersAt(3));
        QVERIFY(answersAt(4));
        QVERIFY(!answersAt(1));
    }

    void aCommonBaudIsGivenAndTheLineEndsThere()
    {
        connectLine({1, 201});
        IdAssigner a(session.get());
        a.setCommonBaud(19200);
        QVERIFY(a.start());
        a.next();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QCOMPARE(sim(0)->deviceId(), 2);
        QCOMPARE(sim(0)->baud(), 19200);
        QCOMPARE(session->connection()->settings().baud, 19200);

        // The next arrives at 9600: the line goes back there for it.
        plugIn(1);
        a.next();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QCOMPARE(sim(1)->deviceId(), 3);
        QCOMPARE(sim(1)->baud(), 19200);

        // One is taken off the line before the end: the roll call at 19200 names it.
        QVERIFY(sim(1)->setValue(QStringLiteral("device.id"), 250));
        a.finish();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Finished, qPrintable(a.text()));
        QCOMPARE(session->connection()->settings().baud, 19200);
        QVERIFY2(a.text().contains(QStringLiteral("Answering: id 2. NOT answering: id 3")),
                 qPrintable(a.text()));
        QCOMPARE(session->line()->deviceIds(), (QList<int>{2, 3})); // it stays listed
        QVERIFY(answersAt(2));
        QVERIFY(!answersAt(3));
    }

    void aTakenIdIsRefusedAndNothingIsWritten()
    {
        connectLine({1, 2}); // someone already at 2, not on the list
        IdAssigner a(session.get());
        QVERIFY(a.start());
        a.next();
        waitWhileWorking(a);
        QCOMPARE(a.state(), IdAssigner::State::Failed);
        QCOMPARE(a.problem(), IdChange::Problem::Taken);
        QVERIFY2(a.text().contains(QStringLiteral("id 2 is taken")), qPrintable(a.text()));
        QCOMPARE(sim(0)->deviceId(), 1);
        QCOMPARE(sim(1)->deviceId(), 2);
        // From 3 on it goes.
        a.setFirstId(3);
        a.next();
        waitWhileWorking(a);
        QVERIFY2(a.state() == IdAssigner::State::Waiting, qPrintable(a.text()));
        QCOMPARE(sim(0)->deviceId(), 3);
    }

    void nobodyAtTheFactoryIdIsSaid()
    {
        connectLine({1});
        IdAssigner a(session.get());
        QVERIFY(a.start());
        a.next();
        waitWhileWorking(a);
        QVERIFY(a.state() == IdAssigner::State::Waiting);
        a.next(); // nobody new was connected
        waitWhileWorking(a);
        QCOMPARE(a.state(), IdAssigner::State::Failed);
        QCOMPARE(a.problem(), IdChange::Problem::NoController);
        QVERIFY2(a.text().contains(QStringLiteral("no controller answers at id 1")),
                 qPrintable(a.text()));
        QCOMPARE(a.assigned(), QList<int>{2});
    }

    void startNeedsAConnection()
    {
        IdAssigner a(session.get());
        QVERIFY(!a.start());
        QCOMPARE(a.state(), IdAssigner::State::Idle);
        QVERIFY(a.text().contains(QStringLiteral("Connect to the line first")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestIdAssigner, Guiless)
#include "tst_idassigner.moc"
