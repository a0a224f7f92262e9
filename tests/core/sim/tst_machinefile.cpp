#include "sim/model/machinefile.h"

#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

QByteArray machineFileJson(const QByteArray &axis, const QByteArray &global = QByteArray())
{
    return R"({"format": "stepcom-sim-machine", "version": 1)" +
           (global.isEmpty() ? QByteArray() : ", " + global) + R"(, "axes": {"motor1": {)" + axis +
           "}}}";
}

} // namespace

// The simulator's machine file: every key read, every mistake refused with the file, the key
// path and what is wrong.
class TstMachineFile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void readsEveryKey()
    {
        QString error;
        const auto m = MachineFile::parse(
            machineFileJson(
                R"("pull_out_rpm": 600, "pull_in_rpm": 90, "accel_limit_rpm_per_s": 5000,
                 "backlash_mm": 0.04, "travel_mm": 300, "start_mm": 12, "negative_switch_mm": 1,
                 "positive_switch_mm": 290, "switch_jitter_mm": 0.01,
                 "switch_hysteresis_mm": 0.2, "hard_stop_mm": 3,
                 "wiring": {"negative": 2, "positive": 1, "home": 4})",
                R"("homing_zeroes_count": false, "seed": 42)"),
            QStringLiteral("m.json"), &error);
        QVERIFY2(m, qPrintable(error));
        QCOMPARE(m->source, QStringLiteral("m.json"));
        QCOMPARE(m->homingZeroesCount, false);
        QCOMPARE(m->seed, 42u);
        const AxisPhysics a = m->axis(1);
        QCOMPARE(a.pullOutRpm, 600.0);
        QCOMPARE(a.pullInRpm, 90.0);
        QCOMPARE(a.accelLimitRpmPerS, 5000.0);
        QCOMPARE(a.backlashMm, 0.04);
        QCOMPARE(a.travelMm, std::optional<double>(300));
        QCOMPARE(a.startMm, std::optional<double>(12));
        QCOMPARE(a.negativeSwitchMm, 1.0);
        QCOMPARE(a.positiveSwitchMm, std::optional<double>(290));
        QCOMPARE(a.switchJitterMm, 0.01);
        QCOMPARE(a.switchHysteresisMm, 0.2);
        QCOMPARE(a.hardStopMm, 3.0);
        QVERIFY(a.wiring);
        QCOMPARE(a.wiring->negative, 2);
        QCOMPARE(a.wiring->positive, 1);
        QCOMPARE(a.wiring->home, 4);
    }

    void defaultsAreHealthy()
    {
        QString error;
        const auto m = MachineFile::parse(R"({"format": "stepcom-sim-machine", "version": 1})",
                                          QStringLiteral("m.json"), &error);
        QVERIFY2(m, qPrintable(error));
        QVERIFY(m->homingZeroesCount);
        QCOMPARE(m->seed, 1u);
        const AxisPhysics a = m->axis(2);
        QVERIFY(std::isinf(a.pullOutRpm) && std::isinf(a.pullInRpm));
        QVERIFY(std::isinf(a.accelLimitRpmPerS));
        QCOMPARE(a.backlashMm, 0.0);
        QCOMPARE(a.switchJitterMm, 0.002);
        QCOMPARE(a.switchHysteresisMm, 0.0);
        QCOMPARE(a.hardStopMm, 5.0);
        QVERIFY(!a.wiring && !a.travelMm && !a.startMm && !a.positiveSwitchMm);
        // Without any machine file the switches are exact, as before.
        QCOMPARE(MachineSettings::ideal().axis(1).switchJitterMm, 0.0);
    }

    void refusesMistakes_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("not JSON") << QByteArray("{") << QStringLiteral("m.json: not JSON");
        QTest::newRow("no format")
            << QByteArray(R"({"version": 1})") << QStringLiteral("m.json: format: must be");
        QTest::newRow("version 2")
            << QByteArray(R"({"format": "stepcom-sim-machine", "version": 2})")
            << QStringLiteral("m.json: version: must be 1");
        QTest::newRow("unknown global key")
            << QByteArray(R"({"format": "stepcom-sim-machine", "version": 1, "speed": 3})")
            << QStringLiteral("m.json: speed: unknown key");
        QTest::newRow("unknown axis") << machineFileJson("").replace("motor1", "motorX")
                                      << QStringLiteral("m.json: axes.motorX: unknown key");
        QTest::newRow("unknown axis key")
            << machineFileJson(R"("pullout": 3)")
            << QStringLiteral("m.json: axes.motor1.pullout: unknown key");
        QTest::newRow("wrong type")
            << machineFileJson(R"("backlash_mm": "0.1")")
            << QStringLiteral("m.json: axes.motor1.backlash_mm: must be a number");
        QTest::newRow("negative backlash")
            << machineFileJson(R"("backlash_mm": -0.1)")
            << QStringLiteral("m.json: axes.motor1.backlash_mm: -0.1 is out of range");
        QTest::newRow("pull-in above pull-out")
            << machineFileJson(R"("pull_out_rpm": 100, "pull_in_rpm": 200)")
            << QStringLiteral("m.json: axes.motor1.pull_in_rpm: 200 is above pull_out_rpm");
        QTest::newRow("pull-in 0") << machineFileJson(R"("pull_in_rpm": 0)")
                                   << QStringLiteral("m.json: axes.motor1.pull_in_rpm: 0 is out");
        QTest::newRow("bool as number")
            << machineFileJson("", R"("homing_zeroes_count": 1)")
            << QStringLiteral("m.json: homing_zeroes_count: must be true or false");
        QTest::newRow("fractional seed") << machineFileJson("", R"("seed": 1.5)")
                                         << QStringLiteral("m.json: seed: must be a whole number");
        QTest::newRow("input 5")
            << machineFileJson(R"("wiring": {"home": 5})")
            << QStringLiteral("m.json: axes.motor1.wiring.home: 5 is out of range (0 to 4)");
        QTest::newRow("unknown wire")
            << machineFileJson(R"("wiring": {"index": 1})")
            << QStringLiteral("m.json: axes.motor1.wiring.index: unknown key");
        QTest::newRow("switches crossed")
            << machineFileJson(R"("negative_switch_mm": 10, "positive_switch_mm": 5)")
            << QStringLiteral("m.json: axes.motor1.positive_switch_mm: 5 is not above");
        QTest::newRow("start beyond the stops")
            << machineFileJson(R"("travel_mm": 100, "start_mm": 200)")
            << QStringLiteral("m.json: axes.motor1.start_mm: 200 is beyond the hard stops");
        QTest::newRow("axis not an object") << QByteArray(R"({"format": "stepcom-sim-machine",
            "version": 1, "axes": {"motor1": 3}})")
                                            << QStringLiteral("m.json: axes.motor1: must be an "
                                                              "object");
    }
    void refusesMistakes()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        QString error;
        QVERIFY(!MachineFile::parse(json, QStringLiteral("m.json"), &error));
        QVERIFY2(error.startsWith(message), qPrintable(error));
    }

    void loadNamesTheFile()
    {
        QString error;
        QVERIFY(!MachineFile::load(QStringLiteral("/nonexistent/m.json"), &error));
        QVERIFY2(error.startsWith(QStringLiteral("/nonexistent/m.json: ")), qPrintable(error));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("machine.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(machineFileJson(R"("backlash_mm": 0.02)"));
        f.close();
        const auto m = MachineFile::load(path, &error);
        QVERIFY2(m, qPrintable(error));
        QCOMPARE(m->axis(1).backlashMm, 0.02);
        QCOMPARE(m->source, path);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstMachineFile, Guiless)
#include "tst_machinefile.moc"
