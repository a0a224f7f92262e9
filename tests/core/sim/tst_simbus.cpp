#include "session/idlist.h"
#include "sim/host/simcommandline.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QModbusTcpClient>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;

// Several simulated controllers on one port (stepcom-sim --ids): each answers only its own id,
// keeps its own registers, and two at the same id collide.
class TstSimBus : public QObject
{
    Q_OBJECT

private:
    struct Answer
    {
        QModbusDevice::Error error = QModbusDevice::NoError;
        QList<quint16> values;
    };

    static std::unique_ptr<QModbusClient> client(const SimHost &host)
    {
        std::unique_ptr<QModbusClient> c;
        if (host.options().tcp) {
            c = std::make_unique<QModbusTcpClient>();
            c->setConnectionParameter(QModbusDevice::NetworkAddressParameter,
                                      QStringLiteral("127.0.0.1"));
            c->setConnectionParameter(QModbusDevice::NetworkPortParameter, host.tcpPort());
        } else {
            c = std::make_unique<QModbusRtuSerialClient>();
            c->setConnectionParameter(QModbusDevice::SerialPortNameParameter, host.rtuPath());
            c->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, 9600);
            c->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
            c->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
            c->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
        }
        c->setTimeout(400);
        c->setNumberOfRetries(0);
        QSignalSpy spy(c.get(), &QModbusDevice::stateChanged);
        c->connectDevice();
        for (int i = 0; i < 20 && c->state() != QModbusDevice::ConnectedState; ++i)
            spy.wait(100);
        return c;
    }
    static Answer finish(QModbusReply *reply)
    {
        Answer a;
        if (!reply)
            return {QModbusDevice::ConnectionError, {}};
        if (!reply->isFinished()) {
            QSignalSpy spy(reply, &QModbusReply::finished);
            spy.wait(3000);
        }
        a.error = reply->error();
        for (qsizetype i = 0; i < reply->result().valueCount(); ++i)
            a.values << reply->result().value(int(i));
        reply->deleteLater();
        return a;
    }
    static Answer read(QModbusClient *c, int unit, int address, int count = 1)
    {
        return finish(c->sendReadRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, quint16(count)), unit));
    }
    static Answer write(QModbusClient *c, int unit, int address, quint16 value)
    {
        return finish(c->sendWriteRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, QList<quint16>{value}),
            unit));
    }
    static SimOptions options(bool tcp, QList<int> ids)
    {
        SimOptions o;
        o.rtu = !tcp;
        o.tcp = tcp;
        o.ids = std::move(ids);
        o.answerDelayMs = 5;
        return o;
    }
    static constexpr int kSpeed = 0;      // 40001, motor 1 speed
    static constexpr int kDeviceId = 211; // 40212

