#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "map/registermap.h"
#include "modbuslinkfixture.h"

#include <QSet>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

using namespace stepcom;
using namespace stepcom::test;

class TestModbusLink : public LinkFixture
{
    Q_OBJECT

private Q_SLOTS:
    void init() { initLink(); }
    void cleanup() { cleanupLink(); }

    // The manual's worked frames, byte for byte, both ways.
    void manualFrames_data()
    {
        QTest::addColumn<int>("kind"); // 0 read, 1 write, 2 coil
        QTest::addColumn<int>("address");
        QTest::addColumn<QVector<quint16>>("values");
        QTest::addColumn<QByteArray>("request");
        QTest::addColumn<QByteArray>("response");
        QTest::newRow("read 40001-40002")
            << 0 << 0 << QVector<quint16>{2} << fromHex("01 03 00 00 00 02 C4 0B")
            << fromHex("01 03 04 00 B4 00 08 BB D3");
        QTest::newRow("write 40002 = 4")
            << 1 << 1 << QVector<quint16>{4} << fromHex("01 06 00 01 00 04 D9 C9")
            << fromHex("01 06 00 01 00 04 D9 C9");
        QTest::newRow("FC10 at 0x0009") << 1 << 9 << QVector<quint16>{0x00C8, 0x0000}
                                        << fromHex("01 10 00 09 00 02 04 00 C8 00 00 B2 3B")
                                        << fromHex("01 10 00 09 00 02 91 CA");
        QTest::newRow("coil 0x0007 ON")
            << 2 << 7 << QVector<quint16>{} << fromHex("01 05 00 07 FF 00 3D FB")
            << fromHex("01 05 00 07 FF 00 3D FB");
    }
    void manualFrames()
    {
        QFETCH(int, kind);
        QFETCH(int, address);
        QFETCH(QVector<quint16>, values);
        QFETCH(QByteArray, request);
        QFETCH(QByteArray, response);
        device->setResponder([response](const QByteArray &, int) { return response; });
        openLink();
        Request req = kind == 0   ? Request::read(quint16(address), values.first())
                      : kind == 1 ? Request::write(quint16(address), values)
                                  : Request::coil(quint16(address), true);
        LinkOutcome o;
        link->submit(req, into(&o));
        QTRY_VERIFY(o.done);
        QCOMPARE(device->requests().size(), 1);
        QCOMPARE(device->requests().first().toHex(' '), request.toHex(' '));
        QVERIFY2(o.result.ok, qPrintable(o.result.errorText));
        if (kind == 0) {
            QCOMPARE(o.result.values, (QVector<quint16>{180, 8}));
            const RegisterMap &map = RegisterMap::builtin();
            QCOMPARE(map.find(QStringLiteral("motor1.step_angle"))->formatRaw(o.result.values[0]),
                     QStringLiteral("1.80"));
            QCOMPARE(map.find(QStringLiteral("motor1.microsteps"))->decode(&o.result.values[1]), 8);
        }
        // The traffic log shows the real frames, CRC included.
        QTRY_VERIFY(link->traffic()->entries().size() >= 2);
        bool sawRequest = false;
        for (const TrafficEntry &e : link->traffic()->entries())
            sawRequest |= e.direction == TrafficEntry::Direction::Sent && e.bytes == request;
        QVERIFY(sawRequest);
    }

    void noAnswerTimesOutRetriesAndKeepsWorking()
    {
        device->setResponder([](const QByteArray &r, int index) -> std::optional<QByteArray> {
            if (index < 2)
                return std::nullopt; // silent twice
            return withCrc(r.left(2) + fromHex("02 00 07"));
        });
        openLink(100, 1);
        LinkOutcome first;
        link->submit(Request::read(0, 1), into(&first));
        QTRY_VERIFY(first.done);
        QVERIFY(!first.result.ok);
        QCOMPARE(first.result.error, QModbusDevice::TimeoutError);
        QCOMPARE(first.result.attempts, 2);
        QVERIFY(first.result.errorText.contains(QStringLiteral("no answer")));
        QCOMPARE(link->stats().timeouts, quint64(2));
        QVERIFY(link->isConnected());
        LinkOutcome second;
        link->submit(Request::read(0, 1), into(&second));
        QTRY_VERIFY(second.done);
        QVERIFY2(second.result.ok, qPrintable(second.result.errorText));
        QCOMPARE(second.result.values, QVector<quint16>{7});
    }

