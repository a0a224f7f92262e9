#include "bus/rtuframe.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QDataStream>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QModbusTcpClient>
#include <QRegularExpression>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;

// The simulator over real Modbus: RTU through the pty bridge and TCP on loopback, with a Qt
// client as the independent peer.
class TstSimServers : public QObject
{
    Q_OBJECT

private:
    struct Result
    {
        QModbusDevice::Error error = QModbusDevice::NoError;
        int exception = 0;
        QList<quint16> values;
        qint64 ms = 0;
    };

    static std::unique_ptr<QModbusClient> rtuClient(const QString &path, int baud = 9600)
    {
        auto c = std::make_unique<QModbusRtuSerialClient>();
        // Qt's defaults are 19200 baud, even parity: set everything.
        c->setConnectionParameter(QModbusDevice::SerialPortNameParameter, path);
        c->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, baud);
        c->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
        c->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
        c->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
        c->setTimeout(400);
        c->setNumberOfRetries(0);
        if (!c->connectDevice())
            return nullptr;
        return c;
    }
    static std::unique_ptr<QModbusClient> tcpClient(quint16 port)
    {
        auto c = std::make_unique<QModbusTcpClient>();
        c->setConnectionParameter(QModbusDevice::NetworkAddressParameter,
                                  QStringLiteral("127.0.0.1"));
        c->setConnectionParameter(QModbusDevice::NetworkPortParameter, port);
        c->setTimeout(400);
        c->setNumberOfRetries(0);
        QSignalSpy spy(c.get(), &QModbusDevice::stateChanged);
        c->connectDevice();
        for (int i = 0; i < 20 && c->state() != QModbusDevice::ConnectedState; ++i)
            spy.wait(100);
        return c;
    }
    static Result finish(QModbusReply *reply, const QElapsedTimer &timer)
    {
        Result r;
        if (!reply)
            return {QModbusDevice::ConnectionError, 0, {}, 0};
        if (!reply->isFinished()) {
            QSignalSpy spy(reply, &QModbusReply::finished);
            spy.wait(3000);
        }
        r.ms = timer.elapsed();
        r.error = reply->error();
        // Not rawResult().isException(): Qt 6.4 stores a received exception's function code
        // sign-extended, which UBSan reports as an invalid enum value.
        if (r.error == QModbusDevice::ProtocolError && !reply->rawResult().data().isEmpty())
            r.exception = quint8(reply->rawResult().data().at(0));
        for (qsizetype i = 0; i < reply->result().valueCount(); ++i)
            r.values << reply->result().value(int(i));
        reply->deleteLater();
        return r;
    }
    static Result read(QModbusClient *c, int address, int count, int unit = 1)
    {
        QElapsedTimer t;
        t.start();
        return finish(
            c->sendReadRequest(
                QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, quint16(count)), unit),
            t);
    }
    static Result write(QModbusClient *c, int address, QList<quint16> values, int unit = 1)
    {
        QElapsedTimer t;
        t.start();
        return finish(
            c->sendWriteRequest(QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, values),
                                unit),
            t);
    }
    static Result raw(QModbusClient *c, const QModbusRequest &request, int unit = 1)
    {
        QElapsedTimer t;
        t.start();
        return finish(c->sendRawRequest(request, unit), t);
    }
    // A request as the Modbus TCP server (MBAP, unit 1) or the RTU-over-TCP one (RTU frame, id
    // 1) takes it.
    static QByteArray framed(bool rtuFraming, quint16 transaction, const QByteArray &pdu)
    {
        QByteArray f;
        if (!rtuFraming) {
            QDataStream s(&f, QIODevice::WriteOnly);
            s << transaction << quint16(0) << quint16(pdu.size() + 1) << quint8(1);
            f.append(pdu);
            return f;
        }
        f.append(char(1)).append(pdu);
        const quint16 sum = RtuFrame::crc(f);
        f.append(char(sum & 0xFF)).append(char(sum >> 8));
        return f;
    }
    // The host with one of its TCP servers, `socket` connected to it; its port (0: it failed).
    static quint16 serveOverTcp(SimHost &host, SimOptions o, bool rtuFraming, QTcpSocket *socket)
    {
        o.tcp = !rtuFraming;
        o.rtuTcp = rtuFraming;
        QString error;
        if (!host.start(o, &error)) {
            qWarning("%s", qPrintable(error));
            return 0;
        }
        const quint16 port = rtuFraming ? host.rtuTcpPort() : host.tcpPort();
        socket->connectToHost(QHostAddress::LocalHost, port);
        return socket->waitForConnected(5000) ? port : 0;
    }
    static SimOptions rtuOptions()
    {
        SimOptions o;
        o.rtu = true;
        return o;
    }

