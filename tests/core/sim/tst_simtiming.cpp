#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QElapsedTimer>
#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;

// The controller's own answer times: --answer-delay down to 0 (firmware that answers at once)
// and --slow-coil (a command acted on at once whose answer leaves late, as when the firmware
// writes its flash first). Wall-clock checks are loose: lower bounds only.
class TstSimTiming : public QObject
{
    Q_OBJECT

private:
    struct Result
    {
        QModbusDevice::Error error = QModbusDevice::NoError;
        QList<quint16> values;
        qint64 ms = 0;
    };

    static std::unique_ptr<QModbusClient> rtuClient(const QString &path)
    {
        auto c = std::make_unique<QModbusRtuSerialClient>();
        c->setConnectionParameter(QModbusDevice::SerialPortNameParameter, path);
        c->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, 9600);
        c->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
        c->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
        c->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
        c->setTimeout(4000); // far above every delay here: a slow answer is no timeout
        c->setNumberOfRetries(0);
        if (!c->connectDevice())
            return nullptr;
        return c;
    }
    static Result finish(QModbusReply *reply, const QElapsedTimer &timer)
    {
        Result r;
        if (!reply)
            return {QModbusDevice::ConnectionError, {}, 0};
        if (!reply->isFinished()) {
            QSignalSpy spy(reply, &QModbusReply::finished);
            spy.wait(6000);
        }
        r.ms = timer.elapsed();
        r.error = reply->error();
        for (qsizetype i = 0; i < reply->result().valueCount(); ++i)
            r.values << reply->result().value(int(i));
        reply->deleteLater();
        return r;
    }
    static Result coil(QModbusClient *c, int plc)
    {
        QElapsedTimer t;
        t.start();
        return finish(c->sendWriteRequest(
                          QModbusDataUnit(QModbusDataUnit::Coils, plc - 1, QList<quint16>{1}), 1),
                      t);
    }
    static Result read(QModbusClient *c, int address, int count)
    {
        QElapsedTimer t;
        t.start();
        return finish(
            c->sendReadRequest(
                QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, quint16(count)), 1),
            t);
    }
    static QModbusRequest coilRequest(int plc, quint16 value)
    {
        return QModbusRequest(QModbusPdu::WriteSingleCoil, quint16(plc - 1), value);
    }

private Q_SLOTS:
    void responderAddsTheSlowCoilsTime()
    {
        SimDevice d;
        SimResponder r({&d}, 35, 0, {});
        r.setSlowCoils({{96, 800}, {73, 1500}});
        QCOMPARE(r.respond(1, coilRequest(96, 0xFF00)).delayMs, 35 + 800);
        QCOMPARE(r.respond(1, coilRequest(73, 0xFF00)).delayMs, 35 + 1500);
        QCOMPARE(r.respond(1, coilRequest(5, 0xFF00)).delayMs, 35);
        QCOMPARE(r.respond(1, coilRequest(96, 0x0000)).delayMs, 35); // OFF does nothing
        const QModbusRequest read(QModbusPdu::ReadHoldingRegisters, quint16(0), quint16(2));
        QCOMPARE(r.respond(1, read).delayMs, 35);
        SimResponder fast({&d}, 0, 0, {});
        QCOMPARE(fast.respond(1, read).delayMs, 0);
        SimResponder two({&d}, 2, 0, {});
        QCOMPARE(two.respond(1, read).delayMs, 2);
    }

    void fastAnswersOverThePty_data()
    {
        QTest::addColumn<int>("delay");
        QTest::newRow("0 ms") << 0;
        QTest::newRow("2 ms") << 2;
    }
    void fastAnswersOverThePty()
    {
#ifndef Q_OS_UNIX
        QSKIP("pseudo-terminals are Unix only");
#endif
        QFETCH(int, delay);
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = delay;
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(c);
        QList<qint64> times;
        for (int i = 0; i < 5; ++i) {
            const Result r = read(c.get(), 0, 2);
            QCOMPARE(r.error, QModbusDevice::NoError);
            QCOMPARE(r.values, (QList<quint16>{180, 8}));
            times << r.ms;
        }
        QCOMPARE(coil(c.get(), 5).error, QModbusDevice::NoError); // a command's echo, too
        QCOMPARE(host.stats().answers, 6);
        qInfo("fastest of 5 answers at --answer-delay %d: %s ms", delay,
              qPrintable(QString::number(*std::min_element(times.cbegin(), times.cend()))));
    }

    void slowCoilAnswersLateOverThePty()
    {
#ifndef Q_OS_UNIX
        QSKIP("pseudo-terminals are Unix only");
#endif
        SimOptions o;
        o.rtu = true;
        o.slowCoils = {{96, 800}, {2, 1500}};
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(c);
        const Result normal = coil(c.get(), 5); // motor 1 stop
        QCOMPARE(normal.error, QModbusDevice::NoError);
        const Result save = coil(c.get(), 96);
        QCOMPARE(save.error, QModbusDevice::NoError);
        const QString times =
            QStringLiteral("normal %1 ms, save %2 ms").arg(normal.ms).arg(save.ms);
        QVERIFY2(save.ms >= 35 + 800 - 20, qPrintable(times));
        QVERIFY2(save.ms - normal.ms >= 800 - 50, qPrintable(times));

        // Acted on at once: motor 1 runs long before the answer to its forward command leaves.
        QElapsedTimer t;
        t.start();
        QModbusReply *reply =
            c->sendWriteRequest(QModbusDataUnit(QModbusDataUnit::Coils, 1, QList<quint16>{1}), 1);
        QVERIFY(reply);
        QTRY_VERIFY_WITH_TIMEOUT(host.device()->running(1), 1000);
        QVERIFY2(!reply->isFinished() || t.elapsed() >= 1400, "the answer came too soon");
        const Result forward = finish(reply, t);
        QCOMPARE(forward.error, QModbusDevice::NoError);
        QVERIFY2(forward.ms >= 35 + 1500 - 20, qPrintable(QString::number(forward.ms)));
        QVERIFY(host.device()->running(1));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimTiming, Guiless)
#include "tst_simtiming.moc"
