#include "device/writeplanner.h"
#include "map/registermap.h"

#include <QTest>

using namespace stepcom;

class TestWritePlanner : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();
    ParameterWrite w(const char *key, qint64 raw)
    {
        return {map.find(QString::fromLatin1(key)), raw};
    }

private Q_SLOTS:
    void singleRegisterIsFc06()
    {
        const QList<Request> plan = WritePlanner::plan({w("motor1.microsteps", 4)}, 49);
        QCOMPARE(plan.size(), 1);
        QCOMPARE(plan[0].functionCode(), 0x06);
        QCOMPARE(plan[0].address, quint16(1));
        QCOMPARE(plan[0].values, QVector<quint16>{4});
        QCOMPARE(plan[0].what, QStringLiteral("motor1.microsteps"));
    }

    void thirtyTwoBitIsOneFc10()
    {
        const QList<Request> plan = WritePlanner::plan({w("motor1.move_distance", 200)}, 49);
        QCOMPARE(plan.size(), 1);
        QCOMPARE(plan[0].functionCode(), 0x10);
        QCOMPARE(plan[0].address, quint16(8));
        QCOMPARE(plan[0].values, (QVector<quint16>{0x00C8, 0x0000}));
    }

    void contiguousRegistersMerge()
    {
        // given out of order; 40001..40006 follow each other, 40081 stands apart
        const QList<Request> plan = WritePlanner::plan(
            {w("motor1.speed", 300), w("motor1.step_angle", 180), w("motor1.microsteps", 8),
             w("motor1.start_frequency", 400), w("motor1.accel_frequency", 2000),
             w("motor1.direction", 1), w("motor1.limit_positive", 2)},
            49);
        QCOMPARE(plan.size(), 2);
        QCOMPARE(plan[0].address, quint16(0));
        QCOMPARE(plan[0].values, (QVector<quint16>{180, 8, 400, 2000, 1, 300}));
        QCOMPARE(plan[1].address, quint16(80));
        QCOMPARE(plan[1].functionCode(), 0x06);
    }

    void splitsBelowTheLimitButNeverThroughAValue()
    {
        QList<ParameterWrite> writes{w("arc.start_x", -1), w("arc.start_y", 2), w("arc.end_x", 3)};
        const QList<Request> plan = WritePlanner::plan(writes, 3); // 2+2 would exceed 3
        QCOMPARE(plan.size(), 3);
        for (const Request &r : plan)
            QCOMPARE(r.values.size(), 2);
        QCOMPARE(plan[0].values, (QVector<quint16>{0xFFFF, 0xFFFF}));
    }

    void everyWritableParameterFitsTheLimit()
    {
        QList<ParameterWrite> writes;
        for (const Parameter *p : map.holdings()) {
            if (p->writable())
                writes.append({p, p->rawMin});
        }
        const QList<Request> plan = WritePlanner::plan(writes, 49);
        int total = 0;
        for (const Request &r : plan) {
            QVERIFY(r.values.size() <= 49);
            total += int(r.values.size());
        }
        QCOMPARE(total, 62);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestWritePlanner, Guiless)
#include "tst_writeplanner.moc"