    // A timeout fitted to quick answers doubles with each timeout of that device (up to the set
    // one) and is fitted again once it answers: a moment of a busy computer or controller costs
    // one more try, not a string of them.
    void fittedTimeoutBacksOffAfterATimeout()
    {
        QSet<int> silent{6, 7};
        device->setResponder(
            [&silent](const QByteArray &r, int index) -> std::optional<QByteArray> {
                if (silent.contains(index))
                    return std::nullopt;
                return withCrc(r.left(2) + fromHex("02 00 07"));
            });
        openLink(2000, 0);
        const Request read = Request::read(0, 1);
        for (int i = 0; i < ModbusLink::kAdaptAfter + 1; ++i) {
            LinkOutcome o;
            link->submit(read, into(&o));
            QTRY_VERIFY(o.done);
            QVERIFY2(o.result.ok, qPrintable(o.result.errorText));
        }
        const int fitted = link->timeoutFor(read);
        QVERIFY2(fitted < 2000 / 4, qPrintable(QString::number(fitted)));
        int previous = fitted;
        for (int timeouts = 1; timeouts <= 2; ++timeouts) {
            LinkOutcome o;
            link->submit(read, into(&o));
            QTRY_VERIFY_WITH_TIMEOUT(o.done, 10000);
            QCOMPARE(o.result.error, QModbusDevice::TimeoutError);
            const int now = link->timeoutFor(read);
            QVERIFY2(now >= 2 * previous - 1 && now <= 2 * previous,
                     qPrintable(QStringLiteral("%1 after %2").arg(now).arg(previous)));
            previous = now;
        }
        LinkOutcome answered;
        link->submit(read, into(&answered));
        QTRY_VERIFY(answered.done);
        QVERIFY2(answered.result.ok, qPrintable(answered.result.errorText));
        QVERIFY2(
            link->timeoutFor(read) < previous / 2,
            qPrintable(
                QStringLiteral("%1, backed off %2").arg(link->timeoutFor(read)).arg(previous)));
        // It stops doubling at eight times the fitted timeout, and never passes the set one.
        for (int i = 9; i < 13; ++i)
            silent.insert(i);
        QList<int> backedOff;
        for (int i = 0; i < 4; ++i) {
            LinkOutcome o;
            link->submit(read, into(&o));
            QTRY_VERIFY_WITH_TIMEOUT(o.done, 15000);
            QCOMPARE(o.result.error, QModbusDevice::TimeoutError);
            backedOff << link->timeoutFor(read);
        }
        QCOMPARE(backedOff.at(3), backedOff.at(2));
        QVERIFY2(backedOff.at(2) > backedOff.at(1) || backedOff.at(2) == 2000,
                 qPrintable(QString::number(backedOff.at(2))));
        QVERIFY(backedOff.at(3) <= 2000);
    }

    // A controller that showed it answers later than the timeout is given that long: the next
    // request of another shape waits for an answer still owed for as long as the controller
    // showed an answer may take, so that answer is not taken for the next one's.
    void anAnswerOwedIsAwaitedAsLongAsTheControllerShowedItTakes()
    {
        const auto answer = [](const QByteArray &r, quint16 value) {
            return withCrc(r.left(2) + QByteArray(1, char(2)) + char(value >> 8) + char(value));
        };
        device->setAnswerDelayMs(0);
        device->setResponder(
            [this, answer](const QByteArray &r, int index) -> std::optional<QByteArray> {
                // 170 ms late, then 220 ms late: past the timeout, the second past twice it; then
                // in 150 ms, within the third request's own timeout.
                const int delayMs = index == 0 ? 170 : index == 1 ? 220 : 150;
                QTimer::singleShot(delayMs, device.get(), [this, r, answer, index] {
                    device->bridge().inject(PtyBridge::Side::A,
                                            answer(r, quint16(std::min(index + 1, 3))));
                });
                return std::nullopt;
            });
        openLink(100, 0);
        LinkOutcome first;
        link->submit(Request::read(0, 1), into(&first));
        QTRY_VERIFY(first.done);
        QCOMPARE(first.result.error, QModbusDevice::TimeoutError);
        LinkOutcome second;
        link->submit(Request::read(1, 1), into(&second));
        QTRY_VERIFY_WITH_TIMEOUT(second.done, 5000);
        QCOMPARE(second.result.error, QModbusDevice::TimeoutError);
        LinkOutcome third;
        Request read = Request::read(2, 1);
        read.timeoutMs = 1000;
        link->submit(read, into(&third));
        QTRY_VERIFY_WITH_TIMEOUT(third.done, 5000);
        QVERIFY2(third.result.ok, qPrintable(third.result.errorText));
        QCOMPARE(third.result.values, QVector<quint16>{3}); // never the second's late 2
        QCOMPARE(device->requests().size(), 3);
    }