private Q_SLOTS:
    void rtuReadAnswersNoSoonerThan35ms()
    {
        SimHost host;
        QString error;
        QVERIFY2(host.start(rtuOptions(), &error), qPrintable(error));
        QVERIFY(QFileInfo::exists(host.rtuPath()));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(c);
        const Result r = read(c.get(), 0, 2);
        QCOMPARE(r.error, QModbusDevice::NoError);
        QCOMPARE(r.values, (QList<quint16>{180, 8}));
        QVERIFY2(r.ms >= 35, qPrintable(QString::number(r.ms)));
        QCOMPARE(host.stats().answers, 1);
    }

    void rtuExceptions()
    {
        SimHost host;
        QString error;
        QVERIFY2(host.start(rtuOptions(), &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(c);
        Result r =
            raw(c.get(), QModbusRequest(QModbusPdu::ReadInputRegisters, quint16(0), quint16(2)));
        QCOMPARE(r.error, QModbusDevice::ProtocolError);
        QCOMPARE(r.exception, 1);
        // A code Qt cannot size is still answered, not dropped.
        r = raw(c.get(),
                QModbusRequest(QModbusPdu::FunctionCode(0x41), QByteArray::fromHex("0102")));
        QCOMPARE(r.exception, 1);
        r = read(c.get(), 0, 50);
        QCOMPARE(r.exception, 3);
        r = raw(c.get(), QModbusRequest(QModbusPdu::WriteSingleCoil, quint16(0), quint16(0x1234)));
        QCOMPARE(r.exception, 3);
        r = write(c.get(), 107, {1}); // 40108: read-only position
        QCOMPARE(r.exception, 2);
        r = read(c.get(), 0, 2);
        QCOMPARE(r.error, QModbusDevice::NoError);
    }

    void otherIdGetsSilence()
    {
        SimHost host;
        QString error;
        QVERIFY2(host.start(rtuOptions(), &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        const Result r = read(c.get(), 0, 2, 2);
        QCOMPARE(r.error, QModbusDevice::TimeoutError);
        QCOMPARE(host.stats().requests, 0);
    }

    void idChangeTakesEffectAfterTheAnswer()
    {
        SimHost host;
        QString error;
        SimOptions o = rtuOptions();
        o.deviceId = 3; // --id
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QCOMPARE(read(c.get(), 211, 1, 3).values, QList<quint16>{3});
        Result r = write(c.get(), 211, {5}, 3); // answered under the old id
        QCOMPARE(r.error, QModbusDevice::NoError);
        QCOMPARE(read(c.get(), 0, 1, 3).error, QModbusDevice::TimeoutError);
        QCOMPARE(read(c.get(), 211, 1, 5).values, QList<quint16>{5});
    }

    void idChangedByHandIsFollowed()
    {
        SimHost host;
        QString error;
        QVERIFY2(host.start(rtuOptions(), &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(host.device()->setValue(QStringLiteral("device.id"), 7));
        QTRY_COMPARE_WITH_TIMEOUT(read(c.get(), 211, 1, 7).values, QList<quint16>{7}, 10000);
        QCOMPARE(read(c.get(), 211, 1, 1).error, QModbusDevice::TimeoutError);
    }

    void baudChangeTakesEffectAfterTheAnswer()
    {
        SimHost host;
        QString error;
        QVERIFY2(host.start(rtuOptions(), &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath(), 19200);
        QCOMPARE(read(c.get(), 0, 1).error, QModbusDevice::TimeoutError); // wrong baud
        QVERIFY(host.stats().wrongBaud >= 1);
        c.reset(); // the port is opened exclusively
        c = rtuClient(host.rtuPath(), 9600);
        QVERIFY(c);
        QCOMPARE(write(c.get(), 212, {19200}).error, QModbusDevice::NoError);
        QCOMPARE(read(c.get(), 0, 1).error, QModbusDevice::TimeoutError);
        c.reset();
        c = rtuClient(host.rtuPath(), 19200);
        QVERIFY(c);
        QCOMPARE(read(c.get(), 212, 1).values, QList<quint16>{19200});
    }

    void wireTimeAddsToTheDelay()
    {
        SimHost host;
        QString error;
        SimOptions o = rtuOptions();
        o.answerDelayMs = 10;
        o.wireBaud = 1200; // (8 + 9 + 7) bytes x 10 bits at 1200 baud = 200 ms
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        c->setTimeout(1000);
        const Result r = read(c.get(), 0, 2);
        QCOMPARE(r.error, QModbusDevice::NoError);
        QVERIFY2(r.ms >= 210 && r.ms < 600, qPrintable(QString::number(r.ms)));
    }

    void faults_data()
    {
        QTest::addColumn<QString>("fault");
        QTest::addColumn<int>("expectError");
        QTest::addColumn<int>("exception");
        QTest::addColumn<int>("minMs");
        QTest::newRow("drop") << "drop" << int(QModbusDevice::TimeoutError) << 0 << 0;
        QTest::newRow("corrupt crc") << "crc" << int(QModbusDevice::TimeoutError) << 0 << 0;
        QTest::newRow("exception 06")
            << "exception" << int(QModbusDevice::ProtocolError) << 6 << 35;
        QTest::newRow("late 250 ms") << "late" << int(QModbusDevice::NoError) << 0 << 285;
    }
    void faults()
    {
        QFETCH(QString, fault);
        QFETCH(int, expectError);
        QFETCH(int, exception);
        QFETCH(int, minMs);
        SimOptions o = rtuOptions();
        if (fault == QLatin1String("drop"))
            o.faults.drop = 1;
        else if (fault == QLatin1String("crc"))
            o.faults.corruptCrc = 1;
        else if (fault == QLatin1String("exception"))
            o.faults.exception = 1, o.faults.exceptionCode = 6;
        else
            o.faults.late = 1, o.faults.lateMs = 250;
        if (fault == QLatin1String("crc")) // proves the answer came, with a broken CRC
            QTest::ignoreMessage(QtWarningMsg, QRegularExpression(QStringLiteral("wrong CRC")));
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        c->setTimeout(800);
        const Result r = read(c.get(), 0, 2);
        QCOMPARE(int(r.error), expectError);
        QCOMPARE(r.exception, exception);
        QVERIFY2(r.ms >= minMs, qPrintable(QString::number(r.ms)));
    }

    void dropIsAShareAndSeeded()
    {
        SimOptions o = rtuOptions();
        o.answerDelayMs = 0;
        o.faults.drop = 0.5;
        o.faults.seed = 7;
        QList<int> runs[2];
        for (QList<int> &run : runs) {
            SimHost host;
            QString error;
            QVERIFY2(host.start(o, &error), qPrintable(error));
            auto c = rtuClient(host.rtuPath());
            c->setTimeout(250); // long enough that no answer arrives after its timeout
            for (int i = 0; i < 10; ++i)
                run << int(read(c.get(), 0, 1).error);
        }
        QCOMPARE(runs[0], runs[1]); // the same seed drops the same answers
        QVERIFY(runs[0].contains(int(QModbusDevice::NoError)));
        QVERIFY(runs[0].contains(int(QModbusDevice::TimeoutError)));
    }

    void hangUpAndComeBackAtTheLink()
    {
        QTemporaryDir dir;
        SimOptions o = rtuOptions();
        o.linkPath = dir.filePath(QStringLiteral("stepcom0"));
        o.faults.hangupAfter = 2;
        o.faults.hangupPauseMs = 300;
        SimHost host;
        QSignalSpy hungUp(&host, &SimHost::hungUp);
        QSignalSpy reopened(&host, &SimHost::reopened);
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        QCOMPARE(host.rtuPath(), o.linkPath);
        const QString firstPty = host.ptyPath();
        auto c = rtuClient(o.linkPath);
        QCOMPARE(read(c.get(), 0, 1).error, QModbusDevice::NoError);
        QCOMPARE(read(c.get(), 0, 1).error, QModbusDevice::NoError); // the second: then hang-up
        QVERIFY(hungUp.wait(1000));
        QVERIFY(!QFileInfo::exists(o.linkPath));
        QVERIFY(reopened.wait(2000));
        QVERIFY(QFileInfo::exists(o.linkPath));
        c.reset();
        c = rtuClient(o.linkPath);
        QVERIFY(c);
        QCOMPARE(read(c.get(), 0, 1).values, QList<quint16>{180});
        Q_UNUSED(firstPty);
    }

    void tcpServesOnAFreePort()
    {
        SimOptions o;
        o.tcp = true;
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        QVERIFY(host.tcpPort() != 0);
        QVERIFY(host.rtuPath().isEmpty());
        auto c = tcpClient(host.tcpPort());
        Result r = read(c.get(), 0, 2);
        QCOMPARE(r.values, (QList<quint16>{180, 8}));
        QVERIFY(r.ms >= 35);
        r = raw(c.get(), QModbusRequest(QModbusPdu::ReadInputRegisters, quint16(0), quint16(2)));
        QCOMPARE(r.exception, 1);
        QCOMPARE(read(c.get(), 0, 2, 9).error, QModbusDevice::TimeoutError); // other unit
        QCOMPARE(write(c.get(), 5, {600}).error, QModbusDevice::NoError);
        QCOMPARE(host.device()->value(QStringLiteral("motor1.speed")), 600);
    }

    void tcpDropAndHangUp()
    {
        SimOptions o;
        o.tcp = true;
        o.faults.drop = 1;
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = tcpClient(host.tcpPort());
        QCOMPARE(read(c.get(), 0, 1).error, QModbusDevice::TimeoutError);
        QSignalSpy reopened(&host, &SimHost::reopened);
        QSignalSpy hungUp(&host, &SimHost::hungUp);
        host.hangUp(200);
        QVERIFY(hungUp.wait(1000));
        QTRY_COMPARE_WITH_TIMEOUT(int(c->state()), int(QModbusDevice::UnconnectedState), 2000);
        // The same port takes connections again once the pause is over.
        std::unique_ptr<QModbusClient> again;
        QTRY_VERIFY_WITH_TIMEOUT(
            (again = tcpClient(host.tcpPort()))->state() == QModbusDevice::ConnectedState, 10000);
    }

    // Both TCP servers serve alike but for their framing and for a slow answer (a coil whose
    // firmware writes its flash first): behind the RTU converter the next request waits for
    // it, on Modbus TCP it is answered meanwhile (docs/simulator.md, "Timing").
    void aRequestWhileASlowAnswerIsPending_data()
    {
        QTest::addColumn<bool>("rtuFraming");
        QTest::addColumn<bool>("inOrder");
        QTest::newRow("modbus tcp") << false << false;
        QTest::newRow("rtu over tcp") << true << true;
    }
    void aRequestWhileASlowAnswerIsPending()
    {
        QFETCH(bool, rtuFraming);
        QFETCH(bool, inOrder);
        SimOptions o;
        o.slowCoils = {{5, 400}}; // 00005, motor 1 stop: harmless
        SimHost host;
        QTcpSocket socket;
        QVERIFY(serveOverTcp(host, o, rtuFraming, &socket) != 0);
        const QByteArray stopPdu = QByteArray::fromHex("050004ff00");
        const QByteArray readPdu = QByteArray::fromHex("0300000001"); // 40001, one register
        socket.write(framed(rtuFraming, 1, stopPdu).append(framed(rtuFraming, 2, readPdu)));
        // The stop's answer repeats its request; the read's has one register: 2 bytes.
        const int header = rtuFraming ? 1 : 7;
        const int trailer = rtuFraming ? 2 : 0;
        const int stopAnswer = header + int(stopPdu.size()) + trailer;
        const int readAnswer = header + 2 + 2 + trailer;
        QByteArray in;
        QVERIFY(QTest::qWaitFor(
            [&] {
                in += socket.readAll();
                return in.size() >= stopAnswer + readAnswer;
            },
            10000));
        QCOMPARE(in.size(), stopAnswer + readAnswer);
        const int first = inOrder ? 0 : readAnswer; // where the stop's answer stands
        const int second = inOrder ? stopAnswer : 0;
        QCOMPARE(in.mid(first + header, stopPdu.size()), stopPdu);
        QCOMPARE(quint8(in.at(second + header)), quint8(0x03));
        if (!rtuFraming) {
            QCOMPARE(in.mid(first, 2), QByteArray::fromHex("0001")); // each its transaction
            QCOMPARE(in.mid(second, 2), QByteArray::fromHex("0002"));
        }
    }

    // The fault plan's hang-up after every N answers ends the connection on either server, and
    // the port takes connections again after the pause.
    void faultHangUpOnEitherServer_data()
    {
        QTest::addColumn<bool>("rtuFraming");
        QTest::newRow("modbus tcp") << false;
        QTest::newRow("rtu over tcp") << true;
    }
    void faultHangUpOnEitherServer()
    {
        QFETCH(bool, rtuFraming);
        SimOptions o;
        o.faults.hangupAfter = 1;
        o.faults.hangupPauseMs = 200;
        SimHost host;
        QTcpSocket socket;
        const quint16 port = serveOverTcp(host, o, rtuFraming, &socket);
        QVERIFY(port != 0);
        socket.write(framed(rtuFraming, 7, QByteArray::fromHex("0300000001")));
        QByteArray in;
        // The answer leaves, then the line goes dead.
        QVERIFY(QTest::qWaitFor(
            [&] {
                in += socket.readAll();
                return socket.state() == QAbstractSocket::UnconnectedState;
            },
            10000));
        in += socket.readAll();
        QCOMPARE(in.size(), rtuFraming ? 7 : 11);
        const auto connects = [port] {
            QTcpSocket again;
            again.connectToHost(QHostAddress::LocalHost, port);
            return again.waitForConnected(1000);
        };
        QTRY_VERIFY_WITH_TIMEOUT(connects(), 10000);
    }

    void manualClockAndDeviceAccess()
    {
        SimOptions o;
        o.tcp = true;
        o.manualClock = true;
        o.inputs = {{3, SimMachine::InputForce::On}};
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = tcpClient(host.tcpPort());
        QVERIFY(host.device()->input(3));
        QCOMPARE(read(c.get(), 125, 1).values, QList<quint16>{1}); // 40126 = IN3
        QCOMPARE(
            raw(c.get(), QModbusRequest(QModbusPdu::WriteSingleCoil, quint16(0), quint16(0xFF00)))
                .error,
            QModbusDevice::NoError);
        QTest::qWait(100);
        QCOMPARE(host.device()->position(1), 0); // time stands still
        host.device()->advance(2000);
        QCOMPARE(read(c.get(), 107, 2).values, (QList<quint16>{1000, 0}));
    }

    void badStartReportsWhy()
    {
        SimOptions o;
        o.tcp = true;
        o.tcpAddress = QHostAddress(QStringLiteral("192.0.2.1")); // not ours
        SimHost host;
        QString error;
        QVERIFY(!host.start(o, &error));
        QVERIFY(error.contains(QStringLiteral("192.0.2.1")));
        QVERIFY(!host.isRunning());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimServers, Guiless)
#include "tst_simservers.moc"
