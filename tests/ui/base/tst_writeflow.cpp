#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QSignalSpy>
#include <QTest>
#include <QWidget>

using namespace stepcom;

// WriteFlow: the window's one way from "write" to the controller -- what the dialog shows,
// what accepting it writes, and when it opens nothing.
class TestWriteFlow : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> parent;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    static QStringList keysOf(const QList<ParameterWrite> &writes)
    {
        QStringList keys;
        for (const ParameterWrite &w : writes)
            keys << w.parameter->key;
        return keys;
    }

private Q_SLOTS:
    void init()
    {
        session = std::make_unique<DeviceSession>();
        parent = std::make_unique<QWidget>();
    }
    void cleanup()
    {
        parent.reset();
        session.reset();
    }

    void opensNothingWhileDisconnected()
    {
        WriteFlow flow(session.get(), parent.get());
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 450).isEmpty());
        QVERIFY(!flow.openAll());
        QVERIFY(!flow.openFor({QStringLiteral("motor1.speed")}));
        QVERIFY(!flow.dialog());
    }

    void opensNothingWithoutEdits()
    {
        test::connectToSimulator(*session);
        WriteFlow flow(session.get(), parent.get());
        QVERIFY(!flow.openAll());
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor2.speed"), 500).isEmpty());
        QVERIFY(!flow.openFor({QStringLiteral("motor1.speed")})); // only other keys are edited
        QVERIFY(!flow.dialog());
    }

    void writesOnlyTheKeysAskedForAndKeepsTheRest()
    {
        test::connectToSimulator(*session);
        WriteFlow flow(session.get(), parent.get());
        ParameterStore *store = session->parameters()->store();
        QVERIFY(store->edit(QStringLiteral("motor1.speed"), 450).isEmpty());
        QVERIFY(store->edit(QStringLiteral("motor2.speed"), 500).isEmpty());
        QVERIFY(flow.openFor({QStringLiteral("motor1.speed")}));
        QVERIFY(flow.dialog());
        QCOMPARE(keysOf(flow.dialog()->writes()), QStringList{QStringLiteral("motor1.speed")});
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300); // nothing before accepting
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        flow.dialog()->accept();
        QTRY_COMPARE(written.size(), 1);
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(store->state(QStringLiteral("motor1.speed")), ParameterStore::State::InSync);
        QCOMPARE(store->state(QStringLiteral("motor2.speed")), ParameterStore::State::Edited);
        QCOMPARE(*sim()->value(QStringLiteral("motor2.speed")), 300);
    }

    // Accepting the dialog says what goes out (the window's session log hears it).
    void acceptingSaysWhatIsWritten()
    {
        test::connectToSimulator(*session);
        WriteFlow flow(session.get(), parent.get());
        QSignalSpy confirmed(&flow, &WriteFlow::confirmed);
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 450).isEmpty());
        QVERIFY(flow.openFor({QStringLiteral("motor1.speed")}));
        QVERIFY(confirmed.isEmpty()); // nothing before accepting
        flow.dialog()->accept();
        QCOMPARE(confirmed.size(), 1);
        QCOMPARE(confirmed.first().first().toString(), QStringLiteral("motor1.speed = 450"));
    }

    // Writes the caller has asked about itself: no dialog, but said, written and verified as
    // the dialog's are.
    void writeConfirmedOpensNothingAndVerifies()
    {
        test::connectToSimulator(*session);
        WriteFlow flow(session.get(), parent.get());
        QSignalSpy confirmed(&flow, &WriteFlow::confirmed);
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        const Parameter *speed = session->map().find(QStringLiteral("motor2.speed"));
        QVERIFY(speed);
        QVERIFY(flow.writeConfirmed({ParameterWrite{speed, 420}}));
        QVERIFY(!flow.dialog());
        QCOMPARE(confirmed.size(), 1);
        QCOMPARE(confirmed.first().first().toString(), QStringLiteral("motor2.speed = 420"));
        QTRY_COMPARE(written.size(), 1);
        QCOMPARE(*sim()->value(QStringLiteral("motor2.speed")), 420);
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor2.speed")),
                 ParameterStore::State::InSync);
    }

    void aNewRequestReplacesTheOpenDialogAndRejectingWritesNothing()
    {
        test::connectToSimulator(*session);
        WriteFlow flow(session.get(), parent.get());
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 450).isEmpty());
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor2.speed"), 500).isEmpty());
        QVERIFY(flow.openFor({QStringLiteral("motor1.speed")}));
        QPointer<WriteChangesDialog> first = flow.dialog();
        QVERIFY(flow.openAll());
        QTRY_VERIFY(!first); // closed and gone
        QCOMPARE(flow.dialog()->writes().size(), 2);
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        flow.dialog()->reject();
        QVERIFY(test::waitForStatusCycles(*session)); // a write would have gone out by then
        QCOMPARE(written.size(), 0);
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestWriteFlow, Gui)
#include "tst_writeflow.moc"
