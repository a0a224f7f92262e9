#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "profile/backupstore.h"
#include "profile/profilerollout.h"
#include "profile/sessionbackup.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

// One profile applied to several controllers of a line of three (ids 1, 2, 3, the built-in
// simulator): only the chosen devices get write frames, each ends with its own result.
class TestProfileRollout : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    QTemporaryDir backups;
    const QStringList changed{QStringLiteral("motor1.speed"),
                              QStringLiteral("motor1.move_distance")};

    SimHost *host() const { return test::simHost(*session); }
    ModbusLink *link() const { return SessionInternals::link(*session); }
    qint64 simValue(int id, const QString &key) const
    {
        return host()->deviceAt(id)->value(key).value_or(-1);
    }
    // The ids the write frames (FC06/FC10) on the wire were addressed to.
    QList<int> writeFrameIds() const
    {
        QList<int> ids;
        for (const TrafficEntry &e : link()->traffic()->entries()) {
            if (e.direction != TrafficEntry::Direction::Sent || e.bytes.size() < 2)
                continue;
            const int fc = quint8(e.bytes.at(1));
            if (fc == 0x06 || fc == 0x10)
                ids << quint8(e.bytes.at(0));
        }
        return ids;
    }
    // Device 1's settings with the two keys changed: what the line's devices do not hold yet.
    Profile changedProfile()
    {
        QHash<QString, qint64> values;
        for (const Parameter *p : Profile::profileParameters(session->map(), false))
            values.insert(p->key, simValue(1, p->key));
        for (const QString &key : changed)
            values[key] += 7;
        Profile profile = Profile::fromValues(session->map(), values, false);
        profile.name = QStringLiteral("axis");
        return profile;
    }
    void connectLine()
    {
        // The window's guard: each device backed up (SessionBackup) before it is written.
        session->risks()->setGuard(
            [this](DeviceSession::Risk risk, int id, DeviceSession::Proceed proceed) {
                SessionBackup::save(session.get(), BackupStore(backups.path()), risk, id,
                                    [proceed](const BackupStore::Saved &saved) {
                                        proceed(saved.ok() ? QString() : saved.error);
                                    });
            });
        test::useBuiltinSimulator(*session, {1, 2, 3});
        session->line()->setDeviceIds({1, 2, 3});
        test::connectToSimulator(*session);
        link()->traffic()->clear();
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        QDir(backups.path()).removeRecursively();
        QDir().mkpath(backups.path());
        connectLine();
    }
    void cleanup() { session.reset(); }

    void appliesToTwoOfThreeOnly()
    {
        const Profile profile = changedProfile();
        const qint64 untouched = simValue(1, changed.first());
        ProfileRollout rollout(session.get(), profile);
        QSignalSpy compared(&rollout, &ProfileRollout::compared);
        rollout.compare({2, 3}, {{2, QStringLiteral("Y axis")}});
        QTRY_COMPARE_WITH_TIMEOUT(compared.size(), 1, 15000);
        QVERIFY2(writeFrameIds().isEmpty(), "comparing writes nothing");
        for (int id : {2, 3}) {
            const RolloutDevice *d = rollout.device(id);
            QVERIFY(d);
            QCOMPARE(d->state, RolloutDevice::State::Compared);
            QCOMPARE(d->chosen, changed);
        }
        QCOMPARE(rollout.chosenValues(), 4);
        QCOMPARE(rollout.chosenDevices(), 2);

        QSignalSpy finished(&rollout, &ProfileRollout::finished);
        rollout.apply();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(finished.first().first().toBool(), true);
        // Only 2 and 3 got write frames; 1, the device in view, none.
        const QList<int> ids = writeFrameIds();
        QVERIFY(!ids.isEmpty());
        QVERIFY2(!ids.contains(1), "no write frame for device 1");
        QVERIFY(ids.contains(2) && ids.contains(3));
        for (int id : {2, 3}) {
            const RolloutDevice *d = rollout.device(id);
            QCOMPARE(d->state, RolloutDevice::State::Written);
            QCOMPARE(d->verified, changed);
            // Its ProfileApply's result, per key, is what the device shows.
            QCOMPARE(d->result.id, id);
            QCOMPARE(d->result.keysIn(AppliedKey::State::Verified), changed);
            for (const QString &key : changed)
                QCOMPARE(simValue(id, key), profile.values.value(key));
        }
        QCOMPARE(simValue(1, changed.first()), untouched);
        QVERIFY(ProfileRollout::describe(*rollout.device(2))
                    .startsWith(QStringLiteral("id 2 (Y axis): written and verified, 2")));
        // One backup per device written, each naming its device's id.
        const QList<BackupEntry> saved = BackupStore(backups.path()).list(session->map());
        QCOMPARE(saved.size(), 2);
        QList<int> backupIds{saved.at(0).deviceId, saved.at(1).deviceId};
        std::sort(backupIds.begin(), backupIds.end());
        QCOMPARE(backupIds, (QList<int>{2, 3}));
    }

    void eachDeviceEndsWithItsOwnResult()
    {
        const Profile profile = changedProfile();
        ProfileRollout rollout(session.get(), profile);
        QSignalSpy compared(&rollout, &ProfileRollout::compared);
        rollout.compare({1, 2, 9}); // no controller of the line has id 9: it cannot be read
        QTRY_COMPARE_WITH_TIMEOUT(compared.size(), 1, 20000);
        QCOMPARE(rollout.device(9)->state, RolloutDevice::State::Failed);
        rollout.choose(2, {}); // the user unchecked every row of device 2
        QSignalSpy finished(&rollout, &ProfileRollout::finished);
        rollout.apply();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 15000);
        QCOMPARE(finished.first().first().toBool(), false); // the worst of them: one failed
        // Device 1 is in view: its store follows the write.
        QCOMPARE(rollout.device(1)->state, RolloutDevice::State::Written);
        QCOMPARE(session->parameters()->store()->deviceValue(changed.first()),
                 std::optional<qint64>(profile.values.value(changed.first())));
        QCOMPARE(rollout.device(2)->state, RolloutDevice::State::Skipped);
        QCOMPARE(rollout.device(2)->reason, QStringLiteral("no value was chosen for it"));
        QVERIFY(!writeFrameIds().contains(2));
        QVERIFY(ProfileRollout::describe(*rollout.device(9)).contains(QStringLiteral("FAILED")));
        QVERIFY(!writeFrameIds().contains(9));
    }

    void anEstopStopsWhatIsLeft()
    {
        const Profile profile = changedProfile();
        ProfileRollout rollout(session.get(), profile);
        QSignalSpy compared(&rollout, &ProfileRollout::compared);
        rollout.compare({2, 3});
        QTRY_COMPARE_WITH_TIMEOUT(compared.size(), 1, 15000);
        QSignalSpy finished(&rollout, &ProfileRollout::finished);
        const qint64 before3 = simValue(3, changed.first());
        rollout.apply(); // device 2's write is queued now
        session->emergencyStop();
        QCOMPARE(finished.size(), 1);
        QCOMPARE(finished.first().first().toBool(), false);
        QCOMPARE(rollout.device(2)->state, RolloutDevice::State::Failed);
        QCOMPARE(rollout.device(3)->state, RolloutDevice::State::Skipped);
        // Nothing more goes out for the rollout: a write would have, ahead of two status polls.
        QVERIFY(test::waitForStatusCycles(*session));
        QVERIFY(!writeFrameIds().contains(3));
        QCOMPARE(simValue(3, changed.first()), before3);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProfileRollout, Guiless)
#include "tst_profilerollout.moc"
