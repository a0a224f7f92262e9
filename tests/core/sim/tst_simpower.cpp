#include "sim/host/simconsole.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "sim/model/simmachine.h"
#include "sim/model/simregisters.h"
#include "simdevicechecks.h"

#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;
using namespace stepcom::test;

// The 24 V supply switched off and on: silence meanwhile, then what was saved to flash,
// positions 0, nothing running, referenced or switched on; on a manual clock, on a line of
// three and over the pty.
class TstSimPower : public QObject
{
    Q_OBJECT

private:
    static QModbusRequest readRequest(int address, int count)
    {
        return QModbusRequest(QModbusPdu::ReadHoldingRegisters, quint16(address), quint16(count));
    }
    static std::unique_ptr<QModbusClient> rtuClient(const QString &path)
    {
        auto c = std::make_unique<QModbusRtuSerialClient>();
        c->setConnectionParameter(QModbusDevice::SerialPortNameParameter, path);
        c->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, 9600);
        c->setConnectionParameter(QModbusDevice::SerialParityParameter, QSerialPort::NoParity);
        c->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, QSerialPort::Data8);
        c->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, QSerialPort::OneStop);
        c->setTimeout(400);
        c->setNumberOfRetries(0);
        if (!c->connectDevice())
            return nullptr;
        return c;
    }
    static QModbusDevice::Error finish(QModbusReply *reply, QList<quint16> *values = nullptr)
    {
        if (!reply)
            return QModbusDevice::ConnectionError;
        if (!reply->isFinished()) {
            QSignalSpy spy(reply, &QModbusReply::finished);
            spy.wait(3000);
        }
        const QModbusDevice::Error error = reply->error();
        if (values)
            for (qsizetype i = 0; i < reply->result().valueCount(); ++i)
                *values << reply->result().value(int(i));
        reply->deleteLater();
        return error;
    }
    static QModbusDevice::Error read(QModbusClient *c, int unit, int address,
                                     QList<quint16> *values = nullptr)
    {
        return finish(c->sendReadRequest(
                          QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, 1), unit),
                      values);
    }
    static QModbusDevice::Error write(QModbusClient *c, int unit, int address, quint16 value)
    {
        return finish(c->sendWriteRequest(
            QModbusDataUnit(QModbusDataUnit::HoldingRegisters, address, QList<quint16>{value}),
            unit));
    }
    static constexpr int kSpeed = 5;      // 40006, motor 1 speed
    static constexpr int kDeviceId = 211; // 40212

