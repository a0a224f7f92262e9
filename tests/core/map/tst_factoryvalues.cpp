#include "map/factoryvalues.h"
#include "sim/model/simregisters.h"
#include "testmaps.h"

#include <QTest>

using namespace stepcom;

// The factory values: the manual's where it names one, always a value the map allows, for
// every map of the family; the simulator starts from them and only wires its switches.
class TestFactoryValues : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void theManualsValues()
    {
        const RegisterMap &map = RegisterMap::builtin();
        const QHash<QString, qint64> v = FactoryValues::writable(map);
        QCOMPARE(v.value(QStringLiteral("device.id")), 1);
        QCOMPARE(v.value(QStringLiteral("device.baud")), 9600);
        QCOMPARE(v.value(QStringLiteral("mode.system")), 0);
        for (const char *key :
             {"motor1.limit_positive", "motor1.limit_negative", "motor1.home_input",
              "motor2.limit_positive", "motor2.limit_negative", "motor2.home_input"})
            QCOMPARE(v.value(QLatin1String(key), -1), 0); // 0 = none (the manual's default)
        QCOMPARE(v.value(QStringLiteral("motor1.step_angle")), 180);
        QCOMPARE(v.value(QStringLiteral("motor2.speed")), 300);
    }

    void alwaysAllowedInEveryMap()
    {
        QStringList errors;
        const auto three = test::threeAxisMap(&errors);
        const auto lite = test::liteVariantMap(&errors);
        QVERIFY2(three && lite, qPrintable(errors.join(QLatin1Char('\n'))));
        for (const RegisterMap *map : {&RegisterMap::builtin(), &*three, &*lite}) {
            const QHash<QString, qint64> v = FactoryValues::writable(*map);
            int writable = 0;
            for (const Parameter &p : map->parameters()) {
                if (!p.writable())
                    continue;
                ++writable;
                QVERIFY2(v.contains(p.key), qPrintable(p.key));
                QVERIFY2(p.checkRaw(v.value(p.key)).isEmpty(), qPrintable(p.key));
            }
            QCOMPARE(v.size(), writable);
        }
        QCOMPARE(FactoryValues::writable(*three).value(QStringLiteral("motor3.speed")), 300);
    }

    void theSimulatorStartsFromThem()
    {
        const RegisterMap &map = RegisterMap::builtin();
        const SimRegisters sim(map);
        for (const Parameter &p : map.parameters()) {
            if (!p.writable())
                continue;
            const bool input = p.localKey.startsWith(QLatin1String("limit_")) ||
                               p.localKey == QLatin1String("home_input");
            if (!input)
                QCOMPARE(sim.raw(&p), FactoryValues::value(p));
        }
        // Its demo machine has switches: motor 1 on IN1/IN2, motor 2 on IN3/IN4.
        QCOMPARE(sim.raw(QStringLiteral("motor1.limit_positive")), 1);
        QCOMPARE(sim.raw(QStringLiteral("motor2.home_input")), 4);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestFactoryValues, Gui)
#include "tst_factoryvalues.moc"
