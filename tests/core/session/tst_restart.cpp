// A controller whose 24 V is switched off and on: the session sees it, reads everything again,
// says what was lost, shows what the controller holds now, keeps the user's edits, and forgets
// the references. On a line of three only the one that restarted is said to.
#include "device/parameterstore.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/restartwatch.h"
#include "session/sessionlog.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "support/replaylog.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

class TestRestart : public QObject
{
    Q_OBJECT

    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    QStringList said;

    bool start(const QList<int> &ids)
    {
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        o.ids = ids;
        host = std::make_unique<SimHost>();
        QString error;
        if (!host->start(o, &error)) {
            qWarning() << error;
            return false;
        }
        session = std::make_unique<DeviceSession>();
        connect(session.get(), &DeviceSession::message, this,
                [this](DeviceSession::Severity, const QString &text) { said << text; });
        if (!ids.isEmpty()) {
            session->line()->setDeviceIds(ids);
            session->line()->setBackgroundIntervalMs(200);
        }
        LinkSettings s;
        s.portName = host->rtuPath();
        s.timeoutMs = 200;
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        if (!read.wait(10000) && read.isEmpty())
            return false;
        return read.at(0).at(0).toBool();
    }
    QString heard() const { return said.join(QLatin1Char('\n')); }
    bool write(int id, const QString &key, qint64 raw)
    {
        const Parameter *p = session->map().find(key);
        bool done = false;
        bool ok = false;
        session->line()->writeDevice(id, {{p, raw}}, [&](const WriteOutcome &w) {
            done = true;
            ok = w.ok;
        });
        return QTest::qWaitFor([&done] { return done; }, 8000) && ok;
    }

private Q_SLOTS:
    void init() { said.clear(); }
    void cleanup()
    {
        session.reset();
        host.reset();
    }

