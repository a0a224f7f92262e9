// What a replay's views stand on beside the state, in the core: the track of each
// controller's status through the whole log (the plots up to any moment, the XY path from the
// start), thinned only beyond its bound; the last lines before a moment (the traffic view),
// read from a snapshot; each device's requests, errors and restarts; the names of the devices
// in the log's header.
#include "logbuilder.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/sessionlog.h"
#include "simsession.h"
#include "support/replaylog.h"

#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace stepcom;
using stepcom::test::LogBuilder;

namespace {

const RegisterMap &trackMap()
{
    return RegisterMap::builtin();
}

const Parameter *param(const char *key)
{
    return trackMap().find(QLatin1String(key));
}

// A 32-bit position as the controller's two words, low word first as the map decodes it.
QList<quint16> positionWords(const Parameter *p, qint64 raw)
{
    return p->encode(raw);
}

} // namespace

class TestReplayTrack : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

    // Motor 1 and 2 positions read every 100 ms for `seconds`, motor 1 at i, motor 2 at 2i
    // (raw); motor 1 stands still from `restFrom` on.
    QString movingLog(int seconds, int restFrom = -1)
    {
        LogBuilder b;
        b.header();
        const Parameter *p1 = param("motor1.position");
        const Parameter *p2 = param("motor2.position");
        for (int i = 0; i < seconds * 10; ++i) {
            const int x = restFrom >= 0 && i >= restFrom * 10 ? restFrom * 10 : i;
            b.read(1, p1->address, positionWords(p1, x));
            b.read(1, p2->address, positionWords(p2, 2 * i));
            b.time = b.time.addMSecs(60); // 4 frames of 10 ms, then the rest of the 100 ms
        }
        return b.save(dir, QStringLiteral("moving-%1-%2.log").arg(seconds).arg(restFrom));
    }

