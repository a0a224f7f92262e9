// The link on a bad line against the simulator: late answers, an echoing adapter, RTU over
// TCP. Whatever the line does, nothing is reported done that the controller does not hold.
#include "bus/modbuslink.h"
#include "bus/trafficlog.h"
#include "line/busscanner.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QSignalSpy>
#include <QTest>

using namespace stepcom;

namespace {

struct AnswerOutcome
{
    bool done = false;
    Result result;
};

// Single-register parameters with their protocol addresses.
const QList<std::pair<QString, quint16>> &keys()
{
    static const QList<std::pair<QString, quint16>> k{
        {QStringLiteral("motor1.speed"), 5},
        {QStringLiteral("motor2.speed"), 15},
        {QStringLiteral("motor1.start_frequency"), 2},
        {QStringLiteral("motor2.start_frequency"), 12},
        {QStringLiteral("motor1.accel_frequency"), 3},
        {QStringLiteral("motor2.accel_frequency"), 13},
    };
    return k;
}

} // namespace

class TestLineAnswers : public QObject
{
    Q_OBJECT

    std::unique_ptr<SimHost> host;
    std::unique_ptr<ModbusLink> link;

    bool startSim(const SimOptions &options)
    {
        host = std::make_unique<SimHost>();
        QString error;
        if (!host->start(options, &error)) {
            qWarning() << error;
            return false;
        }
        return true;
    }
    bool openLink(LinkSettings s)
    {
        link = std::make_unique<ModbusLink>();
        QSignalSpy opened(link.get(), &ModbusLink::opened);
        link->open(s);
        if (!opened.wait(5000) && opened.isEmpty())
            return false;
        return opened.at(0).at(0).toBool();
    }
    Result run(const Request &request)
    {
        AnswerOutcome o;
        link->submit(request, [&o](const Result &r) {
            o.done = true;
            o.result = r;
        });
        // Every request ends (timeouts and retries included) well within this.
        if (!QTest::qWaitFor([&o] { return o.done; }, 30000))
            o.result.errorText = QStringLiteral("the request never ended");
        return o.result;
    }

private Q_SLOTS:
    void cleanup()
    {
        link.reset();
        host.reset();
    }

    // Late answers at several rates and delays while reading, writing and commanding: every
    // value reported read is the controller's, every write reported done is held by it, every
    // command reported done happened.
    void lateAnswersNeverPassForAnother_data()
    {
        QTest::addColumn<double>("share");
        QTest::addColumn<int>("lateMs");
        QTest::addColumn<int>("timeoutMs");
        QTest::addColumn<bool>("overTcp");
        QTest::newRow("half 700 ms late, timeout 500") << 0.5 << 700 << 500 << false;
        QTest::newRow("a third 300 ms late, timeout 250") << 0.33 << 300 << 250 << false;
        QTest::newRow("half 120 ms late, timeout 100") << 0.5 << 120 << 100 << false;
        QTest::newRow("RTU over TCP, half 400 ms late") << 0.5 << 400 << 300 << true;
    }
    void lateAnswersNeverPassForAnother()
    {
        QFETCH(double, share);
        QFETCH(int, lateMs);
        QFETCH(int, timeoutMs);
        QFETCH(bool, overTcp);
        SimOptions options;
        options.rtu = !overTcp;
        options.rtuTcp = overTcp;
        options.faults.late = share;
        options.faults.lateMs = lateMs;
        options.faults.seed = 11;
        QVERIFY(startSim(options));
        for (int i = 0; i < keys().size(); ++i)
            QVERIFY(host->device()->setValue(keys().at(i).first, 101 + i));
        LinkSettings s;
        if (overTcp) {
            s.transport = LinkSettings::Transport::RtuTcp;
            s.tcpPort = host->rtuTcpPort();
        } else {
            s.portName = host->rtuPath();
        }
        s.timeoutMs = timeoutMs;
        s.retries = 2;
        QVERIFY(openLink(s));
        int ok = 0;
        for (int round = 0; round < 1; ++round) {
            for (int i = 0; i < keys().size(); ++i) {
                const auto &[key, address] = keys().at(i);
                const Result read = run(Request::read(address, 1));
                if (read.ok) {
                    ++ok;
                    QCOMPARE(qint64(read.values.value(0)), *host->device()->value(key));
                }
                const quint16 value = quint16(200 + 10 * round + i);
                const Result write = run(Request::write(address, {value}));
                if (write.ok) {
                    ++ok;
                    QCOMPARE(*host->device()->value(key), qint64(value));
                }
            }
            // Output 1 on (00049) and off (00050): done only when the controller did it.
            for (const bool on : {true, false}) {
                Request coil = Request::coil(on ? 48 : 49, true);
                coil.retryable = false;
                const Result r = run(coil);
                if (r.ok) {
                    ++ok;
                    QCOMPARE(*host->device()->value(QStringLiteral("io.out1")), qint64(on));
                }
            }
        }
        QVERIFY2(ok > 0, "nothing at all succeeded");
        QVERIFY(host->stats().late > 0);
        qInfo("%d of %d succeeded; %llu stale answers discarded", ok, 2 * int(keys().size()) + 2,
              link->stats().stale);
    }

