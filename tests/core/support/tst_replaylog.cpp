// ReplayLog (core/support): session logs written here line by line in SessionLog's format, read
// back into every controller's state and the events; what a bad log gives; the snapshots that
// make a seek cheap agree with reading from the start; the session log's own header and marks.
#include "logbuilder.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/sessionlog.h"
#include "simsession.h"
#include "support/replaylog.h"

#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using stepcom::test::LogBuilder;

namespace {

const RegisterMap &map()
{
    return RegisterMap::builtin();
}

quint16 addressOf(const char *key)
{
    return map().find(QLatin1String(key))->address;
}

qint64 valueAt(const ReplayLog &log, qint64 ms, const char *key, int id = 1)
{
    return log.stateAt(ms).devices.value(id).values(map()).value(QLatin1String(key), -1);
}

} // namespace

class TestReplayLog : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

private Q_SLOTS:
    void readsAndWritesGiveTheStateAtEachMoment()
    {
        LogBuilder b;
        b.header();
        b.read(1, 0, {180, 8}); // motor1.step_angle, motor1.microsteps at 0 ms
        b.time = b.time.addMSecs(980);
        b.read(1, addressOf("motor1.speed"), {300}); // at 1000 ms
        b.time = b.time.addMSecs(980);
        b.write(1, addressOf("motor1.speed"), {450}); // at 2000 ms
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir)), qPrintable(log.errorString()));
        QVERIFY(log.warnings().isEmpty());
        QCOMPARE(log.durationMs(), 2010);
        QCOMPARE(valueAt(log, 9, "motor1.step_angle"), -1); // asked, not answered yet
        QCOMPARE(valueAt(log, 10, "motor1.step_angle"), 180);
        QCOMPARE(valueAt(log, 10, "motor1.speed"), -1); // not read yet
        QCOMPARE(valueAt(log, 1500, "motor1.speed"), 300);
        QCOMPARE(valueAt(log, 2500, "motor1.speed"), 450);
        QCOMPARE(valueAt(log, 99999999, "motor1.speed"), 450); // past the end: the last state
        const ReplayState last = log.stateAt(log.durationMs());
        QCOMPARE(last.devices.value(1).writtenValues(map()).value(QStringLiteral("motor1.speed")),
                 450);
        QCOMPARE(log.events().size(), 1);
        const ReplayEvent &e = log.events().first();
        QCOMPARE(e.kind, ReplayEvent::Kind::Write);
        QCOMPARE(e.device, 1);
        QCOMPARE(e.ms, 2010);
        QCOMPARE(e.text, QStringLiteral("motor1.speed 300 rpm → 450 rpm"));
    }

    void answersArePairedAsTheLinkPairsThem()
    {
        LogBuilder b;
        b.header();
        const quint16 speed = addressOf("motor1.speed");
        // An echo of the read, then its answer.
        b.frame(true, LogBuilder::readRequest(1, speed, 1));
        b.frame(false, LogBuilder::readRequest(1, speed, 1));
        b.frame(false, RtuFrame::adu(1, QModbusResponse(QModbusPdu::ReadHoldingRegisters,
                                                        QByteArray::fromHex("02012C"))));
        // A read with no answer, then another one, then the first one's answer, late.
        b.frame(true, LogBuilder::readRequest(1, 0, 2));
        b.frame(true, LogBuilder::readRequest(1, speed, 1));
        b.frame(false, RtuFrame::adu(1, QModbusResponse(QModbusPdu::ReadHoldingRegisters,
                                                        QByteArray::fromHex("0400B40008"))));
        // A refused read.
        b.frame(true, LogBuilder::readRequest(1, 111, 2));
        b.frame(false, LogBuilder::withCrc(QByteArray::fromHex("018302")));
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir)), qPrintable(log.errorString()));
        QList<ReplayEvent::Kind> kinds;
        for (const ReplayEvent &e : log.events())
            kinds << e.kind;
        QCOMPARE(kinds, (QList<ReplayEvent::Kind>{
                            ReplayEvent::Kind::Timeout, ReplayEvent::Kind::LateAnswer,
                            ReplayEvent::Kind::Timeout, ReplayEvent::Kind::Exception}));
        const ReplayDevice d = log.stateAt(log.durationMs()).devices.value(1);
        QCOMPARE(d.values(map()).value(QStringLiteral("motor1.speed")), 300);
        QVERIFY(!d.values(map()).contains(QStringLiteral("motor1.step_angle"))); // late: dropped
        QVERIFY2(d.lastError.contains(QLatin1String("40112")), qPrintable(d.lastError));
        QVERIFY(d.answering);
    }

    // Modbus TCP frames carry the MBAP header instead of the CRC.
    void modbusTcpFramesAreReadToo()
    {
        LogBuilder b;
        b.text += QStringLiteral("# line: transport=tcp host=127.0.0.1 port=502 id=3\n");
        b.frame(true, QByteArray::fromHex("000100000006030300050001"));
        b.frame(false, QByteArray::fromHex("00010000000503030201C2"));
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir)), qPrintable(log.errorString()));
        QCOMPARE(valueAt(log, log.durationMs(), "motor1.speed", 3), 450);
    }

    void commandsTheEstopAndTheSessionsMarksAreEvents()
    {
        LogBuilder b;
        b.header();
        b.mark(SessionLog::kLinkUp, QStringLiteral("/dev/ttyUSB0 · 9600 8N1 · id 1"));
        b.coil(1, map().find(QStringLiteral("motor1.move"))->address);
        b.mark(SessionLog::kUser, QStringLiteral("E-STOP pressed"));
        b.coil(2, map().find(QStringLiteral("estop"))->address);
        b.coil(1, map().find(QStringLiteral("estop"))->address, false);
        b.mark(SessionLog::kRestart, QStringLiteral("id 2: motor1.speed 222 → 120 rpm"));
        b.mark(SessionLog::kLinkDown, QStringLiteral("the port vanished"));
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir)), qPrintable(log.errorString()));
        QStringList seen;
        for (const ReplayEvent &e : log.events())
            seen << QStringLiteral("%1 %2 %3")
                        .arg(e.device)
                        .arg(ReplayEvent::kindName(e.kind), e.text);
        QCOMPARE(seen, (QStringList{
                           "0 link-up /dev/ttyUSB0 · 9600 8N1 · id 1", "1 command motor1.move",
                           "0 user E-STOP pressed", "2 estop E-STOP acknowledged",
                           "2 restart id 2: motor1.speed 222 → 120 rpm",
                           "1 estop E-STOP sent, not acknowledged",
                           "1 timeout no answer: command estop", "0 link-down the port vanished"}));
        QVERIFY(log.stateAt(40).linkUp);
        QVERIFY(!log.stateAt(log.durationMs()).linkUp);
    }

    // A possible restart is an event of its own kind, said as the session said it; the device
    // list does not claim it restarted.
    void aPossibleRestartIsAnEventOfItsOwn()
    {
        LogBuilder b;
        b.header();
        b.coil(1, map().find(QStringLiteral("motor1.home"))->address);
        b.mark("possible-restart",
               QStringLiteral("id 1 may have restarted: silent 1.6 s; zeroed motor1; stood still "
                              "motor2; moving motor1; before motor1=12.00, motor2=0.00"));
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir)), qPrintable(log.errorString()));
        QStringList seen;
        for (const ReplayEvent &e : log.events())
            seen << QStringLiteral("%1 %2 %3")
                        .arg(e.device)
                        .arg(ReplayEvent::kindName(e.kind), e.text.section(QLatin1Char(':'), 0, 0));
        QCOMPARE(seen, (QStringList{"1 command motor1.home",
                                    "1 possible-restart id 1 may have restarted"}));
        QCOMPARE(log.stateAt(log.durationMs()).devices.value(1).restartMs, -1);
    }

    void badLogsGiveNamedErrors_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<int>("problem");
        QTest::addColumn<QString>("message");
        QTest::newRow("empty") << QByteArray() << int(ReplayLog::Problem::Empty) << "is empty";
        QTest::newRow("only a header") << QByteArray("# StepCom 0.1.0 session log, part 1: x\n")
                                       << int(ReplayLog::Problem::Empty) << "holds no frames";
        QTest::newRow("not a log")
            << QByteArray("hello\nworld\n") << int(ReplayLog::Problem::NotALog)
            << "not a StepCom session log: not one of its lines is one (2 lines)";
        QTest::newRow("a zip") << QByteArray("PK\x03\x04rest") << int(ReplayLog::Problem::NotALog)
                               << "is a zip file";
        QTest::newRow("other map")
            << QByteArray("# StepCom 0.1.0 session log, part 1: x\n# map: other/9\n")
            << int(ReplayLog::Problem::OtherMap)
            << "line 2: the log was recorded with the "
               "register map other/9, not with stepper2/1";
    }
    void badLogsGiveNamedErrors()
    {
        QFETCH(QByteArray, content);
        QFETCH(int, problem);
        QFETCH(QString, message);
        const QString path = dir.filePath(QStringLiteral("bad.log"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(content);
        f.close();
        ReplayLog log;
        QVERIFY(!log.open(path));
        QCOMPARE(int(log.problem()), problem);
        QVERIFY2(log.errorString().contains(message), qPrintable(log.errorString()));
        QVERIFY(!log.open(dir.filePath(QStringLiteral("nothing.log"))));
        QCOMPARE(log.problem(), ReplayLog::Problem::NotFound);
    }

    void garbageAndACutLastLineAreWarnings()
    {
        LogBuilder b;
        b.header();
        b.read(1, 0, {180, 8});
        b.text += QStringLiteral("garbage here\n");
        b.read(1, addressOf("motor1.speed"), {300});
        b.text += QStringLiteral("2026-11-24 22:10:00.100  TX  poll     01 0G\n");        // bad hex
        b.text += QStringLiteral("2026-11-24 22:10:00.200  TX  poll     01 03 00 00 00"); // cut
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir)), qPrintable(log.errorString()));
        QCOMPARE(log.garbageLines(), 2);
        QCOMPARE(log.garbageLineNumbers(), (QList<qint64>{8, 11}));
        QVERIFY(log.truncated());
        const QString warnings = log.warnings().join(QLatin1Char('\n'));
        QVERIFY2(warnings.contains(QLatin1String("lines not of a session log, skipped: 2 (line "
                                                 "8, 11)")),
                 qPrintable(warnings));
        QVERIFY2(warnings.contains(QLatin1String("in the middle of line 12")),
                 qPrintable(warnings));
        QCOMPARE(valueAt(log, log.durationMs(), "motor1.speed"), 300);
    }

    // A long log: the state found through the snapshots is the one read from the start.
    void snapshotsAgreeWithReadingFromTheStart()
    {
        LogBuilder b;
        b.header();
        const quint16 position = addressOf("motor1.position");
        const int reads = 12000; // about 1.3 MB: several snapshots
        for (int i = 0; i < reads; ++i)
            b.read(1, position, {quint16(i), 0}); // answered at i * 20 + 10 ms
        ReplayLog log;
        int progress = 0;
        ReplayLog::Callbacks callbacks;
        callbacks.progress = [&progress](qint64, qint64) { ++progress; };
        QVERIFY2(log.open(b.save(dir), callbacks), qPrintable(log.errorString()));
        QVERIFY2(log.snapshotCount() > 3, qPrintable(QString::number(log.snapshotCount())));
        QVERIFY(progress > 0);
        for (const qint64 ms : {qint64(0), qint64(9), qint64(10), qint64(12345), qint64(555555),
                                qint64(1199999), log.durationMs()}) {
            const qint64 expected = ms < 10 ? -1 : std::min<qint64>(reads - 1, (ms - 10) / 20);
            QCOMPARE(valueAt(log, ms, "motor1.position"), expected);
        }
        // The lines of a stretch, in order, each with the state after it (the plots).
        QList<qint64> positions;
        QStringList raw;
        log.walk(100000, 100100,
                 [&](QByteArrayView line, const LogLine &, qint64, const ReplayState &state) {
                     raw << QString::fromUtf8(line).trimmed();
                     positions << state.devices.value(1).values(map()).value(
                         QStringLiteral("motor1.position"));
                     return true;
                 });
        QCOMPARE(positions,
                 (QList<qint64>{4999, 5000, 5000, 5001, 5001, 5002, 5002, 5003, 5003, 5004, 5004}));
        QVERIFY2(raw.first().startsWith(QLatin1String("2026-11-24 22:11:40.000  TX  ")),
                 qPrintable(raw.first()));
    }

    void openingCanBeCancelled()
    {
        LogBuilder b;
        b.header();
        for (int i = 0; i < 12000; ++i)
            b.read(1, 0, {quint16(i), 8});
        ReplayLog log;
        ReplayLog::Callbacks callbacks;
        callbacks.cancelled = [] { return true; };
        QVERIFY(!log.open(b.save(dir), callbacks));
        QCOMPARE(log.problem(), ReplayLog::Problem::Cancelled);
    }

    void timesAreSecondsOrClockTimes_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<qint64>("ms");
        QTest::newRow("seconds") << "12.5" << qint64(12500);
        QTest::newRow("zero") << "0" << qint64(0);
        QTest::newRow("clock") << "22:10:01.5" << qint64(1500);
        QTest::newRow("clock, no ms") << "22:10:03" << qint64(3000);
        QTest::newRow("before the start") << "21:00:00" << qint64(-1);
        QTest::newRow("not a time") << "soon" << qint64(-1);
        QTest::newRow("negative") << "-3" << qint64(-1);
    }
    void timesAreSecondsOrClockTimes()
    {
        QFETCH(QString, text);
        QFETCH(qint64, ms);
        LogBuilder b;
        b.header();
        b.read(1, 0, {180, 8});
        ReplayLog log;
        QVERIFY(log.open(b.save(dir)));
        QString error;
        const auto parsed = log.parseTime(text, &error);
        QCOMPARE(parsed.value_or(-1), ms);
        QCOMPARE(error.isEmpty(), ms >= 0);
    }

    // What StepCom writes replays: the session log's header and marks, from a real session.
    void theSessionLogWritesAReplayableHeader()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session);
        SessionLog sessionLog(&session);
        const QString path = dir.filePath(QStringLiteral("session.log"));
        sessionLog.setFile(path);
        test::connectToSimulator(session);
        sessionLog.noteUserAction(QStringLiteral("page: Motor 1"));
        session.connection()->disconnectFrom();
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains(QStringLiteral("\n# map: %1\n").arg(map().identity())),
                 qPrintable(text.left(600)));
        QVERIFY(text.contains(QLatin1String("\n# line: transport=rtu port=")));
        QVERIFY(text.contains(QLatin1String("\n# ids: 1\n")));
        ReplayLog log;
        QVERIFY2(log.open(path), qPrintable(log.errorString()));
        QVERIFY2(log.warnings().isEmpty(), qPrintable(log.warnings().join(QLatin1Char('\n'))));
        QStringList kinds;
        for (const ReplayEvent &e : log.events())
            kinds << ReplayEvent::kindName(e.kind) + QLatin1Char(' ') + e.text;
        // The built-in simulator is named where the link comes up, so no log passes for a
        // machine's.
        QCOMPARE(kinds, (QStringList{"link-up built-in simulator, not a machine: " +
                                         session.connection()->settings().describe(),
                                     "user page: Motor 1", "link-down disconnected by the user"}));

        // Everything the read-all read, as the store holds it.
        const QHash<QString, qint64> replayed =
            log.stateAt(log.durationMs()).devices.value(1).values(map());
        for (const Parameter *p : map().holdings()) {
            const auto held = session.parameters()->store()->deviceValue(p->key);
            if (held)
                QCOMPARE(replayed.value(p->key, -1), *held);
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReplayLog, Guiless)
#include "tst_replaylog.moc"