    // An E-STOP after a read that timed out goes at once: the read's answer, still owed, has
    // another shape (told apart by what it says), so the E-STOP does not wait for it, and its
    // own answer is taken.
    void emergencyStopDoesNotWaitForAnAnswerOfAnotherShape()
    {
        bool lateAnswerSent = false;
        bool estopBeforeIt = false;
        device->setAnswerDelayMs(0);
        device->setResponder([&](const QByteArray &r, int index) -> std::optional<QByteArray> {
            if (index == 0) {
                QTimer::singleShot(550, device.get(), [this, r, &lateAnswerSent] {
                    lateAnswerSent = true;
                    device->bridge().inject(PtyBridge::Side::A,
                                            withCrc(r.left(2) + fromHex("02 00 07")));
                });
                return std::nullopt;
            }
            estopBeforeIt = !lateAnswerSent;
            return r; // a coil write is answered with its own copy
        });
        openLink(300, 0);
        LinkOutcome read;
        link->submit(Request::read(0, 1), into(&read));
        QTRY_VERIFY(read.done);
        QCOMPARE(read.result.error, QModbusDevice::TimeoutError);
        Request estop = Request::coil(41, true, Priority::Emergency);
        estop.retryable = false;
        LinkOutcome stopped;
        link->submit(estop, into(&stopped));
        QTRY_VERIFY_WITH_TIMEOUT(stopped.done, 5000);
        QVERIFY2(stopped.result.ok, qPrintable(stopped.result.errorText));
        QVERIFY(estopBeforeIt); // it left before the read's late answer
        QTRY_VERIFY(lateAnswerSent);
        QVERIFY(link->isConnected());
    }

    // Destroying the link with a request in flight tells no one: the objects behind the
    // callbacks are going away too (stepcomctl crashed here when its runner was destroyed).
    void destroyedWithARequestInFlightCallsNoOne()
    {
        device->setResponder(
            [](const QByteArray &, int) -> std::optional<QByteArray> { return std::nullopt; });
        openLink(5000, 0);
        QSignalSpy received(device.get(), &ScriptedDevice::requestReceived);
        bool called = false;
        link->submit(Request::read(0, 1), [&called](const Result &) { called = true; });
        QTRY_COMPARE(received.size(), 1); // on the wire, waiting for its answer
        link.reset();
        QVERIFY(!called);
    }

    void badCrcIsCountedAndRetried()
    {
        device->setResponder([](const QByteArray &r, int index) {
            QByteArray answer = withCrc(r.left(2) + fromHex("02 01 2C"));
            if (index == 0)
                answer[answer.size() - 1] = char(answer.at(answer.size() - 1) ^ 0x55);
            return answer;
        });
        openLink(150, 2);
        LinkOutcome o;
        link->submit(Request::read(5, 1), into(&o));
        QTRY_VERIFY(o.done);
        QVERIFY2(o.result.ok, qPrintable(o.result.errorText));
        QCOMPARE(o.result.values, QVector<quint16>{300});
        QCOMPARE(o.result.attempts, 2);
        QCOMPARE(link->stats().crcErrors, quint64(1));
    }

    void exceptionIsReportedInWords()
    {
        device->setResponder([](const QByteArray &r, int) {
            return withCrc(r.left(1) + QByteArray(1, char(0x86)) + QByteArray(1, char(0x02)));
        });
        openLink();
        Request req = Request::write(0x0014, {1});
        req.what = QStringLiteral("motor1.speed");
        LinkOutcome o;
        link->submit(req, into(&o));
        QTRY_VERIFY(o.done);
        QVERIFY(!o.result.ok);
        QCOMPARE(o.result.exceptionCode, 2);
        QVERIFY2(o.result.errorText.contains(QStringLiteral("illegal data address")),
                 qPrintable(o.result.errorText));
        QVERIFY(o.result.errorText.contains(QStringLiteral("motor1.speed")));
        QVERIFY(o.result.errorText.contains(QStringLiteral("40021")));
        QCOMPARE(device->requests().size(), 1); // a refusal is an answer: never retried
        QCOMPARE(link->stats().exceptionsByCode.value(2), quint64(1));
    }

    void lateAnswerIsNotTakenForTheNextOne()
    {
        // First answer arrives after the timeout; the second request must get its own values.
        device->setResponder([this](const QByteArray &r, int index) -> std::optional<QByteArray> {
            const QByteArray answer =
                withCrc(r.left(2) + fromHex("02 00") + QByteArray(1, char(index + 1)));
            if (index == 0) {
                QTimer::singleShot(160, this, [this, answer] {
                    device->bridge().inject(PtyBridge::Side::A, answer);
                });
                return std::nullopt;
            }
            return answer;
        });
        openLink(100, 0);
        link->setQuietTimeMs(120);
        LinkOutcome first;
        LinkOutcome second;
        link->submit(Request::read(0, 1), into(&first));
        link->submit(Request::read(1, 1), into(&second));
        QTRY_VERIFY(second.done);
        QVERIFY(first.done && !first.result.ok);
        QVERIFY2(second.result.ok, qPrintable(second.result.errorText));
        QCOMPARE(second.result.values, QVector<quint16>{2});
    }

