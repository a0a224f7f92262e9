// A whole commissioning session recorded by the window against a simulated controller
// with faults to rehearse: connect and read-all, edits written, a jog, homing, a move stopped by
// E-STOP, a command answered late (its coil answers after the link gave the first attempt up), a
// link lost and back (the port hangs up), a power cycle, and the lost edit written again. The
// replay shows exactly what the live window held at ten chosen moments -- after each fault too --
// as `stepcomctl replay --at` does, and the faults are markers: late answer, link lost and back,
// controller restarted.
#include "base/writechangesdialog.h"
#include "replay/replaybar.h"
#include "replay/replayslider.h"
#include "replayfixture.h"
#include "session/jogcontroller.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/reconnector.h"
#include "session/sessionlog.h"
#include "session/stepmove.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "window/windowprobe.h"

#include <QComboBox>
#include <QTest>

using namespace stepcom;

class TestReplayRecorded : public test::ReplayFixture
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;

    // Writes the edits held in the store through the window's dialog, confirmed.
    void writeEdits()
    {
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        WindowProbe(*window).writeChanges();
        QTRY_VERIFY(WindowProbe(*window).writeDialog());
        WindowProbe(*window).writeDialog()->accept();
        QVERIFY(written.wait(15000) || !written.isEmpty());
    }
    // The moment of that name and its time in the log.
    const Moment &moment(const QString &what) const
    {
        return *std::find_if(moments.cbegin(), moments.cend(),
                             [&what](const Moment &m) { return m.what == what; });
    }
    qint64 msOf(const QString &what) const
    {
        QString error;
        return replay()->log().parseTime(moment(what).clock, &error).value_or(-1);
    }
    // The events of a kind between two moments (exclusive of neither).
    QList<ReplayEvent> eventsBetween(ReplayEvent::Kind kind, qint64 from, qint64 to) const
    {
        QList<ReplayEvent> found;
        for (const ReplayEvent &e : replay()->log().events()) {
            if (e.kind == kind && e.ms >= from && e.ms <= to)
                found << e;
        }
        return found;
    }
    // An event is a marker of the timeline (its text in the tip) and a row of the list.
    void checkMarker(const ReplayEvent &e)
    {
        ReplayBar *bar = replay()->bar();
        const QStringList tip = bar->slider()->textsAt(bar->slider()->xOf(e.ms));
        QVERIFY2(tip.join(u'\n').contains(e.text), qPrintable(tip.join(u'\n')));
        bool listed = false;
        for (int i = 0; i < bar->eventList()->count() && !listed; ++i)
            listed = bar->eventList()->itemText(i).contains(e.text);
        QVERIFY2(listed, qPrintable(e.text));
    }

