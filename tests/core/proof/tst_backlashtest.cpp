#include "proof/backlashtest.h"
#include "proof/marginfinder.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QJsonArray>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <memory>

using namespace stepcom;
using namespace stepcom::test;

// The backlash test with the simulator's carriage as the dial gauge, and the margin search
// against a motor that stalls above a speed (or an acceleration): what they measure against
// what the simulator really has, and the registers put back.
class TestBacklashTest : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return host->device(); }
    qint64 held(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }
    void boot(const AxisPhysics &physics)
    {
        host = std::make_unique<SimHost>();
        QVERIFY(startProofSim(*host, physics));
        session = proofSession(*host);
    }
    // Runs the test, reading the gauge (the carriage) `readings` times, then stopping.
    BacklashResult gauge(const BacklashTest::Options &options, int readings = -1)
    {
        BacklashTest test(session.get());
        QSignalSpy finished(&test, &BacklashTest::finished);
        int given = 0;
        connect(&test, &BacklashTest::readingWanted, &test, [&] {
            if (readings >= 0 && given >= readings) {
                test.stop();
                return;
            }
            ++given;
            test.giveReading(sim()->truth().axes.at(0).carriageMm);
        });
        test.start(options);
        if (finished.isEmpty() && !finished.wait(120000))
            return {};
        return finished.first().first().value<BacklashResult>();
    }
    MarginResult margin(const MarginFinder::Options &options)
    {
        MarginFinder finder(session.get());
        QSignalSpy finished(&finder, &MarginFinder::finished);
        finder.start(options);
        if (finished.isEmpty() && !finished.wait(200000))
            return {};
        return finished.first().first().value<MarginResult>();
    }

private Q_SLOTS:
    void cleanup()
    {
        session.reset();
        host.reset();
    }

    void backlashMatchesTheMachine_data()
    {
        QTest::addColumn<double>("backlash");
        QTest::newRow("none") << 0.0;
        QTest::newRow("0.05 mm") << 0.05;
        QTest::newRow("0.2 mm") << 0.2;
    }
    void backlashMatchesTheMachine()
    {
        QFETCH(double, backlash);
        AxisPhysics p = proofAxis();
        p.startMm = 20;
        p.backlashMm = backlash;
        boot(p);
        BacklashTest::Options o;
        o.distance = 1;
        o.cycles = 2;
        const BacklashResult r = gauge(o);
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("done"));
        QCOMPARE(r.readings.size(), 5);
        QVERIFY(r.backlash);
        QVERIFY2(std::abs(*r.backlash - backlash) <= 0.02,
                 qPrintable(QStringLiteral("%1 vs %2").arg(*r.backlash).arg(backlash)));
        QCOMPARE(r.approachFromOneSide(), backlash > r.resolution); // 0.01 mm here
        QVERIFY(r.restored);
        QCOMPARE(held("motor1.speed"), 300);
        QCOMPARE(r.toJson().value(QStringLiteral("readings")).toArray().size(), 5);
    }

    void noMoreReadingsStops()
    {
        AxisPhysics p = proofAxis();
        p.startMm = 20;
        boot(p);
        BacklashTest::Options o;
        const BacklashResult r = gauge(o, 2);
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("stopped"));
        QCOMPARE(r.readings.size(), 2);
        QVERIFY(!r.backlash);
        QVERIFY(r.restored);
        QCOMPARE(held("motor1.speed"), 300);
    }

    void marginBracketsTheStallSpeed()
    {
        AxisPhysics p = proofAxis();
        p.pullOutRpm = 250;
        p.pullInRpm = 100;
        boot(p);
        MarginFinder::Options o;
        o.from = 100;
        o.to = 400;
        o.step = 100;
        o.cycles = 1;
        o.distance = 5;
        const MarginResult r = margin(o);
        QCOMPARE(proofOutcomeWord(r.outcome), QStringLiteral("done"));
        QVERIFY2(r.kept && r.stall, qPrintable(r.text));
        // Within one step of the pull-out speed: the last kept below it, the first lost above.
        QCOMPARE(*r.kept, 200);
        QCOMPARE(*r.stall, 300);
        QCOMPARE(*r.recommended, 150);
        QCOMPARE(r.steps.size(), 3);
        QVERIFY(r.restored);
        QCOMPARE(held("motor1.speed"), 300);
        QCOMPARE(r.toJson().value(QStringLiteral("stall_rpm")).toInt(), 300);
    }

    void marginValues()
    {
        QCOMPARE(MarginFinder::values(100, 400, 100), (QList<qint64>{100, 200, 300, 400}));
        QCOMPARE(MarginFinder::values(100, 350, 100), (QList<qint64>{100, 200, 300, 350}));
        QCOMPARE(MarginFinder::values(5, 5, 1), (QList<qint64>{5}));
        QVERIFY(MarginFinder::values(5, 4, 1).isEmpty());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestBacklashTest, Guiless)
#include "tst_backlashtest.moc"
