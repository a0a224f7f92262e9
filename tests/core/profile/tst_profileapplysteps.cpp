// ProfileApply on the simulator: read, compare, back up through the session's risk guard,
// write, verify, save to flash; an E-STOP, a lost link and a restart in the middle.
#include "bus/trafficlog.h"
#include "profile/backupstore.h"
#include "profile/profileapply.h"
#include "profile/sessionbackup.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace stepcom;
using State = AppliedKey::State;

class TestProfileApplySteps : public QObject
{
    Q_OBJECT

    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    QTemporaryDir backups;
    QList<QPair<DeviceSession::Risk, int>> guarded; // what the risk guard was asked, in order
    QString refusal;                                // the guard's answer
    const QString speed = QStringLiteral("motor1.speed");
    const QString distance = QStringLiteral("motor1.move_distance");

    bool start(const QList<int> &ids)
    {
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 2;
        o.ids = ids;
        host = std::make_unique<SimHost>();
        QString error;
        if (!host->start(o, &error)) {
            qWarning() << error;
            return false;
        }
        session = std::make_unique<DeviceSession>();
        if (!ids.isEmpty())
            session->line()->setDeviceIds(ids);
        // The window's and stepcomctl's guard: a backup through SessionBackup, then go on.
        session->risks()->setGuard(
            [this](DeviceSession::Risk risk, int id, DeviceSession::Proceed proceed) {
                guarded.append({risk, id});
                if (!refusal.isEmpty()) {
                    proceed(refusal);
                    return;
                }
                SessionBackup::save(session.get(), BackupStore(backups.path()), risk, id,
                                    [proceed](const BackupStore::Saved &saved) {
                                        proceed(saved.ok() ? QString() : saved.error);
                                    });
            });
        LinkSettings s;
        s.portName = host->rtuPath();
        s.timeoutMs = 200;
        QSignalSpy read(session.get()->parameters(), &SessionParameters::readFinished);
        session->connection()->connectTo(s);
        if (!read.wait(10000) && read.isEmpty())
            return false;
        return read.at(0).at(0).toBool();
    }
    qint64 simValue(int id, const QString &key) const
    {
        SimDevice *d = id == 0 ? host->device() : host->deviceAt(id);
        return d->value(key).value_or(-1);
    }
    // What controller `id` holds, with `changes` added to the keys named.
    Profile profileFrom(int id, const QHash<QString, qint64> &changes)
    {
        QHash<QString, qint64> values;
        for (const Parameter *p : Profile::profileParameters(session->map(), false))
            values.insert(p->key, simValue(id, p->key));
        for (auto it = changes.cbegin(); it != changes.cend(); ++it)
            values[it.key()] += it.value();
        return Profile::fromValues(session->map(), values, false);
    }
    int writeFramesTo(int id) const
    {
        int n = 0;
        for (const TrafficEntry &e : session->connection()->traffic()->entries()) {
            if (e.direction == TrafficEntry::Direction::Sent && e.bytes.size() > 1 &&
                (quint8(e.bytes.at(1)) == 0x06 || quint8(e.bytes.at(1)) == 0x10) &&
                quint8(e.bytes.at(0)) == id)
                ++n;
        }
        return n;
    }
    static ProfileApplyResult run(ProfileApply &apply, const QStringList &keys, int ms = 15000)
    {
        QSignalSpy finished(&apply, &ProfileApply::finished);
        apply.apply(keys);
        if (!QTest::qWaitFor([&] { return !finished.isEmpty(); }, ms))
            qWarning("ProfileApply did not finish");
        return apply.result();
    }

private Q_SLOTS:
    void init()
    {
        guarded.clear();
        refusal.clear();
        QDir(backups.path()).removeRecursively();
        QDir().mkpath(backups.path());
    }
    void cleanup()
    {
        session.reset();
        host.reset();
    }