private Q_SLOTS:
    void offIsSilentAndPowerReturnsWithFlash()
    {
        SimDevice d; // no clock: only advance() moves time
        int linkCalls = 0;
        d.setLinkObserver([&linkCalls] { ++linkCalls; });
        set(d, "motor1.speed", 250);
        cmd(d, "save_to_flash");
        set(d, "motor1.microsteps", 16); // never saved
        set(d, "device.id", 7);          // never saved
        QCOMPARE(linkCalls, 1);
        cmd(d, "output1_on");
        cmd(d, "motor1.forward");
        d.advance(1000);
        QVERIFY(d.running(1));
        QVERIFY(d.output(1));
        QVERIFY(value(d, "motor1.position") > 0);
        const double carriage = d.machinePosition(1);

        d.powerCycle(3000);
        QVERIFY(d.isPoweredOff());
        QVERIFY(!d.running(1)); // the motors stop at once
        QVERIFY(!d.output(1));
        QVERIFY(!d.handle(readRequest(0, 2)).response.isValid());
        QVERIFY(!d.handle(QModbusRequest(QModbusPdu::WriteSingleCoil, quint16(1), quint16(0xFF00)))
                     .response.isValid());
        QString error;
        QVERIFY(!d.setValue(QStringLiteral("motor1.speed"), 100, &error));
        QVERIFY2(error.contains(QStringLiteral("switched off")), qPrintable(error));
        QVERIFY(!d.command(QStringLiteral("motor1.forward"), &error));
        QVERIFY(d.statusText().contains(QStringLiteral("24 V off")));
        d.advance(2999);
        QVERIFY(d.isPoweredOff());
        QVERIFY(!d.handle(readRequest(0, 2)).response.isValid());

        d.advance(1);
        QVERIFY(!d.isPoweredOff());
        QCOMPARE(value(d, "motor1.speed"), 250);    // saved
        QCOMPARE(value(d, "motor1.microsteps"), 8); // lost
        QCOMPARE(d.deviceId(), 1);                  // the unsaved id is lost too
        QCOMPARE(linkCalls, 2);                     // so the server follows it
        QCOMPARE(value(d, "motor1.position"), 0);
        QCOMPARE(d.steps(1), 0);
        QCOMPARE(d.machinePosition(1), carriage); // the carriage stays where it is
        QVERIFY(!d.running(1));
        QVERIFY(!d.output(1));
        QCOMPARE(value(d, "io.out1"), 0);
        QVERIFY(d.handle(readRequest(0, 2)).response.isValid());
        d.advance(500);
        QVERIFY(!d.running(1)); // nothing starts by itself
    }

    void powerReturnsOnTheDevicesClock()
    {
        SimDevice d;
        qint64 t = 1000;
        d.setClock([&t] { return t; });
        d.powerCycle(500);
        t += 499;
        QVERIFY(d.isPoweredOff());
        t += 1;
        QVERIFY(!d.isPoweredOff());
        // Off again while off: the off time starts again.
        d.powerCycle(300);
        t += 200;
        d.powerCycle(300);
        t += 200;
        QVERIFY(d.isPoweredOff());
        t += 100;
        QVERIFY(!d.isPoweredOff());
    }

    void savedIdAndBaudSurvive()
    {
        SimDevice d;
        set(d, "device.id", 12);
        set(d, "device.baud", 19200);
        cmd(d, "save_to_flash");
        set(d, "device.baud", 38400);
        d.powerCycle(10);
        d.advance(10);
        QCOMPARE(d.deviceId(), 12);
        QCOMPARE(d.baud(), 19200);
        // setSavedValue(): what --id gives a controller of a line, kept through a power cycle.
        QString error;
        QVERIFY2(d.setSavedValue(QStringLiteral("device.id"), 3, &error), qPrintable(error));
        d.powerCycle(10);
        d.advance(10);
        QCOMPARE(d.deviceId(), 3);
    }

    void homingAndInputsAreForgotten()
    {
        SimDevice d;
        d.setMachinePosition(1, 30);
        d.setMachinePosition(2, 30);
        cmd(d, "home_all");
        d.advance(200);
        QVERIFY(d.running(1)); // homing motor 1, motor 2 queued
        d.powerCycle(100);
        d.advance(100);
        QVERIFY(!d.isPoweredOff());
        d.advance(5000);
        QVERIFY(!d.running(1));
        QVERIFY(!d.running(2)); // the sequence did not go on with motor 2

        // Mode 3 (IN1 runs forward): a pulse while off is not seen.
        set(d, "mode.system", 3);
        cmd(d, "save_to_flash");
        d.powerCycle(300);
        d.setInput(1, SimDevice::InputForce::Pulse);
        d.advance(300);
        QVERIFY(!d.isPoweredOff());
        d.advance(100);
        QVERIFY(!d.running(1));
        QCOMPARE(value(d, "mode.system"), 3);
        d.setInput(1, SimDevice::InputForce::Pulse); // with power it is
        d.advance(10);
        QVERIFY(d.running(1));
    }

    void machinePowerUpClearsHomed()
    {
        SimRegisters regs(RegisterMap::builtin());
        SimMachine m(regs);
        m.setMachinePosition(1, 1);
        m.home(1);
        m.advance(500);
        QVERIFY(m.homed(1));
        m.jog(2, 1);
        m.setOutput(2, true);
        m.advance(200);
        QVERIFY(m.axis(2).positionRaw() > 0);
        m.powerDown();
        QVERIFY(!m.powered());
        QVERIFY(!m.axis(2).isRunning());
        m.powerUp();
        QVERIFY(m.powered());
        QVERIFY(!m.homed(1));
        QVERIFY(!m.homingSequenceActive());
        QCOMPARE(m.axis(1).positionRaw(), 0);
        QCOMPARE(m.axis(2).positionRaw(), 0);
        QVERIFY(!m.output(2));
    }

    void onlyTheCycledControllerOfALineGoesSilent()
    {
#ifndef Q_OS_UNIX
        QSKIP("pseudo-terminals are Unix only");
#endif
        SimOptions o;
        o.rtu = true;
        o.ids = {1, 2, 3};
        o.answerDelayMs = 5;
        o.manualClock = true; // the off time passes only by advance()
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(c);
        for (int id : {1, 2, 3})
            QCOMPARE(write(c.get(), id, kSpeed, quint16(100 + id)), QModbusDevice::NoError);
        QVERIFY(!host.powerCycle(1000, 9));
        QVERIFY(host.powerCycle(1000, 2));
        SimDevice *two = host.devices().at(1);
        QVERIFY(two->isPoweredOff());
        QVERIFY(!host.devices().at(0)->isPoweredOff());
        QList<quint16> values;
        QCOMPARE(read(c.get(), 1, kSpeed, &values), QModbusDevice::NoError);
        QCOMPARE(read(c.get(), 2, kSpeed), QModbusDevice::TimeoutError);
        QCOMPARE(read(c.get(), 3, kSpeed, &values), QModbusDevice::NoError);
        QCOMPARE(values, (QList<quint16>{101, 103}));
        two->advance(1000);
        values.clear();
        // Back with its own id (the one it was given is in its flash), its write lost.
        QCOMPARE(read(c.get(), 2, kSpeed, &values), QModbusDevice::NoError);
        QCOMPARE(values, QList<quint16>{300});
        QCOMPARE(read(c.get(), 2, kDeviceId, &values), QModbusDevice::NoError);
        QCOMPARE(values.last(), 2);
        QCOMPARE(host.devices().at(0)->value(QStringLiteral("motor1.speed")), qint64(101));
        QCOMPARE(host.stats().collisions, 0);
    }

    void ptyIsSilentWhileOffAndTheIdReverts()
    {
#ifndef Q_OS_UNIX
        QSKIP("pseudo-terminals are Unix only");
#endif
        SimOptions o;
        o.rtu = true;
        o.answerDelayMs = 5;
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        auto c = rtuClient(host.rtuPath());
        QVERIFY(c);
        QCOMPARE(write(c.get(), 1, kDeviceId, 9), QModbusDevice::NoError); // not saved
        // The server follows the new id once the answer is out.
        QTRY_COMPARE_WITH_TIMEOUT(read(c.get(), 9, kDeviceId), QModbusDevice::NoError, 10000);
        QVERIFY(host.powerCycle(1500));
        QCOMPARE(read(c.get(), 9, kDeviceId), QModbusDevice::TimeoutError);
        QCOMPARE(read(c.get(), 1, kDeviceId), QModbusDevice::TimeoutError);
        // Back from the power cycle (1.5 s off) under the id in flash.
        QList<quint16> values;
        QTRY_COMPARE_WITH_TIMEOUT(read(c.get(), 1, kDeviceId, &values), QModbusDevice::NoError,
                                  15000);
        QCOMPARE(values.last(), 1);
        QCOMPARE(read(c.get(), 9, kDeviceId), QModbusDevice::TimeoutError);
    }

    void scheduledPowerCycle()
    {
        SimOptions o;
        o.tcp = true;
        o.powerCycles = {{100, 300}};
        SimHost host;
        QSignalSpy messages(&host, &SimHost::message);
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        QVERIFY(!host.device()->isPoweredOff());
        QTRY_VERIFY_WITH_TIMEOUT(host.device()->isPoweredOff(), 3000);
        QCOMPARE(messages.value(0).value(0).toString(),
                 QStringLiteral("power cycle: 24 V off for 0.3 s"));
        QTRY_VERIFY_WITH_TIMEOUT(!host.device()->isPoweredOff(), 3000);
        QTRY_COMPARE_WITH_TIMEOUT(messages.size(), 2, 3000);
        // Stopping cancels cycles still to come.
        o.powerCycles = {{200, 300}};
        QVERIFY2(host.start(o, &error), qPrintable(error));
        host.stop();
        QTest::qWait(300);
        QCOMPARE(messages.size(), 2);
    }

    void consoleCommand()
    {
        SimOptions o;
        o.tcp = true;
        o.manualClock = true;
        o.ids = {1, 2, 3};
        SimHost host;
        QString error;
        QVERIFY2(host.start(o, &error), qPrintable(error));
        SimConsole c(&host);
        QVERIFY(c.execute(QStringLiteral("help")).text.contains(QStringLiteral("power-cycle")));
        SimConsole::Result r = c.execute(QStringLiteral("power-cycle 1.5 id 2"));
        QVERIFY2(r.ok, qPrintable(r.text));
        QCOMPARE(r.text, QStringLiteral("id 2: 24 V off for 1.5 s"));
        QVERIFY(!host.devices().at(0)->isPoweredOff());
        QVERIFY(host.devices().at(1)->isPoweredOff());
        host.devices().at(1)->advance(1499);
        QVERIFY(host.devices().at(1)->isPoweredOff());
        host.devices().at(1)->advance(1);
        QVERIFY(!host.devices().at(1)->isPoweredOff());

        r = c.execute(QStringLiteral("power-cycle"));
        QCOMPARE(r.text, QStringLiteral("24 V off for 3 s"));
        for (SimDevice *d : host.devices())
            QVERIFY(d->isPoweredOff());
        QVERIFY(c.execute(QStringLiteral("status")).text.contains(QStringLiteral("24 V off")));
        host.devices().at(0)->advance(3000);
        QVERIFY(!host.devices().at(0)->isPoweredOff());
        QVERIFY(host.devices().at(2)->isPoweredOff()); // each on its own clock
        QVERIFY(c.execute(QStringLiteral("power-cycle id 3")).ok);

        for (const char *bad :
             {"power-cycle 0", "power-cycle -2", "power-cycle abc", "power-cycle 3 id",
              "power-cycle 3 id 0", "power-cycle 3 2", "power-cycle 3 id 2 4"}) {
            r = c.execute(QLatin1String(bad));
            QVERIFY2(!r.ok && r.text.startsWith(QStringLiteral("usage: power-cycle")), bad);
        }
        r = c.execute(QStringLiteral("power-cycle 2 id 9"));
        QVERIFY(!r.ok);
        QCOMPARE(r.text, QStringLiteral("no controller has id 9"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstSimPower, Guiless)
#include "tst_simpower.moc"