private Q_SLOTS:
    // Every change is a sample, at the answer that brought it; the plots' columns as the
    // recorder has them.
    void theTrackHoldsEveryChange()
    {
        ReplayLog log;
        QVERIFY2(log.open(movingLog(120)), qPrintable(log.errorString()));
        const ReplayTrack &track = log.track();
        QCOMPARE(track.devices(), QList<int>{1});
        // Two answers a cycle, each a change (one position, then the other).
        QCOMPARE(track.size(1), 2 * 1200);
        QCOMPARE(track.thinnedToMs(), 0);
        const QList<StatusSample> all = track.samples(1, 0, log.durationMs(), 1000000);
        QCOMPARE(all.size(), 2 * 1200);
        const double scale1 = param("motor1.position")->scale;
        QCOMPARE(all.first().elapsedMs, 10); // the first answer
        QCOMPARE(all.first().epochMs, 1000010);
        QCOMPARE(all.first().positions.value(0), 0.0);
        QVERIFY(std::isnan(all.first().positions.value(1))); // not read yet
        QCOMPARE(all.first().running.value(0), qint8(-1));
        QCOMPARE(all.last().positions.value(0), 1199 / scale1);
        // A stretch: the samples from one moment through another, in time order.
        const QList<StatusSample> minute = track.samples(1, 60000, 61000, 0);
        QVERIFY(!minute.isEmpty());
        QVERIFY(minute.first().elapsedMs >= 60000);
        QVERIFY(minute.last().elapsedMs <= 61000);
        QCOMPARE(track.sampleAt(1, 60005, 0)->elapsedMs, 60000 - 70); // the last answer before
        QVERIFY(!track.sampleAt(1, 5, 0));
        QVERIFY(!track.sampleAt(2, 60000, 0)); // no such device
    }

    // The XY path from the start: a point each time the tool moved; thinned to a bound with
    // its first point and its newest half whole.
    void thePathGoesBackToTheStart()
    {
        ReplayLog log;
        QVERIFY2(log.open(movingLog(120)), qPrintable(log.errorString()));
        const double scale1 = param("motor1.position")->scale;
        const QList<QPointF> path = log.track().path(1, 90000, 100000);
        QVERIFY(path.size() > 1700);
        QCOMPARE(path.first(), QPointF(0, 0));
        QVERIFY(path.last().x() > 890 / scale1);
        for (qsizetype i = 1; i < path.size(); ++i)
            QVERIFY(path.at(i) != path.at(i - 1));
        const QList<QPointF> thin = log.track().path(1, 90000, 400);
        QCOMPARE(thin.size(), 400);
        QCOMPARE(thin.first(), path.first());
        QCOMPARE(thin.last(), path.last());
        for (qsizetype i = 1, j = 1; i < thin.size(); ++i) { // in the path's order
            while (j < path.size() && path.at(j) != thin.at(i))
                ++j;
            QVERIFY2(j < path.size(), qPrintable(QString::number(i)));
        }
        // Back and forth at a step finer than a plot shows: the points closer than
        // 1/kPathResolution of the extent to the last one kept are left out, the turns stay.
        LogBuilder b;
        b.header();
        const Parameter *p1 = param("motor1.position");
        const Parameter *p2 = param("motor2.position");
        b.read(1, p2->address, positionWords(p2, 0));
        const int leg = 5000; // 50 mm in steps of 0.01 mm; a plot shows 0.025 mm at best
        for (int i = 0; i < 3 * leg; ++i) {
            const bool back = (i / leg) % 2 != 0;
            b.read(1, p1->address, positionWords(p1, back ? leg - i % leg : i % leg));
        }
        ReplayLog zigzag;
        QVERIFY2(zigzag.open(b.save(dir, QStringLiteral("zigzag.log"))),
                 qPrintable(zigzag.errorString()));
        const QList<QPointF> fine = zigzag.track().path(1, zigzag.durationMs(), 100000);
        QCOMPARE(fine.size(), 3 * leg);
        const QList<QPointF> coarse = zigzag.track().path(1, zigzag.durationMs(), 8000);
        QVERIFY2(coarse.size() > 4000 && coarse.size() <= 8000,
                 qPrintable(QString::number(coarse.size())));
        QCOMPARE(coarse.first(), fine.first());
        QCOMPARE(coarse.last(), fine.last());
        const double near = 50.0 / ReplayTrack::kPathResolution;
        double furthest = 0;
        for (qsizetype i = 0; i < coarse.size(); ++i) {
            furthest = std::max(furthest, coarse.at(i).x());
            if (i > 0 && i + 1 < coarse.size())
                QVERIFY2(std::abs(coarse.at(i).x() - coarse.at(i - 1).x()) >= near - 1e-9,
                         qPrintable(QStringLiteral("%1: %2 %3 %4")
                                        .arg(i)
                                        .arg(coarse.at(i - 1).x())
                                        .arg(coarse.at(i).x())
                                        .arg(coarse.size())));
        }
        QVERIFY2(furthest >= 50.0 - near, qPrintable(QString::number(furthest))); // the turn
        // Still too many: evenly thinned, the ends kept.
        const QList<QPointF> few = zigzag.track().path(1, zigzag.durationMs(), 1000);
        QCOMPARE(few.size(), 1000);
        QCOMPARE(few.first(), fine.first());
        QCOMPARE(few.last(), fine.last());
        QCOMPARE(log.track().path(1, 5, 400), QList<QPointF>{});
    }

    // A motor at rest adds nothing but the end of its run: what the live plot draws, in fewer
    // samples.
    void aRunAtRestKeepsItsEnds()
    {
        LogBuilder b;
        b.header();
        const Parameter *p1 = param("motor1.position");
        for (int i = 0; i < 100; ++i) { // 10 s of the same position, then one move
            b.read(1, p1->address, positionWords(p1, i < 99 ? 5 : 6));
            b.time = b.time.addMSecs(80);
        }
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir, QStringLiteral("rest.log"))), qPrintable(log.errorString()));
        const QList<StatusSample> s = log.track().samples(1, 0, log.durationMs(), 0);
        QCOMPARE(s.size(), 3);
        QCOMPARE(s.at(0).elapsedMs, 10);
        QCOMPARE(s.at(1).elapsedMs, 10 + 98 * 100); // the run's last answer
        QCOMPARE(s.at(1).positions.value(0), s.at(0).positions.value(0));
        QCOMPARE(s.at(2).elapsedMs, 10 + 99 * 100);
    }

    // Beyond its bound every other sample goes (the first and the last stay), and new ones come
    // no closer than the spacing left.
    void aLongTrackIsThinnedInBoundedMemory()
    {
        ReplayTrack track(trackMap());
        track.setMaxSamples(1000);
        ReplayDevice d;
        const Parameter *p1 = param("motor1.position");
        for (int i = 0; i < 5000; ++i) {
            const QVector<quint16> w = p1->encode(i);
            d.words.insert(p1->address, w.at(0));
            d.words.insert(quint16(p1->address + 1), w.at(1));
            track.add(1, i * 100, d);
        }
        track.finish();
        QVERIFY2(track.totalSize() <= 1000, qPrintable(QString::number(track.totalSize())));
        QVERIFY(track.totalSize() >= 250);
        QVERIFY(track.thinnedToMs() >= 100);
        const QList<StatusSample> s = track.samples(1, 0, 1000000, 0);
        QCOMPARE(s.first().elapsedMs, 0);
        QCOMPARE(s.last().elapsedMs, 499900);
        QCOMPARE(s.last().positions.value(0), 4999 / double(p1->scale));
        for (qsizetype i = 1; i < s.size(); ++i)
            QVERIFY(s.at(i).elapsedMs > s.at(i - 1).elapsedMs);
    }

    // The last lines through a moment, from a snapshot before them: at least as many as asked,
    // ending at the moment, from the start in a short log.
    void theLastLinesBeforeAMoment()
    {
        ReplayLog log;
        QVERIFY2(log.open(movingLog(600)), qPrintable(log.errorString()));
        QVERIFY(log.snapshotCount() > 3);
        QList<qint64> times;
        log.walkTail(400000, 3000, [&](QByteArrayView, const LogLine &line, qint64 ms, qint64) {
            if (line.type == LogLine::Type::Frame)
                times << ms;
            return true;
        });
        QVERIFY2(times.size() >= 3000, qPrintable(QString::number(times.size())));
        QVERIFY(times.size() < 24000);  // not the whole log before the moment
        QCOMPARE(times.last(), 400000); // the read sent at the moment
        QVERIFY(std::is_sorted(times.cbegin(), times.cend()));
        qsizetype fromStart = 0;
        log.walkTail(300, 3000, [&](QByteArrayView, const LogLine &, qint64, qint64) {
            ++fromStart;
            return true;
        });
        QCOMPARE(fromStart, 5 + 13); // the header, then the frames through 300 ms
    }

    // The lines before a line number, exactly, from a snapshot: the traffic view scrolled back.
    void theLinesBeforeALine()
    {
        ReplayLog log;
        QVERIFY2(log.open(movingLog(600)), qPrintable(log.errorString()));
        QList<qint64> numbers;
        log.walkTail(400000, 3000, [&](QByteArrayView, const LogLine &, qint64, qint64 lineNo) {
            numbers << lineNo;
            return true;
        });
        for (qsizetype i = 1; i < numbers.size(); ++i)
            QCOMPARE(numbers.at(i), numbers.at(i - 1) + 1);
        QCOMPARE(numbers.last(), 5 + 4 * 4000 + 1); // the header, 4000 cycles, the request
        QList<qint64> before;
        QList<qint64> times;
        log.walkBefore(numbers.first(), 5000,
                       [&](QByteArrayView, const LogLine &, qint64 ms, qint64 lineNo) {
                           before << lineNo;
                           times << ms;
                           return true;
                       });
        QCOMPARE(before.size(), 5000);
        QCOMPARE(before.first(), numbers.first() - 5000);
        QCOMPARE(before.last(), numbers.first() - 1);
        QVERIFY(times.last() <= 400000);
        // At the start of the log: what there is.
        QList<qint64> first;
        log.walkBefore(9, 100, [&](QByteArrayView, const LogLine &, qint64, qint64 lineNo) {
            first << lineNo;
            return true;
        });
        QCOMPARE(first, (QList<qint64>{1, 2, 3, 4, 5, 6, 7, 8}));
        bool any = false;
        log.walkBefore(1, 100,
                       [&](QByteArrayView, const LogLine &, qint64, qint64) { return any = true; });
        QVERIFY(!any);
    }

    // Each device's requests, errors, last restart; an answer means the line is up.
    void eachDeviceCountsItsRequestsAndErrors()
    {
        LogBuilder b;
        b.header();
        const quint16 speed = param("motor1.speed")->address;
        b.read(1, speed, {300});
        b.read(2, speed, {450});
        b.frame(true, LogBuilder::readRequest(2, speed, 1)); // no answer
        b.frame(true, LogBuilder::readRequest(2, speed, 1));
        b.frame(false, LogBuilder::withCrc(QByteArray::fromHex("028302"))); // refused
        b.mark(SessionLog::kRestart, QStringLiteral("id 2: motor1.speed 450 → 120 rpm"));
        b.read(1, speed, {310});
        ReplayLog log;
        QVERIFY2(log.open(b.save(dir, QStringLiteral("two.log"))), qPrintable(log.errorString()));
        const ReplayState at = log.stateAt(log.durationMs());
        QVERIFY(at.linkUp); // no linkup line in this log: the answers say it
        QCOMPARE(at.devices.value(1).requests, 2);
        QCOMPARE(at.devices.value(1).errors, 0);
        QCOMPARE(at.devices.value(2).requests, 3);
        QCOMPARE(at.devices.value(2).errors, 2);
        QVERIFY2(at.devices.value(2).lastError.startsWith(QLatin1String("refused")),
                 qPrintable(at.devices.value(2).lastError));
        QCOMPARE(at.devices.value(2).restartText,
                 QStringLiteral("id 2: motor1.speed 450 → 120 rpm"));
        QCOMPARE(at.devices.value(2).restartMs, 70);
        QCOMPARE(at.devices.value(1).restartMs, -1);
        QCOMPARE(log.stateAt(5).devices.value(2).requests, 0);
        QVERIFY(!log.stateAt(5).linkUp);
        // `stepcomctl replay --at --json` says the same.
        const QJsonObject two = at.toJson(trackMap())
                                    .value(QStringLiteral("devices"))
                                    .toObject()
                                    .value(QStringLiteral("2"))
                                    .toObject();
        QCOMPARE(two.value(QStringLiteral("requests")).toInt(), 3);
        QCOMPARE(two.value(QStringLiteral("errors")).toInt(), 2);
        QCOMPARE(two.value(QStringLiteral("restart_s")).toDouble(), 0.07);
        QCOMPARE(two.value(QStringLiteral("restart")).toString(),
                 QStringLiteral("id 2: motor1.speed 450 → 120 rpm"));
    }

    // The names the user gave the devices go into the header and come back from it.
    void theDevicesNamesAreInTheHeader()
    {
        DeviceSession session;
        test::useBuiltinSimulator(session);
        SessionLog sessionLog(&session);
        const QString path = dir.filePath(QStringLiteral("named.log"));
        sessionLog.setFile(path);
        sessionLog.setDeviceNames({{1, QStringLiteral("X gantry, left")},
                                   {2, QStringLiteral("Z: \"lift\"")},
                                   {3, QStringLiteral("  ")}});
        test::connectToSimulator(session);
        session.connection()->disconnectFrom();
        ReplayLog log;
        QVERIFY2(log.open(path), qPrintable(log.errorString()));
        QVERIFY2(log.header().value(QStringLiteral("names")).startsWith(u'{'),
                 qPrintable(log.header().value(QStringLiteral("names"))));
        const QHash<int, QString> names = log.deviceNames();
        QCOMPARE(names.value(1), QStringLiteral("X gantry, left"));
        QCOMPARE(names.value(2), QStringLiteral("Z: \"lift\""));
        QCOMPARE(names.size(), 2); // a blank name is no name
        // Without names the header says none.
        QVERIFY(!SessionLog::header(&session, 1, QStringLiteral("x"))
                     .contains(QLatin1String("# names:")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReplayTrack, Guiless)
#include "tst_replaytrack.moc"
