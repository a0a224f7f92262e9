// The live view on connect: the status is read before everything else, and it keeps
// running on a controller that refuses gap reads or lacks a listed register.
#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

namespace {

// The FC03 requests that went out, as (first PLC register, count).
QList<std::pair<int, int>> readsSent(const DeviceSession &session)
{
    QList<std::pair<int, int>> out;
    for (const TrafficEntry &e : session.connection()->traffic()->entries()) {
        if (e.direction != TrafficEntry::Direction::Sent || e.bytes.size() < 8 ||
            quint8(e.bytes.at(1)) != 0x03)
            continue;
        const int address = (quint8(e.bytes.at(2)) << 8) | quint8(e.bytes.at(3));
        const int count = (quint8(e.bytes.at(4)) << 8) | quint8(e.bytes.at(5));
        out.append({40001 + address, count});
    }
    return out;
}

LinkSettings ptyLink(const SimHost &host)
{
    LinkSettings s;
    s.portName = host.rtuPath();
    s.baud = 9600;
    s.deviceId = 1;
    return s;
}

} // namespace

class TestLiveView : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void statusBeforeEverythingElse()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        DeviceSession session;
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        session.connection()->connectTo(ptyLink(host));
        QVERIFY(read.wait(10000));
        QCOMPARE(read.first().first().toBool(), true);
        const QList<std::pair<int, int>> sent = readsSent(session);
        // The status plan first (positions .. inputs, outputs .. running), then the read-all.
        QVERIFY2(sent.size() >= 7, qPrintable(QString::number(sent.size())));
        QCOMPARE(sent.at(0), (std::pair<int, int>{40108, 20}));
        QCOMPARE(sent.at(1), (std::pair<int, int>{40148, 22}));
        QCOMPARE(sent.at(2), (std::pair<int, int>{40001, 20}));
    }

    void liveViewGoesOn_data()
    {
        QTest::addColumn<bool>("lacks");
        QTest::newRow("refuses gaps") << false;
        QTest::newRow("lacks 40110") << true;
    }
    void liveViewGoesOn()
    {
        QFETCH(bool, lacks);
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.strictReads = true;
        if (lacks)
            options.lacks = {QStringLiteral("40110")};
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        DeviceSession session;
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        QSignalSpy learnt(session.connection(), &SessionConnection::readLimitsLearned);
        session.connection()->connectTo(ptyLink(host));
        QVERIFY(read.wait(10000));
        QCOMPARE(read.first().first().toBool(), true); // the read-all went on
        QCOMPARE(learnt.size(), lacks ? 2 : 1);        // said once each
        QVERIFY(session.connection()->readLimits().gapFree());
        const ParameterStore *store = session.parameters()->store();
        QCOMPARE(store->state(QStringLiteral("motor2.position")),
                 lacks ? ParameterStore::State::Unsupported : ParameterStore::State::InSync);
        QCOMPARE(store->state(QStringLiteral("motor1.speed")), ParameterStore::State::InSync);
        // The live view follows the inputs, cycle after cycle, without failures.
        host.device()->setInput(3, SimDevice::InputForce::On);
        QTRY_COMPARE_WITH_TIMEOUT(store->deviceValue(QStringLiteral("io.in3")).value_or(-1), 1,
                                  5000);
        QSignalSpy cycles(session.status(), &SessionStatus::statusCycleFinished);
        QTRY_VERIFY_WITH_TIMEOUT(cycles.size() >= 3, 5000);
        for (const QList<QVariant> &c : std::as_const(cycles))
            QVERIFY(c.first().toBool());
        QCOMPARE(learnt.size(), lacks ? 2 : 1); // nothing more to learn
        // No read after the lessons covers an unlisted or lacking register.
        const QList<std::pair<int, int>> sent = readsSent(session);
        for (qsizetype i = sent.size() - 4; i < sent.size(); ++i) {
            for (int plc = sent.at(i).first; plc < sent.at(i).first + sent.at(i).second; ++plc) {
                const Parameter *p = session.map().holdingAt(quint16(plc - 40001));
                QVERIFY2(p, qPrintable(QString::number(plc)));
                QVERIFY(!lacks || p->key != QLatin1String("motor2.position"));
            }
        }
    }

    // Several controllers on one line: what one refuses is learnt for its id alone.
    void limitsArePerDeviceId()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.ids = {1, 2};
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        host.deviceAt(2)->setStrictReads(true);
        host.deviceAt(2)->setLacking({QStringLiteral("motor2.position")});
        DeviceSession session;
        session.line()->setDeviceIds({1, 2});
        session.line()->setBackgroundIntervalMs(100);
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        QSignalSpy learnt(session.connection(), &SessionConnection::readLimitsLearned);
        session.connection()->connectTo(ptyLink(host));
        QVERIFY(read.wait(10000));
        QCOMPARE(read.first().first().toBool(), true);
        // The background poll of id 2 learns both lessons, said with the id.
        QTRY_COMPARE_WITH_TIMEOUT(learnt.size(), 2, 10000);
        for (const QList<QVariant> &l : std::as_const(learnt))
            QVERIFY2(l.first().toString().startsWith(QLatin1String("Device id 2: ")),
                     qPrintable(l.first().toString()));
        const ParameterStore *store = session.parameters()->store();
        QVERIFY(
            session.connection()->readLimits().isEmpty()); // id 1 reads its merged plan as before
        QCOMPARE(store->state(QStringLiteral("motor2.position")), ParameterStore::State::InSync);

        read.clear();
        QVERIFY(session.line()->showDevice(2));
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QVERIFY(read.first().first().toBool());
        QVERIFY(session.connection()->readLimits().gapFree());
        QCOMPARE(store->state(QStringLiteral("motor2.position")),
                 ParameterStore::State::Unsupported);
        QCOMPARE(learnt.size(), 2); // nothing learnt twice

        read.clear();
        QVERIFY(session.line()->showDevice(1));
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QVERIFY(session.connection()->readLimits().isEmpty());
        QCOMPARE(store->state(QStringLiteral("motor2.position")), ParameterStore::State::InSync);
    }

    // Kept in the saved connection settings: the next session reads gap-free at once and
    // says once in words what it knew.
    void knownLimitsNeedNoLearning()
    {
        SimHost host;
        SimOptions options;
        options.rtu = true;
        options.strictReads = true;
        options.lacks = {QStringLiteral("motor2.speed")};
        QString error;
        QVERIFY2(host.start(options, &error), qPrintable(error));
        QMap<QString, QString> known;
        {
            DeviceSession first;
            QSignalSpy read(first.parameters(), &SessionParameters::readFinished);
            first.connection()->connectTo(ptyLink(host));
            QVERIFY(read.wait(10000));
            known = first.connection()->knownReadLimits();
        }
        const QString key = SessionConnection::lineKey(ptyLink(host)) + QStringLiteral("#1");
        QCOMPARE(known, (QMap<QString, QString>{{key, QStringLiteral("gaps,motor2.speed")}}));

        DeviceSession session;
        session.connection()->setKnownReadLimits(
            {{key, QStringLiteral("gaps,motor2.speed,not a key!")}, {QStringLiteral("x"), {}}});
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        QSignalSpy learnt(session.connection(), &SessionConnection::readLimitsLearned);
        QSignalSpy messages(&session, &DeviceSession::message);
        session.connection()->connectTo(ptyLink(host));
        QVERIFY(read.wait(10000));
        QVERIFY(read.first().first().toBool());
        QCOMPARE(learnt.size(), 0);
        QCOMPARE(session.connection()->linkStats().exceptions, 0); // not one refused read
        QCOMPARE(session.parameters()->store()->state(QStringLiteral("motor2.speed")),
                 ParameterStore::State::Unsupported);
        QStringList said;
        for (const QList<QVariant> &m : std::as_const(messages))
            said << m.at(1).toString();
        QCOMPARE(said.filter(QStringLiteral("Known from an earlier connection")).size(), 1);
        QCOMPARE(session.connection()->knownReadLimits(), known);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestLiveView, Guiless)
#include "tst_liveview.moc"
