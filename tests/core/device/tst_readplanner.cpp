#include "device/readlimits.h"
#include "device/readplanner.h"
#include "map/registermap.h"

#include <QTest>

using namespace stepcom;

namespace {

const RegisterMap &map()
{
    return RegisterMap::builtin();
}

QList<const Parameter *> keys(const QStringList &names)
{
    QList<const Parameter *> out;
    for (const QString &k : names)
        out << map().find(k);
    return out;
}

QList<const Parameter *> statusParams()
{
    return keys({"motor1.position", "motor2.position", "io.in1", "io.in2", "io.in3", "io.in4",
                 "io.out1", "io.out2", "io.out3", "motor1.running", "motor2.running"});
}

QList<const Parameter *> writableParams()
{
    QList<const Parameter *> out;
    for (const Parameter *p : map().holdings()) {
        if (p->writable())
            out << p;
    }
    return out;
}

ReadBlock block(int firstPlc, int lastPlc)
{
    return {quint16(firstPlc - 40001), quint16(lastPlc - firstPlc + 1)};
}

} // namespace

class TestReadPlanner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void costModelMatchesTheDesignNotes()
    {
        const ReadCostModel m = ReadCostModel::forBaud(9600);
        QVERIFY(qAbs(m.readMs(4) - 64.17) < 0.05); // positions only: about 64 ms
    }

    // The design notes' table: registers, optimum at 9600 and number of reads.
    void knownAnswers_data()
    {
        QTest::addColumn<QString>("what");
        QTest::addColumn<int>("reads");
        QTest::addColumn<double>("optimumMs");
        QTest::newRow("live status") << "status" << 2 << 199.0;
        QTest::newRow("positions only") << "positions" << 1 << 64.0;
        QTest::newRow("every writable parameter") << "writable" << 4 << 359.0;
        QTest::newRow("everything readable") << "all" << 5 << 523.0;
    }
    void knownAnswers()
    {
        QFETCH(QString, what);
        QFETCH(int, reads);
        QFETCH(double, optimumMs);
        QList<const Parameter *> params;
        if (what == QLatin1String("status"))
            params = statusParams();
        else if (what == QLatin1String("positions"))
            params = keys({"motor1.position", "motor2.position"});
        else if (what == QLatin1String("writable"))
            params = writableParams();
        else
            params = map().holdings();
        const ReadCostModel model = ReadCostModel::forBaud(9600);
        const QList<ReadBlock> plan = ReadPlanner::plan(params, 49, model);
        QCOMPARE(plan.size(), reads);
        const double cost = ReadPlanner::costMs(plan, model);
        QVERIFY2(qAbs(cost - optimumMs) < 1.0, qPrintable(QString::number(cost)));
        for (const ReadBlock &b : plan)
            QVERIFY(b.count <= 49);
        // every parameter is covered whole
        for (const Parameter *p : params) {
            const bool covered = std::any_of(plan.cbegin(), plan.cend(), [p](const ReadBlock &b) {
                return p->address >= b.address && p->lastAddress() <= b.lastAddress();
            });
            QVERIFY2(covered, qPrintable(p->key));
        }
    }

    void readAllPlanIsTheOptimum()
    {
        const QList<ReadBlock> plan =
            ReadPlanner::plan(map().holdings(), 49, ReadCostModel::forBaud(9600));
        const QList<ReadBlock> expected{block(40001, 40020), block(40081, 40086),
                                        block(40108, 40150), block(40168, 40213),
                                        block(40300, 40301)};
        QCOMPARE(plan, expected);
    }

    void statusPlan()
    {
        const QList<ReadBlock> plan =
            ReadPlanner::plan(statusParams(), 49, ReadCostModel::forBaud(9600));
        const QList<ReadBlock> expected{block(40108, 40127), block(40148, 40169)};
        QCOMPARE(plan, expected);
    }

    void fasterLinksMergeMore()
    {
        // On TCP a request costs the same whatever its size: fewest reads wins.
        const QList<ReadBlock> tcp =
            ReadPlanner::plan(map().holdings(), 49, ReadCostModel::forBaud(0));
        const QList<ReadBlock> rtu =
            ReadPlanner::plan(map().holdings(), 49, ReadCostModel::forBaud(4800));
        QVERIFY(tcp.size() <= rtu.size());
    }

    void neverSplitsA32BitValue()
    {
        // motor1.pitch is 40007-40008: 40001-40008 is 8 registers, over a limit of 7, and the
        // pitch must not be cut into 40001-40007 + 40008.
        const QList<ReadBlock> plan = ReadPlanner::plan(keys({"motor1.step_angle", "motor1.pitch"}),
                                                        7, ReadCostModel::forBaud(9600));
        QCOMPARE(plan, (QList<ReadBlock>{block(40001, 40001), block(40007, 40008)}));
    }

    void splitsWhenTheGapCostsMore()
    {
        const QList<ReadBlock> plan = ReadPlanner::plan(keys({"motor1.step_angle", "mode.system"}),
                                                        49, ReadCostModel::forBaud(9600));
        QCOMPARE(plan.size(), 2);
    }

    // A controller that refuses reads covering reserved registers: the cheapest plan of only
    // listed registers. Known answers at 9600 baud.
    void gapFreePlans_data()
    {
        QTest::addColumn<QString>("what");
        QTest::addColumn<QList<ReadBlock>>("expected");
        QTest::newRow("live status") << "status"
                                     << QList<ReadBlock>{block(40108, 40111), block(40124, 40127),
                                                         block(40148, 40150), block(40168, 40169)};
        QTest::newRow("everything readable")
            << "all"
            << QList<ReadBlock>{block(40001, 40020), block(40081, 40086), block(40108, 40111),
                                block(40124, 40127), block(40148, 40150), block(40168, 40169),
                                block(40177, 40178), block(40182, 40213), block(40300, 40301)};
    }
    void gapFreePlans()
    {
        QFETCH(QString, what);
        QFETCH(QList<ReadBlock>, expected);
        ReadLimits limits;
        limits.setGapFree(true);
        const QList<const Parameter *> params =
            what == QLatin1String("status") ? statusParams() : map().holdings();
        const QList<ReadBlock> plan =
            ReadPlanner::plan(params, 49, ReadCostModel::forBaud(9600), [&](int first, int last) {
                return limits.mayRead(map(), first, last);
            });
        QCOMPARE(plan, expected);
        for (const ReadBlock &b : plan) {
            for (int a = b.address; a <= b.lastAddress(); ++a)
                QVERIFY2(map().holdingAt(quint16(a)), qPrintable(QString::number(a + 40001)));
        }
    }

    // What one refusal teaches: a gap first, then a lone parameter, else a split to find out.
    void refusalsTeachInOrder()
    {
        ReadLimits limits;
        QCOMPARE(limits.learn(map(), block(40108, 40127)), ReadLimits::Lesson::GapsRefused);
        QVERIFY(limits.gapFree());
        // planned before the lesson: plan again, nothing new learnt
        QCOMPARE(limits.learn(map(), block(40108, 40150)), ReadLimits::Lesson::AlreadyKnown);
        QCOMPARE(limits.learn(map(), block(40108, 40111)), ReadLimits::Lesson::Split);
        QVERIFY(
            !limits.mayRead(map(), block(40108, 40111).address, block(40108, 40111).lastAddress()));
        QString key;
        QCOMPARE(limits.learn(map(), block(40110, 40111), &key), ReadLimits::Lesson::Unsupported);
        QCOMPARE(key, QStringLiteral("motor2.position"));
        QVERIFY(limits.isUnsupported(key));
        QVERIFY(
            limits.mayRead(map(), block(40108, 40109).address, block(40108, 40109).lastAddress()));
    }

    void emptyPlan() { QVERIFY(ReadPlanner::plan({}, 49, ReadCostModel::forBaud(9600)).isEmpty()); }
};

#include "testregistry.h"
STEPCOM_TEST(TestReadPlanner, Guiless)
#include "tst_readplanner.moc"
