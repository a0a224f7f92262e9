#include "device/parameterstore.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

class TestParameterStore : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();
    ParameterWrite w(ParameterStore &s, const char *key, qint64 raw)
    {
        return {s.map().find(QString::fromLatin1(key)), raw};
    }

private Q_SLOTS:
    void statesFollowTheDevice()
    {
        ParameterStore store(map);
        const QString speed = QStringLiteral("motor1.speed");
        QCOMPARE(store.state(speed), ParameterStore::State::Unknown);
        store.setDeviceValues({{speed, 300}});
        QCOMPARE(store.state(speed), ParameterStore::State::InSync);
        QVERIFY(store.edit(speed, 450).isEmpty());
        QCOMPARE(store.state(speed), ParameterStore::State::Edited);
        QCOMPARE(*store.shownValue(speed), 450);
        QCOMPARE(*store.deviceValue(speed), 300);
        // a poll never overwrites what the user typed
        store.setDeviceValues({{speed, 310}});
        QCOMPARE(*store.shownValue(speed), 450);
        // editing back to what the device holds is no edit
        QVERIFY(store.edit(speed, 310).isEmpty());
        QCOMPARE(store.state(speed), ParameterStore::State::InSync);
        QVERIFY(!store.hasEdits());
    }

    void rejectsBadEdits()
    {
        ParameterStore store(map);
        QVERIFY(store.edit(QStringLiteral("motor1.speed"), 99999)
                    .contains(QStringLiteral("out of range")));
        QVERIFY(
            store.edit(QStringLiteral("motor1.position"), 0).contains(QStringLiteral("read-only")));
        QVERIFY(store.edit(QStringLiteral("nope"), 0).contains(QStringLiteral("unknown")));
        QVERIFY(!store.hasEdits());
    }

    void writeOutcomeUpdatesStates()
    {
        ParameterStore store(map);
        QSignalSpy unsaved(&store, &ParameterStore::unsavedChanged);
        store.setDeviceValues({{QStringLiteral("motor1.speed"), 300},
                               {QStringLiteral("motor1.microsteps"), 8},
                               {QStringLiteral("motor2.speed"), 300}});
        store.edit(QStringLiteral("motor1.speed"), 450);
        store.edit(QStringLiteral("motor1.microsteps"), 16);
        store.edit(QStringLiteral("motor2.speed"), 100);
        const QList<ParameterWrite> writes = store.pendingWrites();
        QCOMPARE(writes.size(), 3);
        WriteOutcome outcome;
        outcome.written = {QStringLiteral("motor1.speed"), QStringLiteral("motor1.microsteps")};
        outcome.mismatches.append({QStringLiteral("motor1.microsteps"), 16, 8});
        outcome.notWritten = {QStringLiteral("motor2.speed")};
        outcome.errors = {QStringLiteral("x")};
        store.applyWriteOutcome(writes, outcome);
        QCOMPARE(store.state(QStringLiteral("motor1.speed")), ParameterStore::State::InSync);
        QCOMPARE(*store.deviceValue(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(store.state(QStringLiteral("motor1.microsteps")),
                 ParameterStore::State::WriteFailed);
        QVERIFY(store.entry(QStringLiteral("motor1.microsteps"))
                    .error.contains(QStringLiteral("holds 8")));
        QCOMPARE(store.state(QStringLiteral("motor2.speed")), ParameterStore::State::WriteFailed);
        QCOMPARE(*store.shownValue(QStringLiteral("motor2.speed")), 100); // the edit is kept
        QVERIFY(store.unsavedToFlash());
        QCOMPARE(unsaved.size(), 1);
    }

    void aWriteWithoutAnswerLeavesTheDeviceValueUnknown()
    {
        ParameterStore store(map);
        store.setDeviceValues({{QStringLiteral("motor1.speed"), 300}});
        store.edit(QStringLiteral("motor1.speed"), 450);
        WriteOutcome outcome; // sent, timed out: neither written nor "not written"
        outcome.errors = {QStringLiteral("motor1.speed: no answer")};
        store.applyWriteOutcome(store.pendingWrites(), outcome);
        QCOMPARE(store.state(QStringLiteral("motor1.speed")), ParameterStore::State::WriteFailed);
        QCOMPARE(store.deviceValue(QStringLiteral("motor1.speed")), std::nullopt); // not 300
        QCOMPARE(*store.shownValue(QStringLiteral("motor1.speed")), 450);
    }

    // A parameter the controller lacks: its own state, no value, no edit, no pending write;
    // another controller (or the same one, learnt again) brings it back.
    void unsupportedParameters()
    {
        ParameterStore store(map);
        const QString speed = QStringLiteral("motor2.speed");
        store.setDeviceValues({{speed, 300}});
        QVERIFY(store.edit(speed, 450).isEmpty());
        store.setUnsupported({speed});
        QCOMPARE(store.state(speed), ParameterStore::State::Unsupported);
        QVERIFY(store.isUnsupported(speed));
        QVERIFY(!store.deviceValue(speed));
        QVERIFY(store.pendingWrites().isEmpty());
        QVERIFY(store.edit(speed, 500).contains(QStringLiteral("not supported")));
        QCOMPARE(store.state(QStringLiteral("motor1.speed")), ParameterStore::State::Unknown);
        store.setUnsupported({});
        QCOMPARE(store.state(speed), ParameterStore::State::Unknown);
        store.setDeviceValues({{speed, 300}});
        QCOMPARE(store.state(speed), ParameterStore::State::InSync);
    }

    void forgettingKeepsEdits()
    {
        ParameterStore store(map);
        store.setDeviceValues({{QStringLiteral("motor1.speed"), 300}});
        store.edit(QStringLiteral("motor1.speed"), 450);
        store.forgetDeviceValues();
        QVERIFY(!store.deviceValue(QStringLiteral("motor1.speed")));
        QCOMPARE(*store.shownValue(QStringLiteral("motor1.speed")), 450);
        store.revertAll();
        QCOMPARE(store.state(QStringLiteral("motor1.speed")), ParameterStore::State::Unknown);
    }

    // A replayed moment stands where the controller's values would: the moment's
    // values only, edits dropped, kept when a link is lost, forgotten when the replay closes.
    void aReplayedMomentHoldsOnlyItsValues()
    {
        ParameterStore store(map);
        const QString speed = QStringLiteral("motor1.speed");
        const QString pitch = QStringLiteral("motor1.pitch");
        store.setDeviceValues({{speed, 300}, {pitch, 500}});
        QVERIFY(store.edit(speed, 450).isEmpty());
        QSignalSpy origin(&store, &ParameterStore::originChanged);
        store.showReplay(QStringLiteral("a.log"), {{speed, 320}});
        QVERIFY(store.isReplay());
        QCOMPARE(store.replayName(), QStringLiteral("a.log"));
        QCOMPARE(store.deviceValue(speed), 320);
        QCOMPARE(store.state(speed), ParameterStore::State::InSync);
        QVERIFY(!store.deviceValue(pitch).has_value());
        QVERIFY(!store.hasEdits());
        store.showReplay(QStringLiteral("a.log"), {{pitch, 250}}); // another moment
        QVERIFY(!store.deviceValue(speed).has_value());
        QCOMPARE(store.deviceValue(pitch), 250);
        QCOMPARE(origin.size(), 1); // one replay, many moments
        store.forgetDeviceValues(); // no link to lose
        QCOMPARE(store.deviceValue(pitch), 250);
        store.closeReplay();
        QVERIFY(!store.isReplay());
        QVERIFY(!store.deviceValue(pitch).has_value());
        QCOMPARE(origin.size(), 2);
        // A profile file opened during a replay ends it.
        store.showReplay(QStringLiteral("a.log"), {{pitch, 250}});
        store.openFile(QStringLiteral("m.json"), {{speed, 400}});
        QVERIFY(!store.isReplay());
        QVERIFY(store.isFile());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestParameterStore, Guiless)
#include "tst_parameterstore.moc"