    // The owed answer: a read times out without retries, the next read (another address, the
    // same count, so content cannot tell the answers apart) would go out after the quiet time
    // and meet the late answer past its earliest time. The answer the timed-out read still
    // owes keeps the next request back until it came (or two timeouts passed), so every value
    // reported read is the one at the address asked for.
    void lateAnswerOwedToATimedOutReadIsNotTakenByTheNextRead_data()
    {
        QTest::addColumn<bool>("overTcp");
        QTest::newRow("pty") << false;
        QTest::newRow("RTU over TCP") << true;
    }
    void lateAnswerOwedToATimedOutReadIsNotTakenByTheNextRead()
    {
        QFETCH(bool, overTcp);
        SimOptions options;
        options.rtu = !overTcp;
        options.rtuTcp = overTcp;
        options.faults.late = 0.5;
        // After the timeout (300) plus the quiet time (100), before two timeouts: the answer
        // lands while the next read would be on the wire.
        options.faults.lateMs = 450;
        options.faults.seed = 3;
        QVERIFY(startSim(options));
        for (int i = 0; i < keys().size(); ++i)
            QVERIFY(host->device()->setValue(keys().at(i).first, 101 + i));
        LinkSettings s;
        if (overTcp) {
            s.transport = LinkSettings::Transport::RtuTcp;
            s.tcpPort = host->rtuTcpPort();
        } else {
            s.portName = host->rtuPath();
        }
        s.timeoutMs = 300;
        s.retries = 0;
        QVERIFY(openLink(s));
        QCOMPARE(link->quietTimeMs(), 100);
        int ok = 0;
        int timedOut = 0;
        for (int round = 0; round < 3; ++round) {
            for (int i = 0; i < keys().size(); ++i) {
                const auto &[key, address] = keys().at(i);
                const Result read = run(Request::read(address, 1));
                if (read.ok) {
                    ++ok;
                    if (qint64(read.values.value(0)) != *host->device()->value(key))
                        QFAIL(qPrintable(QStringLiteral("%1 read as %2, the controller holds %3: "
                                                        "a late answer to another read")
                                             .arg(key)
                                             .arg(read.values.value(0))
                                             .arg(*host->device()->value(key))));
                } else {
                    QVERIFY2(read.error == QModbusDevice::TimeoutError, qPrintable(read.errorText));
                    ++timedOut;
                }
            }
        }
        // Both happened: the case was really exercised.
        QVERIFY(ok > 0);
        QVERIFY(timedOut > 0);
        QVERIFY(host->stats().late > 0);
    }

    // An echo nobody set up is found on the first read (an FC03 request is never its own
    // answer), said once, and skipped from then on: the read and a command after it succeed.
    void echoOffIsDetectedAndLearnt()
    {
        SimOptions options;
        options.rtu = true;
        options.echo = true;
        QVERIFY(startSim(options));
        LinkSettings s;
        s.portName = host->rtuPath();
        s.timeoutMs = 300;
        QVERIFY(openLink(s));
        QSignalSpy echo(link.get(), &ModbusLink::echoDetected);
        QVERIFY(host->device()->setValue(QStringLiteral("motor1.speed"), 321));
        const Result read = run(Request::read(5, 1));
        QVERIFY2(read.ok, qPrintable(read.errorText));
        QCOMPARE(read.values, QVector<quint16>{321});
        QCOMPARE(echo.size(), 1);
        QCOMPARE(link->stats().echo, 1);
        QVERIFY(host->device()->command(QStringLiteral("motor1.forward")));
        QTRY_VERIFY(host->device()->running(1));
        Request estop = Request::coil(41, true, Priority::Emergency);
        estop.retryable = false;
        const Result command = run(estop);
        QVERIFY2(command.ok, qPrintable(command.errorText));
        QVERIFY(!host->device()->running(1));
        QCOMPARE(echo.size(), 1); // said once
        QCOMPARE(link->stats().timeouts, quint64(0));
        QCOMPARE(link->stats().stale, quint64(0));
    }

