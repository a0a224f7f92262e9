#include "proofsim.h"
#include "sequence/sequenceparser.h"
#include "sequence/sequencerunner.h"
#include "session/devicesession.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;
using namespace stepcom::test;

// SequenceRunner in the core, against the simulator over TCP: pause after each step, single
// steps and resume; a stop that switches the outputs off when on_stop says all_off, and one
// that leaves them; a restart of the controller mid-run.
class TestSequenceRunner : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return host->device(); }
    Sequence parse(const QByteArray &json)
    {
        QStringList errors;
        const auto s =
            SequenceParser::parse(json, QStringLiteral("test.stepseq"), session->map(), &errors);
        if (!s)
            qWarning("%s", qPrintable(errors.join(QLatin1Char('\n'))));
        return s.value_or(Sequence{});
    }
    qint64 output(int n) const
    {
        return sim()->value(QStringLiteral("io.out%1").arg(n)).value_or(-1);
    }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        QVERIFY(startProofSim(*host, proofAxis()));
        session = proofSession(*host);
    }
    void cleanup()
    {
        session.reset();
        host.reset();
    }

    void pausesAfterEachStepAndSingleSteps()
    {
        const Sequence s = parse(R"({"format": "stepcom-sequence", "version": 1, "steps": [
            {"dwell_ms": 10}, {"output": 1, "on": true}, {"dwell_ms": 10},
            {"output": 1, "on": false}]})");
        QCOMPARE(s.steps.size(), 4);
        SequenceRunner runner(session.get());
        QSignalSpy paused(&runner, &SequenceRunner::paused);
        QSignalSpy stepped(&runner, &SequenceRunner::stepFinished);
        QSignalSpy finished(&runner, &SequenceRunner::finished);
        runner.setPauseAfterStep(true);
        QVERIFY(runner.start(s, 1));
        QTRY_COMPARE_WITH_TIMEOUT(paused.size(), 1, 10000);
        QVERIFY(runner.isPaused());
        QCOMPARE(stepped.size(), 1);
        QCOMPARE(paused.last().first().toString(), QStringLiteral("steps[1]"));
        // Paused: nothing more happens. The output step would have gone out, ahead of the
        // status polls, by the time two of them have ended.
        QVERIFY(waitForStatusCycles(*session));
        QCOMPARE(stepped.size(), 1);
        QCOMPARE(output(1), 0);
        runner.singleStep(); // the output goes on, then it pauses again
        QTRY_COMPARE_WITH_TIMEOUT(paused.size(), 2, 10000);
        QCOMPARE(stepped.size(), 2);
        QCOMPARE(output(1), 1);
        QCOMPARE(runner.currentStep(), QStringLiteral("steps[2]"));
        runner.setPauseAfterStep(false);
        runner.resume(); // on to the end without pausing again
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QCOMPARE(paused.size(), 2);
        const auto r = finished.first().first().value<SequenceResult>();
        QVERIFY2(r.ok(), qPrintable(r.text));
        QCOMPARE(output(1), 0);
    }

    void stopSwitchesTheOutputsAsOnStopSays_data()
    {
        QTest::addColumn<QString>("onStop");
        QTest::addColumn<qint64>("after");
        QTest::newRow("all_off") << "all_off" << 0LL;
        QTest::newRow("leave") << "leave" << 1LL;
    }
    void stopSwitchesTheOutputsAsOnStopSays()
    {
        QFETCH(QString, onStop);
        QFETCH(qint64, after);
        const Sequence s = parse(QStringLiteral(R"({"format": "stepcom-sequence", "version": 1,
            "on_stop": {"outputs": "%1"},
            "steps": [{"output": 1, "on": true}, {"dwell_ms": 60000}]})")
                                     .arg(onStop)
                                     .toUtf8());
        SequenceRunner runner(session.get());
        QSignalSpy started(&runner, &SequenceRunner::stepStarted);
        QSignalSpy finished(&runner, &SequenceRunner::finished);
        QVERIFY(runner.start(s, 1));
        QTRY_COMPARE_WITH_TIMEOUT(started.size(), 2, 10000); // dwelling with the output on
        QCOMPARE(output(1), 1);
        runner.stop();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const auto r = finished.first().first().value<SequenceResult>();
        QCOMPARE(r.word(), QStringLiteral("interrupted"));
        QCOMPARE(output(1), after);
    }

    // The controller loses power mid-run for 1.5 s (its counts are 0 here, so the silence is
    // what shows it): a run never goes on after a restart.
    void aRestartEndsTheRun()
    {
        const Sequence s = parse(R"({"format": "stepcom-sequence", "version": 1,
            "steps": [{"dwell_ms": 60000}, {"output": 1, "on": true}]})");
        SequenceRunner runner(session.get());
        QSignalSpy started(&runner, &SequenceRunner::stepStarted);
        QSignalSpy finished(&runner, &SequenceRunner::finished);
        QVERIFY(runner.start(s, 1));
        QTRY_COMPARE_WITH_TIMEOUT(started.size(), 1, 10000);
        QVERIFY(host->powerCycle(1500));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        const auto r = finished.first().first().value<SequenceResult>();
        QCOMPARE(r.word(), QStringLiteral("restarted"));
        QCOMPARE(r.step, QStringLiteral("steps[0]"));
        QCOMPARE(output(1), 0); // the step after it never ran
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestSequenceRunner, Guiless)
#include "tst_sequencerunner.moc"