private Q_SLOTS:
    void initTestCase()
    {
        logPath = dir.filePath(QStringLiteral("logs/recorded.log"));
        QDir().mkpath(dir.filePath(QStringLiteral("logs")));
        openWindow();
        WindowProbe(*window).sessionLog()->setFile(logPath);
        // The controller, with what goes wrong on site: output 1's coil answers 450 ms late (as
        // firmware writing its flash first), later its port hangs up and its 24 V goes off.
        host = std::make_unique<SimHost>();
        SimOptions o;
        o.rtu = true;
        o.linkPath = dir.filePath(QStringLiteral("ttyUSB0"));
        o.slowCoils = {{49, 450}};
        QString error;
        QVERIFY2(host->start(o, &error), qPrintable(error));
        QVERIFY(session->connection()->reconnector()->isEnabled()); // the window turns it on
        session->connection()->reconnector()->setDelaysMs({300, 600});
        LinkSettings s;
        s.portName = o.linkPath;
        s.baud = 9600;
        s.deviceId = 1;
        s.timeoutMs = 300; // fixed: the late coil's first attempt is given up, its retry waits
        s.adaptTimeout = false;

        // 1. connect and read everything
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        QTRY_VERIFY_WITH_TIMEOUT(!read.isEmpty(), 15000);
        QVERIFY(read.at(0).at(0).toBool());
        captureSettled(QStringLiteral("read-all"));

        // 2. edits written: motor 1's speed and start frequency
        const qint64 speed = *store()->deviceValue(key("speed"));
        const qint64 start = *store()->deviceValue(key("start_frequency"));
        QVERIFY(store()->edit(key("speed"), speed + 17).isEmpty());
        QVERIFY(store()->edit(key("start_frequency"), start + 10).isEmpty());
        writeEdits();
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(store()->deviceValue(key("speed")), speed + 17);
        QCOMPARE(store()->deviceValue(key("start_frequency")), start + 10);
        captureSettled(QStringLiteral("written"));

        // 3. a jog forward, held until the axis went a millimetre, let go
        const qint64 before = *store()->deviceValue(key("position"));
        QVERIFY(session->jog()->press(1, JogController::Direction::Forward));
        QTRY_VERIFY_WITH_TIMEOUT(
            store()->deviceValue(key("position")).value_or(before) > before + 100, 20000);
        session->jog()->release(1);
        QTRY_COMPARE_WITH_TIMEOUT(session->jog()->state(1), JogController::State::Idle, 10000);
        captureSettled(QStringLiteral("jogged"));
        QVERIFY(moments.last().values.value(key("position")) > before);

        // 4. homing: back to the home switch, the position zeroed there
        session->command(QStringLiteral("motor1.home"));
        QTRY_VERIFY_WITH_TIMEOUT(!host->device()->running(1) && host->device()->position(1) == 0,
                                 60000);
        QTRY_VERIFY_WITH_TIMEOUT(!session->motion()->active(1), 20000); // judged and done
        captureSettled(QStringLiteral("homed"));
        QCOMPARE(moments.last().values.value(key("position")), 0);

        // 5. a long move, seen running, then E-STOP
        QCOMPARE(session->stepMove()->start({StepMoveRequest::Kind::By, 1, 500.0, 0}), QString());
        captureAtCycleEnd(QStringLiteral("running"), false,
                          [this] { return store()->deviceValue(key("running")).value_or(0) == 1; });
        QSignalSpy stopped(session.get(), &DeviceSession::commandFinished);
        session->emergencyStop();
        QTRY_VERIFY_WITH_TIMEOUT(!stopped.isEmpty(), 10000);
        QCOMPARE(stopped.at(0).at(0).toString(), QStringLiteral("estop"));
        QTRY_VERIFY_WITH_TIMEOUT(store()->deviceValue(key("running")) == 0, 10000);
        captureSettled(QStringLiteral("stopped"));

        // 6. a late answer: output 1 on, its coil answered after the first attempt was given
        // up; the retry takes that answer, the retry's own comes late and is discarded. Should
        // a stalled machine let the first answer in on time, it goes again.
        const quint64 staleBefore = session->connection()->linkStats().stale;
        for (int attempt = 0;
             attempt < 3 && session->connection()->linkStats().stale == staleBefore; ++attempt) {
            QSignalSpy commanded(session.get(), &DeviceSession::commandFinished);
            session->command(QStringLiteral("output1_on"));
            QTRY_VERIFY_WITH_TIMEOUT(!commanded.isEmpty(), 20000);
            if (QTest::qWaitFor(
                    [&] { return session->connection()->linkStats().stale > staleBefore; }, 10000))
                break;
        }
        QVERIFY(session->connection()->linkStats().stale > staleBefore);
        QTRY_VERIFY_WITH_TIMEOUT(host->device()->value(QStringLiteral("io.out1")) == 1, 10000);
        captureSettled(QStringLiteral("late answer"));

        // 7. the link lost (the port hangs up for 1.5 s) and back on its own, read again
        QSignalSpy lost(session->connection(), &SessionConnection::linkLost);
        QSignalSpy readAgain(session->parameters(), &SessionParameters::readFinished);
        host->hangUp(1500);
        QTRY_VERIFY_WITH_TIMEOUT(!lost.isEmpty(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(session->connection()->isConnected() && !readAgain.isEmpty(),
                                 30000);
        QVERIFY(readAgain.last().at(0).toBool());
        captureSettled(QStringLiteral("reconnected"));

        // 8. a power cycle: the edits not saved to flash are lost, the positions too
        QSignalSpy restarted(session.get(), &DeviceSession::controllerRestarted);
        QVERIFY(host->powerCycle(1500));
        QVERIFY(restarted.wait(30000) || !restarted.isEmpty());
        QVERIFY2(restarted.at(0).at(1).toStringList().join(u' ').contains(key("speed")),
                 qPrintable(restarted.at(0).at(1).toStringList().join(u' ')));
        QTRY_COMPARE_WITH_TIMEOUT(store()->deviceValue(key("speed")), speed, 10000);
        captureSettled(QStringLiteral("restarted"));

        // 9. the lost edit written again
        QVERIFY(store()->edit(key("speed"), speed + 17).isEmpty());
        writeEdits();
        if (QTest::currentTestFailed())
            return;
        QTRY_COMPARE(store()->deviceValue(key("speed")), speed + 17);
        captureSettled(QStringLiteral("written again"));

        session->connection()->disconnectFrom();
        QTRY_VERIFY(!session->connection()->isConnected());
        WindowProbe(*window).sessionLog()->setFile(QString());
        if (qEnvironmentVariableIsSet("REPLAY_KEEP_LOG"))
            QFile::copy(logPath, qEnvironmentVariable("REPLAY_KEEP_LOG"));
    }
    void cleanupTestCase()
    {
        closeWindow();
        host.reset();
    }
    void cleanup() { closeReplay(); }

    // Ten moments, in the order they happened, and what each shows of the session.
    void tenMomentsWereTaken()
    {
        QStringList names;
        for (const Moment &m : std::as_const(moments))
            names << m.what;
        QCOMPARE(names, (QStringList{"read-all", "written", "jogged", "homed", "running", "stopped",
                                     "late answer", "reconnected", "restarted", "written again"}));
        const qint64 factory = moment(QStringLiteral("read-all")).values.value(key("speed"));
        QCOMPARE(moment(QStringLiteral("written")).values.value(key("speed")), factory + 17);
        QCOMPARE(moment(QStringLiteral("restarted")).values.value(key("speed")), factory);
        QCOMPARE(moment(QStringLiteral("restarted")).values.value(key("start_frequency")),
                 moment(QStringLiteral("read-all")).values.value(key("start_frequency")));
        QCOMPARE(moment(QStringLiteral("written again")).values.value(key("speed")), factory + 17);
        QCOMPARE(moment(QStringLiteral("running")).values.value(key("running")), 1);
        QVERIFY(moment(QStringLiteral("stopped")).values.value(key("position")) > 0);
    }

    // At each moment -- after the late answer, the link's return and the restart too -- the
    // replay shows what the live window showed.
    void replayShowsWhatTheLiveWindowShowed()
    {
        const qsizetype sent = session->connection()->traffic()->entries().size();
        QVERIFY(openReplay(logPath));
        for (const Moment &m : std::as_const(moments)) {
            checkReplayAt(m);
            if (QTest::currentTestFailed())
                return;
        }
        QCOMPARE(session->connection()->traffic()->entries().size(), sent); // nothing went out
    }

    // The faults are markers, each before the moment compared after it: the late answer to the
    // output's coil, the link lost and back, the controller restarted.
    void theFaultsAreMarkers()
    {
        window->resize(1366, 900); // a laptop's window: the timeline as wide as there
        QVERIFY(openReplay(logPath));
        QCoreApplication::processEvents();
        const QList<ReplayEvent> late =
            eventsBetween(ReplayEvent::Kind::LateAnswer, msOf(QStringLiteral("stopped")),
                          msOf(QStringLiteral("late answer")));
        const auto coil = std::find_if(late.cbegin(), late.cend(), [](const ReplayEvent &e) {
            return e.text.contains(QLatin1String("output1_on"));
        });
        QVERIFY2(coil != late.cend(), qPrintable(QString::number(late.size())));
        QVERIFY2(coil->text.startsWith(QLatin1String("late answer")), qPrintable(coil->text));
        checkMarker(*coil);

        const QList<ReplayEvent> down =
            eventsBetween(ReplayEvent::Kind::LinkDown, msOf(QStringLiteral("late answer")),
                          msOf(QStringLiteral("reconnected")));
        QVERIFY(!down.isEmpty());
        checkMarker(down.first());
        const QList<ReplayEvent> up = eventsBetween(ReplayEvent::Kind::LinkUp, down.first().ms,
                                                    msOf(QStringLiteral("reconnected")));
        QVERIFY(!up.isEmpty());
        checkMarker(up.last());

        const QList<ReplayEvent> restart =
            eventsBetween(ReplayEvent::Kind::Restart, msOf(QStringLiteral("reconnected")),
                          msOf(QStringLiteral("restarted")));
        QCOMPARE(restart.size(), 1);
        QVERIFY2(restart.first().text.startsWith(QLatin1String("id 1: ")) &&
                     restart.first().text.contains(key("speed")),
                 qPrintable(restart.first().text));
        checkMarker(restart.first());
        // Between the link's loss and its return the replay says it is down.
        replay()->seek((down.first().ms + up.last().ms) / 2);
        QVERIFY2(replay()->momentStateText().contains(QLatin1String("link is down")),
                 qPrintable(replay()->momentStateText()));
        // The jog, the homing and the E-STOP are there too.
        QStringList commands;
        for (const ReplayEvent &e : replay()->log().events()) {
            if (e.kind == ReplayEvent::Kind::Command || e.kind == ReplayEvent::Kind::EmergencyStop)
                commands << e.text;
        }
        for (const char *expected : {"motor1.forward", "motor1.home", "E-STOP acknowledged"})
            QVERIFY2(commands.join(u'\n').contains(QLatin1String(expected)),
                     qPrintable(commands.join(u'\n')));
    }

    // `stepcomctl replay` agrees: the same state at every moment, the same faults listed.
    void theCommandLineAgrees()
    {
        for (const Moment &m : std::as_const(moments)) {
            checkCommandLineAt(m);
            if (QTest::currentTestFailed())
                return;
        }
        const test::ProgramRun r =
            test::runProgram(QStringLiteral("stepcomctl"), {"replay", logPath, "--events"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (const char *kind : {"late-answer", "link-down", "link-up", "restart", "estop"})
            QVERIFY2(r.out.contains(QLatin1String(kind)), kind);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReplayRecorded, Gui)
#include "tst_replayrecorded.moc"