private Q_SLOTS:
    void eachIdAnswersWithItsOwnRegisters_data()
    {
        QTest::addColumn<bool>("tcp");
        QTest::newRow("rtu") << false;
        QTest::newRow("tcp") << true;
    }
    void eachIdAnswersWithItsOwnRegisters()
    {
        QFETCH(bool, tcp);
#ifndef Q_OS_UNIX
        if (!tcp)
            QSKIP("pseudo-terminals are Unix only");
#endif
        SimHost host;
        QString error;
        QVERIFY2(host.start(options(tcp, {1, 2, 3}), &error), qPrintable(error));
        QCOMPARE(host.devices().size(), 3);
        auto c = client(host);
        QCOMPARE(c->state(), QModbusDevice::ConnectedState);
        for (int id : {1, 2, 3}) {
            const Answer a = read(c.get(), id, kDeviceId);
            QCOMPARE(a.error, QModbusDevice::NoError);
            QCOMPARE(a.values, QList<quint16>{quint16(id)});
        }
        // A write to id 2 changes id 2 only.
        QCOMPARE(write(c.get(), 2, kSpeed, 250).error, QModbusDevice::NoError);
        QCOMPARE(read(c.get(), 1, kSpeed).values, QList<quint16>{180});
        QCOMPARE(read(c.get(), 2, kSpeed).values, QList<quint16>{250});
        QCOMPARE(read(c.get(), 3, kSpeed).values, QList<quint16>{180});
        const Parameter *speed = host.device()->map().holdingAt(kSpeed);
        QVERIFY(speed);
        QCOMPARE(host.deviceAt(2)->value(speed->key), qint64(250));
        QCOMPARE(host.deviceAt(3)->value(speed->key), qint64(180));
        // No controller at id 4: silence.
        QCOMPARE(read(c.get(), 4, kSpeed).error, QModbusDevice::TimeoutError);
        QCOMPARE(host.stats().collisions, 0);
    }

    void commandMovesOnlyItsController()
    {
        SimHost host;
        QString error;
        QVERIFY2(host.start(options(true, {1, 2, 3}), &error), qPrintable(error));
        auto c = client(host);
        const Parameter *move = host.device()->map().find(QStringLiteral("motor1.move"));
        QVERIFY(move);
        const Answer a = finish(c->sendWriteRequest(
            QModbusDataUnit(QModbusDataUnit::Coils, move->address, QList<quint16>{1}), 3));
        QCOMPARE(a.error, QModbusDevice::NoError);
        QVERIFY(host.deviceAt(3)->running(1));
        QVERIFY(!host.deviceAt(1)->running(1));
        QVERIFY(!host.deviceAt(2)->running(1));
    }

    void twoControllersAtOneIdCollide_data()
    {
        eachIdAnswersWithItsOwnRegisters_data();
    }
    void twoControllersAtOneIdCollide()
    {
        QFETCH(bool, tcp);
#ifndef Q_OS_UNIX
        if (!tcp)
            QSKIP("pseudo-terminals are Unix only");
#endif
        SimHost host;
        QString error;
        QVERIFY2(host.start(options(tcp, {1, 1, 2}), &error), qPrintable(error));
        auto c = client(host);
        const Answer garbled = read(c.get(), 1, kDeviceId);
        QVERIFY2(garbled.error != QModbusDevice::NoError, "two answers at once must be garbage");
        QCOMPARE(host.stats().collisions, 1);
        // Both heard the write, so both act on it, and the answer is garbage again.
        QVERIFY(write(c.get(), 1, kSpeed, 300).error != QModbusDevice::NoError);
        const QString speed = host.device()->map().holdingAt(kSpeed)->key;
        QCOMPARE(host.devices().at(0)->value(speed), qint64(300));
        QCOMPARE(host.devices().at(1)->value(speed), qint64(300));
        QCOMPARE(host.devices().at(2)->value(speed), qint64(180));
        // The third, alone at its id, answers cleanly.
        const Answer clean = read(c.get(), 2, kDeviceId);
        QCOMPARE(clean.error, QModbusDevice::NoError);
        QCOMPARE(clean.values, QList<quint16>{2});
    }

    void idsOption_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QList<int>>("ids");
        QTest::addColumn<QString>("error");
        QTest::newRow("list") << QStringList{"--ids", "1,2,3"} << QList<int>{1, 2, 3} << "";
        QTest::newRow("range") << QStringList{"--ids", "2-4"} << QList<int>{2, 3, 4} << "";
        QTest::newRow("collision") << QStringList{"--ids", "1,1"} << QList<int>{1, 1} << "";
        QTest::newRow("zero") << QStringList{"--ids", "0,1"} << QList<int>{} << "--ids: '0'";
        QTest::newRow("word") << QStringList{"--ids", "a"} << QList<int>{} << "--ids: 'a'";
        QTest::newRow("both") << QStringList{"--id", "2", "--ids", "1,2"} << QList<int>{}
                              << "--ids: give either";
    }
    void idsOption()
    {
        QFETCH(QStringList, args);
        QFETCH(QList<int>, ids);
        QFETCH(QString, error);
        QCommandLineParser parser;
        SimCommandLine::addOptions(parser);
        QVERIFY(parser.parse(QStringList{QStringLiteral("stepcom-sim")} + args));
        SimOptions o;
        QString why;
        const bool ok = SimCommandLine::toOptions(parser, &o, &why);
        QCOMPARE(ok, error.isEmpty());
        if (ok)
            QCOMPARE(o.ids, ids);
        else
            QVERIFY2(why.startsWith(error), qPrintable(why));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimBus, Guiless)
#include "tst_simbus.moc"