    void echoOnWorks_data()
    {
        QTest::addColumn<bool>("overTcp");
        QTest::newRow("pty") << false;
        QTest::newRow("RTU over TCP") << true;
    }
    void echoOnWorks()
    {
        QFETCH(bool, overTcp);
        SimOptions options;
        options.rtu = !overTcp;
        options.rtuTcp = overTcp;
        options.echo = true;
        QVERIFY(startSim(options));
        LinkSettings s;
        if (overTcp) {
            s.transport = LinkSettings::Transport::RtuTcp;
            s.tcpPort = host->rtuTcpPort();
        } else {
            s.portName = host->rtuPath();
        }
        s.echo = true;
        QVERIFY(openLink(s));
        QVERIFY(host->device()->setValue(QStringLiteral("motor1.speed"), 321));
        const Result read = run(Request::read(5, 1));
        QVERIFY2(read.ok, qPrintable(read.errorText));
        QCOMPARE(read.values, QVector<quint16>{321});
        const Result write = run(Request::write(15, {222}));
        QVERIFY2(write.ok, qPrintable(write.errorText));
        QCOMPARE(*host->device()->value(QStringLiteral("motor2.speed")), 222);
        const Result block = run(Request::write(6, {0x1234, 0}));
        QVERIFY2(block.ok, qPrintable(block.errorText));
        const Result on = run(Request::coil(48, true));
        QVERIFY2(on.ok, qPrintable(on.errorText));
        QCOMPARE(*host->device()->value(QStringLiteral("io.out1")), 1);
        QCOMPARE(link->stats().echo, 1);
        QCOMPARE(link->stats().stale, quint64(0));
    }

    // RTU over TCP: the manual's frames reach the controller and its answers come back.
    void rtuOverTcpReadWriteCommand()
    {
        SimOptions options;
        options.rtuTcp = true;
        QVERIFY(startSim(options));
        LinkSettings s;
        s.transport = LinkSettings::Transport::RtuTcp;
        s.tcpPort = host->rtuTcpPort();
        QVERIFY(openLink(s));
        const Result read = run(Request::read(0, 2));
        QVERIFY2(read.ok, qPrintable(read.errorText));
        QCOMPARE(read.values, (QVector<quint16>{180, 8}));
        const Result write = run(Request::write(1, {4}));
        QVERIFY2(write.ok, qPrintable(write.errorText));
        QCOMPARE(*host->device()->value(QStringLiteral("motor1.microsteps")), 4);
        const Result coil = run(Request::coil(48, true));
        QVERIFY2(coil.ok, qPrintable(coil.errorText));
        QCOMPARE(*host->device()->value(QStringLiteral("io.out1")), 1);
        // Another id is silence, and says what to check.
        link->setDeviceId(7);
        const Result none = run(Request::read(0, 1));
        QVERIFY(!none.ok);
        QVERIFY2(none.errorText.contains(QStringLiteral("device id (7)")),
                 qPrintable(none.errorText));
        // The traffic log shows the RTU frames, CRC included.
        bool sawFrame = false;
        for (const TrafficEntry &e : link->traffic()->entries())
            sawFrame |= e.bytes == QByteArray::fromHex("010300000002C40B");
        QVERIFY(sawFrame);
    }

    // The bus scan over a transparent converter: ids only (the converter's baud is its own).
    void scanOverRtuTcpFindsTheController()
    {
        SimOptions options;
        options.rtuTcp = true;
        options.deviceId = 3;
        QVERIFY(startSim(options));
        LinkSettings base;
        base.transport = LinkSettings::Transport::RtuTcp;
        base.tcpPort = host->rtuTcpPort();
        BusScanner scanner;
        QSignalSpy finished(&scanner, &BusScanner::finished);
        scanner.start(base, {9600, 19200}, 1, 5, 150);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        QCOMPARE(scanner.total(), 5); // one baud: the converter's
        QCOMPARE(scanner.found().size(), 1);
        QCOMPARE(scanner.found().first().deviceId, 3);
    }

    // A busy controller (exception 06) did nothing: the request goes again after a pause.
    void busyIsRetriedAfterAPause()
    {
        SimOptions options;
        options.rtu = true;
        options.faults.exception = 0.5;
        options.faults.exceptionCode = 6;
        options.faults.seed = 5;
        QVERIFY(startSim(options));
        LinkSettings s;
        s.portName = host->rtuPath();
        s.retries = 6;
        QVERIFY(openLink(s));
        for (int i = 0; i < 6; ++i) {
            const Result write = run(Request::write(5, {quint16(400 + i)}));
            QVERIFY2(write.ok, qPrintable(write.errorText));
            QCOMPARE(*host->device()->value(QStringLiteral("motor1.speed")), 400 + i);
        }
        QVERIFY(link->stats().exceptionsByCode.value(6) > 0);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestLineAnswers, Guiless)
#include "tst_lineanswers.moc"