    void oneDeviceBackedUpWrittenVerified()
    {
        QVERIFY(start({}));
        const qint64 held = simValue(0, distance);
        Profile profile = profileFrom(0, {{speed, 7}});
        ProfileApply apply(session.get(), profile);
        QList<ProfileApply::Step> steps;
        connect(&apply, &ProfileApply::progress, this,
                [&steps](ProfileApply::Step s) { steps << s; });
        const ProfileApplyResult r = run(apply, {speed, distance});
        QVERIFY2(r.ok(), qPrintable(r.problems().join(QLatin1Char('\n')) + r.error));
        QCOMPARE(r.end, ProfileApplyResult::End::Done);
        QCOMPARE(r.key(speed)->state, State::Verified);
        QCOMPARE(*r.key(speed)->before, profile.values.value(speed) - 7);
        QCOMPARE(r.key(distance)->state, State::Unchanged); // already held: not written
        QCOMPARE(simValue(0, speed), profile.values.value(speed));
        QCOMPARE(simValue(0, distance), held);
        QCOMPARE(steps, (QList<ProfileApply::Step>{ProfileApply::Step::Reading,
                                                   ProfileApply::Step::BackingUp,
                                                   ProfileApply::Step::Writing}));
        // The backup went through the session's risk guard, for this device, before writing.
        QCOMPARE(guarded,
                 (QList<QPair<DeviceSession::Risk, int>>{{DeviceSession::Risk::Apply, 1}}));
        const QList<BackupEntry> saved = BackupStore(backups.path()).list(session->map());
        QCOMPARE(saved.size(), 1);
        const auto backup = BackupStore::load(saved.first().path, session->map());
        QCOMPARE(backup.profile->values.value(speed), profile.values.value(speed) - 7);
    }

    void aDeviceNotInViewIsBackedUpAndWrittenItself()
    {
        QVERIFY(start({1, 2, 3}));
        const qint64 one = simValue(1, speed);
        Profile profile = profileFrom(3, {{speed, 9}});
        ProfileApply two(session.get(), profile, 2);
        ProfileApply three(session.get(), profile, 3);
        session->connection()->traffic()->clear();
        const ProfileApplyResult r3 = run(three, {speed});
        const ProfileApplyResult r2 = run(two, {speed});
        QVERIFY(r2.ok() && r3.ok());
        QCOMPARE(r3.id, 3);
        QCOMPARE(simValue(3, speed), profile.values.value(speed));
        QCOMPARE(simValue(2, speed), profile.values.value(speed));
        QCOMPARE(simValue(1, speed), one);
        QCOMPARE(writeFramesTo(1), 0);
        QCOMPARE(guarded, (QList<QPair<DeviceSession::Risk, int>>{
                              {DeviceSession::Risk::Apply, 3}, {DeviceSession::Risk::Apply, 2}}));
        QList<int> ids;
        for (const BackupEntry &e : BackupStore(backups.path()).list(session->map()))
            ids << e.deviceId;
        std::sort(ids.begin(), ids.end());
        QCOMPARE(ids, (QList<int>{2, 3}));
    }

    void refusedValuesAreNamedAndNotSent()
    {
        QVERIFY(start({}));
        Profile profile = profileFrom(0, {{speed, 5}});
        const Parameter *d = session->map().find(distance);
        profile.values[distance] = d->rawMax + 1; // out of the map's range
        ProfileApply apply(session.get(), profile);
        const ProfileApplyResult r = run(apply, {speed, distance});
        QVERIFY(!r.ok());
        QCOMPARE(r.key(speed)->state, State::Verified);
        QCOMPARE(r.key(distance)->state, State::Refused);
        QCOMPARE(r.key(distance)->refusal, AppliedKey::Refusal::OutOfRange);
        QVERIFY2(r.key(distance)->reason.contains(QStringLiteral("out of range")),
                 qPrintable(r.key(distance)->reason));
        QVERIFY(simValue(0, distance) != d->rawMax + 1);
        QVERIFY(r.problems().join(QLatin1Char(' ')).contains(distance));
    }

    void theReviewsQuestionRefusesWhenAsked()
    {
        QVERIFY(start({}));
        const QString mode = QStringLiteral("mode.system");
        Profile profile = profileFrom(0, {{speed, 3}, {mode, 1}});
        ProfileApply apply(session.get(), profile);
        apply.setRefuseQuestioned(true);
        const qint64 before = simValue(0, mode);
        const ProfileApplyResult r = run(apply, {speed, mode});
        QCOMPARE(r.key(mode)->state, State::Refused);
        QCOMPARE(r.key(mode)->refusal, AppliedKey::Refusal::Questioned);
        QCOMPARE(simValue(0, mode), before);
        QCOMPARE(r.key(speed)->state, State::Verified);
    }