    void wrongSizedAnswerIsRejected()
    {
        device->setResponder(
            [](const QByteArray &r, int) { return withCrc(r.left(2) + fromHex("02 00 01")); });
        openLink(100, 0);
        LinkOutcome o;
        link->submit(Request::read(0, 2), into(&o));
        QTRY_VERIFY(o.done);
        QVERIFY(!o.result.ok);
        QVERIFY2(
            o.result.errorText.contains(QStringLiteral("carried 1 registers, 2 were asked for")),
            qPrintable(o.result.errorText));
    }

    // Regression: an FC06 answer for another address (01 06 00 50 ...) to a write of 00 B0 was
    // taken; and an answer sooner than the controller can answer is a late one.
    void foreignAndEarlyAnswersAreDiscarded()
    {
        device->setResponder([this](const QByteArray &r, int index) -> std::optional<QByteArray> {
            if (index == 0) {
                // At once (too soon, another value), then one for 0x0050, then the real one.
                device->bridge().inject(PtyBridge::Side::A, withCrc(fromHex("01 06 00 B0 00 02")));
                QTimer::singleShot(40, this, [this] {
                    device->bridge().inject(PtyBridge::Side::A,
                                            withCrc(fromHex("01 06 00 50 00 01")));
                });
                QTimer::singleShot(80, this,
                                   [this, r] { device->bridge().inject(PtyBridge::Side::A, r); });
            }
            return std::nullopt;
        });
        openLink(300, 0);
        LinkOutcome o;
        link->submit(Request::write(0xB0, {1}), into(&o));
        QTRY_VERIFY(o.done);
        QVERIFY2(o.result.ok, qPrintable(o.result.errorText));
        QCOMPARE(link->stats().stale, quint64(2));
        bool logged = false;
        for (const TrafficEntry &e : link->traffic()->entries())
            logged |= e.summary.contains(QStringLiteral("stale/foreign answer"));
        QVERIFY(logged);
    }

    // The timeout suggested with the link statistics follows the measured round trips.
    void suggestedTimeoutFollowsTheRoundTrips()
    {
        LinkStats stats;
        for (const qint64 ms : {40, 45, 52, 61}) {
            ++stats.answers;
            stats.addRoundTrip(ms);
        }
        QCOMPARE(stats.suggestedTimeoutMs(), -1); // too few to say
        ++stats.answers;
        stats.addRoundTrip(230);
        QCOMPARE(stats.suggestedTimeoutMs(), 400); // 230 * 1.5 + 50 = 395, in 50 ms steps
    }

    void motionCommandIsNeverRetried()
    {
        openLink(80, 3); // silent device
        Request req = Request::coil(1, true);
        req.retryable = false;
        LinkOutcome o;
        link->submit(req, into(&o));
        QTRY_VERIFY(o.done);
        QCOMPARE(device->requests().size(), 1);
        QVERIFY(o.result.mayHaveActed);
        QVERIFY(o.result.errorText.contains(QStringLiteral("may have acted")));
    }

    void emergencyGoesOutNextAheadOfEverythingQueued()
    {
        device->useRegisterDevice();
        device->setAnswerDelayMs(40);
        openLink();
        QList<quint64> order;
        connect(link.get(), &ModbusLink::dispatched, this,
                [&order](quint64 id, const Request &) { order << id; });
        QList<quint64> polls;
        for (int i = 0; i < 5; ++i)
            polls << link->submit(Request::read(quint16(i), 1, Priority::Poll), {});
        QTRY_COMPARE(order.size(), 1); // the first poll is on the wire
        const quint64 write = link->submit(Request::write(10, {1}), {});
        Request stop = Request::coil(41, true, Priority::Emergency);
        const quint64 estop = link->submit(stop, {});
        QTRY_COMPARE(order.size(), 7);
        QCOMPARE(order.at(0), polls.at(0));
        QCOMPARE(order.at(1), estop); // within one in-flight transaction
        QCOMPARE(order.at(2), write);
        QCOMPARE(order.mid(3), polls.mid(1));
        QCOMPARE(device->requests().at(1), fromHex("01 05 00 29 FF 00 5D F2"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestModbusLink, Guiless)
#include "tst_modbuslink.moc"