    void aPowerCycleWhilePollingIsSeenAndSaid()
    {
        QVERIFY(start({}));
        SimDevice *sim = host->device();
        const qint64 factory = *sim->value(QStringLiteral("motor1.speed"));
        QVERIFY(write(1, QStringLiteral("motor1.speed"), factory + 22)); // not saved to flash
        // An edit the user holds, not written.
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor2.speed"), 150).isEmpty());
        QVERIFY(sim->command(QStringLiteral("motor1.move")));
        QTRY_VERIFY_WITH_TIMEOUT(!sim->running(1) && sim->position(1) != 0, 10000);
        QTRY_VERIFY(session->parameters()->store()->deviceValue(
                        QStringLiteral("motor1.position")) == sim->position(1));
        session->motion()->references()->setReasonOn(1, 1, ReferenceTracker::Reason::Homed);
        QSignalSpy restarted(session.get(), &DeviceSession::controllerRestarted);
        QVERIFY(host->powerCycle(1500));
        QVERIFY2(restarted.wait(15000), qPrintable(heard()));
        QCOMPARE(restarted.at(0).at(0).toInt(), 1);
        const QStringList lost = restarted.at(0).at(1).toStringList();
        QVERIFY2(lost.join(QLatin1Char(' ')).contains(QLatin1String("motor1.speed")),
                 qPrintable(lost.join(QLatin1Char('\n'))));
        // What is shown is what the controller holds now.
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("motor1.speed")),
                 factory);
        QTRY_COMPARE(
            *session->parameters()->store()->deviceValue(QStringLiteral("motor1.position")), 0);
        QVERIFY(!session->parameters()->store()->unsavedToFlash());
        // The edit is still held; the reference is gone.
        QCOMPARE(*session->parameters()->store()->shownValue(QStringLiteral("motor2.speed")), 150);
        QCOMPARE(session->motion()->references()->reasonOn(1, 1),
                 ReferenceTracker::Reason::Restarted);
        QVERIFY2(heard().contains(QLatin1String("The controller restarted")), qPrintable(heard()));
        QVERIFY2(heard().contains(QLatin1String("changes not saved to flash lost: motor1.speed")),
                 qPrintable(heard()));
        QCOMPARE(restarted.size(), 1); // said once
    }

    void aRestartAfterSavingLosesOnlyThePositions()
    {
        QVERIFY(start({}));
        QVERIFY(host->device()->command(QStringLiteral("motor1.move")));
        QTRY_VERIFY_WITH_TIMEOUT(!host->device()->running(1), 10000);
        QTRY_VERIFY(session->parameters()->store()->deviceValue(
                        QStringLiteral("motor1.position")) == host->device()->position(1));
        QVERIFY(host->device()->save(nullptr)); // everything in flash: no value can be lost
        const qint64 at = host->device()->position(1);
        // A controller at rest: zeros a moment after a motor was seen running may be that
        // motion's own (homing zeroes after it stops), so the power goes off only once the
        // motion is longer ago than that (a busy computer may have seen it run until now).
        QTest::qWait(int(RestartWatch::kCommandWindowMs));
        QSignalSpy restarted(session.get(), &DeviceSession::controllerRestarted);
        QVERIFY(host->powerCycle(1200));
        QVERIFY2(restarted.wait(15000), qPrintable(heard()));
        // Restarted all the same: the positions went to 0 (from `at`).
        QVERIFY(at != 0);
        QVERIFY(restarted.at(0).at(1).toStringList().isEmpty());
        QVERIFY2(heard().contains(QLatin1String("positions lost")), qPrintable(heard()));
        QVERIFY2(!heard().contains(QLatin1String("not saved to flash lost")), qPrintable(heard()));
    }

    // A power cycle during a homing with nothing unsaved: the axis stands at 0 afterwards, as
    // a homing that ended would. Nothing proves a restart, so none is claimed: the homing's end
    // and the references are not known.
    void aPowerCycleDuringHomingIsNotGuessed()
    {
        QVERIFY(start({}));
        QVERIFY(host->device()->save(nullptr)); // no value can be lost
        QTemporaryDir dir;
        SessionLog log(session.get());
        log.setFile(dir.filePath(QStringLiteral("s.log")));
        QSignalSpy finished(session->motion(), &MotionSupervisor::finished);
        QSignalSpy restarted(session.get(), &DeviceSession::controllerRestarted);
        QSignalSpy possible(session.get(), &DeviceSession::controllerMayHaveRestarted);
        session->command(QStringLiteral("motor1.home"));
        QTRY_VERIFY_WITH_TIMEOUT(host->device()->running(1) &&
                                     session->parameters()
                                             ->store()
                                             ->deviceValue(QStringLiteral("motor1.position"))
                                             .value_or(0) != 0,
                                 5000);
        QVERIFY(host->powerCycle(1500));
        QTRY_VERIFY_WITH_TIMEOUT(heard().contains(QLatin1String("cannot be told")), 15000);
        QCOMPARE(restarted.size(), 0);
        QCOMPARE(session->motion()->references()->reasonOn(1, 1), ReferenceTracker::Reason::Silent);
        QVERIFY(!finished.isEmpty());
        const auto outcome = finished.last().at(0).value<MotionOutcome>();
        QCOMPARE(outcome.cause, MotionCause::Silent);
        QCOMPARE(outcome.verdict, MotionOutcome::Verdict::NotKnown); // not "interrupted"
        QVERIFY2(!heard().contains(QLatin1String("The controller restarted")), qPrintable(heard()));
        // Not claimed, but said, with what was seen: front-ends show it (monitor's JSON).
        QCOMPARE(possible.size(), 1);
        QCOMPARE(possible.at(0).at(0).toInt(), 1);
        const auto seen = possible.at(0).at(1).value<RestartWatch::Evidence>();
        QVERIFY(seen.silentMs >= RestartWatch::kSilenceMs);
        QCOMPARE(seen.moving, QList<int>{1});
        QCOMPARE(seen.zeroed, QList<int>{1});
        QVERIFY2(heard().contains(QLatin1String("may have restarted")), qPrintable(heard()));
        QVERIFY2(heard().contains(QLatin1String("motor 1 was moving and reads 0.00")),
                 qPrintable(heard()));
        // Kept in the session log with what was seen, so its replay shows it too.
        ReplayLog replay;
        QVERIFY2(replay.open(log.currentFile()), qPrintable(replay.errorString()));
        QStringList marks;
        for (const ReplayEvent &e : replay.events())
            if (e.kind == ReplayEvent::Kind::PossibleRestart)
                marks << QStringLiteral("%1 %2").arg(e.device).arg(e.text);
        QCOMPARE(marks.size(), 1);
        QVERIFY2(marks.first().startsWith(QLatin1String("1 id 1 may have restarted: silent ")),
                 qPrintable(marks.first()));
        QVERIFY2(marks.first().contains(QLatin1String("; zeroed motor1; ")),
                 qPrintable(marks.first()));
        QVERIFY2(marks.first().contains(QLatin1String("; moving motor1; ")),
                 qPrintable(marks.first()));
    }

    // Motor 1 stands away from 0, a long single move of motor 2 is followed, the power goes off:
    // motor 1 at 0 afterwards proves the restart, whatever motor 2 did. It is said with what
    // was seen, and the followed move ends with that reason.
    void aPowerCycleWhileTheOtherAxisMovesIsARestart()
    {
        QVERIFY(start({}));
        SimDevice *sim = host->device();
        QVERIFY(write(1, QStringLiteral("motor2.move_distance"), 10000000)); // 100 000 mm
        QVERIFY(sim->save(nullptr)); // nothing to lose but the positions
        QVERIFY(sim->command(QStringLiteral("motor1.move")));
        QTRY_VERIFY_WITH_TIMEOUT(!sim->running(1) && sim->position(1) != 0, 10000);
        QSignalSpy finished(session->motion(), &MotionSupervisor::finished);
        QSignalSpy restarted(session.get(), &DeviceSession::controllerRestarted);
        QSignalSpy possible(session.get(), &DeviceSession::controllerMayHaveRestarted);
        session->command(QStringLiteral("motor2.move"));
        QTRY_VERIFY_WITH_TIMEOUT(session->motion()->active(2) &&
                                     session->parameters()->store()->deviceValue(
                                         QStringLiteral("motor2.running")) == 1 &&
                                     session->parameters()
                                             ->store()
                                             ->deviceValue(QStringLiteral("motor2.position"))
                                             .value_or(0) != 0 &&
                                     session->parameters()->store()->deviceValue(
                                         QStringLiteral("motor1.position")) == sim->position(1),
                                 10000);
        QVERIFY(host->powerCycle(1500));
        QVERIFY2(restarted.wait(15000), qPrintable(heard()));
        QCOMPARE(possible.size(), 0);
        const auto seen = restarted.at(0).at(2).value<RestartWatch::Evidence>();
        QVERIFY(seen.silentMs >= RestartWatch::kSilenceMs);
        QCOMPARE(seen.stoodStill, QList<int>{1});
        QCOMPARE(seen.moving, QList<int>{2});
        QCOMPARE(seen.zeroed, (QList<int>{1, 2}));
        QVERIFY2(heard().contains(QLatin1String("The controller restarted")), qPrintable(heard()));
        QVERIFY2(heard().contains(QLatin1String("motor 1 stood still at")), qPrintable(heard()));
        // The move of motor 2 ended with the restart, not as a stop nobody gave.
        QTRY_VERIFY(!finished.isEmpty());
        const auto outcome = finished.last().at(0).value<MotionOutcome>();
        QCOMPARE(outcome.cause, MotionCause::Restarted);
        const QString text = session->motion()->text(outcome);
        QVERIFY2(text.contains(QLatin1String("the controller restarted")), qPrintable(text));
        QVERIFY2(!text.contains(QLatin1String("no stop")), qPrintable(text));
        QVERIFY(!session->motion()->active(2));
    }

    void oneControllerOfThreeRestarts()
    {
        QVERIFY(start({1, 2, 3}));
        QVERIFY(write(2, QStringLiteral("motor1.speed"), 111));
        QVERIFY(write(3, QStringLiteral("motor1.speed"), 112));
        QTRY_VERIFY_WITH_TIMEOUT(session->line()->deviceStatus(2).cycles >= 2, 10000);
        QSignalSpy restarted(session.get(), &DeviceSession::controllerRestarted);
        QVERIFY(host->powerCycle(1500, 2));
        QVERIFY2(restarted.wait(20000), qPrintable(heard()));
        QCOMPARE(restarted.at(0).at(0).toInt(), 2);
        QVERIFY(restarted.at(0)
                    .at(1)
                    .toStringList()
                    .join(QLatin1Char(' '))
                    .contains(QLatin1String("motor1.speed")));
        QVERIFY2(heard().contains(QLatin1String("Device 2: The controller restarted")),
                 qPrintable(heard()));
        // 1 and 3 went on: polled a few more times each, neither said it restarted.
        const auto cycles1 = session->line()->deviceStatus(1).cycles;
        const auto cycles3 = session->line()->deviceStatus(3).cycles;
        QTRY_VERIFY_WITH_TIMEOUT(session->line()->deviceStatus(1).cycles >= cycles1 + 3 &&
                                     session->line()->deviceStatus(3).cycles >= cycles3 + 3,
                                 20000);
        QCOMPARE(restarted.size(), 1);
        QCOMPARE(session->line()->knownValues(2).value(QStringLiteral("motor1.speed")),
                 *host->deviceAt(2)->value(QStringLiteral("motor1.speed")));
        QCOMPARE(*host->deviceAt(3)->value(QStringLiteral("motor1.speed")), 112);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestRestart, Guiless)
#include "tst_restart.moc"