    void aGuardThatRefusesWritesNothing()
    {
        QVERIFY(start({}));
        refusal = QStringLiteral("no backup could be saved");
        ProfileApply apply(session.get(), profileFrom(0, {{speed, 4}}));
        session->connection()->traffic()->clear();
        const ProfileApplyResult r = run(apply, {speed});
        QCOMPARE(r.end, ProfileApplyResult::End::Failed);
        QCOMPARE(r.error, refusal);
        QCOMPARE(r.key(speed)->state, State::NotWritten);
        QCOMPARE(writeFramesTo(1), 0);
    }

    void anEstopStopsItAndSaysWhatIsNotKnown()
    {
        QVERIFY(start({}));
        Profile profile = profileFrom(0, {{speed, 6}});
        ProfileApply apply(session.get(), profile);
        apply.setSaveToFlash(true);
        // The write frame is on the wire: the E-STOP comes before its answer and read-back.
        connect(session->connection()->traffic(), &TrafficLog::entryAdded, this,
                [this](const TrafficEntry &e) {
                    if (e.direction == TrafficEntry::Direction::Sent && e.bytes.size() > 1 &&
                        quint8(e.bytes.at(1)) == 0x06)
                        QTimer::singleShot(0, session.get(), &DeviceSession::emergencyStop);
                });
        QSignalSpy finished(&apply, &ProfileApply::finished);
        apply.apply({speed});
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const ProfileApplyResult r = apply.result();
        QCOMPARE(r.end, ProfileApplyResult::End::Stopped);
        QCOMPARE(r.key(speed)->state, State::NotKnown); // queued or sent: never guessed
        QVERIFY(!r.savedToFlash.has_value());
        QCOMPARE(guarded.size(), 1); // no save to flash after it
    }

    void aLinkLostBetweenWriteAndVerifySaysWrittenNotVerified()
    {
        QVERIFY(start({}));
        Profile profile = profileFrom(0, {{speed, 8}});
        ProfileApply apply(session.get(), profile);
        // The write's answer came: the simulator goes away before the read-back.
        connect(session->connection()->traffic(), &TrafficLog::entryAdded, this,
                [this](const TrafficEntry &e) {
                    if (e.direction == TrafficEntry::Direction::Received && e.bytes.size() > 1 &&
                        quint8(e.bytes.at(1)) == 0x06 && host->isRunning())
                        host->stop();
                });
        const ProfileApplyResult r = run(apply, {speed}, 20000);
        QVERIFY(!r.ok());
        const AppliedKey *k = r.key(speed);
        QCOMPARE(k->state, State::Written); // acknowledged: known written
        QVERIFY(!k->readBack.has_value());  // what it holds now: not known
        QVERIFY(r.keysIn(State::Verified).isEmpty());
        QVERIFY2(
            ProfileApplyResult::describe(*k).contains(QStringLiteral("could not read it back")),
            qPrintable(ProfileApplyResult::describe(*k)));
    }

    void aRestartBeforeTheSaveToFlashIsSeen()
    {
        QVERIFY(start({}));
        Profile profile = profileFrom(0, {{speed, 12}});
        const qint64 before = simValue(0, speed);
        ProfileApply apply(session.get(), profile);
        apply.setSaveToFlash(true);
        // Written and verified; the 24 V goes off as the save to flash starts.
        connect(&apply, &ProfileApply::progress, this, [this](ProfileApply::Step s) {
            if (s == ProfileApply::Step::SavingToFlash)
                QVERIFY(host->powerCycle(1000));
        });
        const ProfileApplyResult r = run(apply, {speed}, 30000);
        QCOMPARE(r.end, ProfileApplyResult::End::Restarted);
        const AppliedKey *k = r.key(speed);
        QCOMPARE(k->state, State::Lost);
        QCOMPARE(*k->readBack, before);
        QVERIFY(r.savedToFlash != true); // never said saved
        QVERIFY(!r.ok());
        QCOMPARE(simValue(0, speed), before);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProfileApplySteps, Guiless)
#include "tst_profileapplysteps.moc"
