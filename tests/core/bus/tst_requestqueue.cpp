#include "bus/requestqueue.h"

#include <QTest>

using namespace stepcom;

namespace {
QueuedRequest item(quint64 id, Priority p)
{
    QueuedRequest q;
    q.id = id;
    q.request = Request::read(0, 1, p);
    return q;
}
} // namespace

class TestRequestQueue : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void emergencyGoesFirst()
    {
        RequestQueue q;
        q.push(item(1, Priority::Poll));
        q.push(item(2, Priority::Read));
        q.push(item(3, Priority::Command));
        q.push(item(4, Priority::Poll));
        q.push(item(5, Priority::Emergency));
        q.push(item(6, Priority::Command));
        QList<quint64> order;
        while (!q.isEmpty())
            order << q.takeNext().id;
        QCOMPARE(order, (QList<quint64>{5, 3, 6, 2, 1, 4}));
    }

    void retryKeepsItsPlace()
    {
        RequestQueue q;
        q.push(item(1, Priority::Read));
        q.push(item(2, Priority::Read));
        q.pushFront(item(3, Priority::Read));
        q.push(item(4, Priority::Emergency));
        QCOMPARE(q.takeNext().id, quint64(4));
        QCOMPARE(q.takeNext().id, quint64(3));
    }

    void cancelBackgroundWork()
    {
        RequestQueue q;
        q.push(item(1, Priority::Poll));
        q.push(item(2, Priority::Command));
        q.push(item(3, Priority::Read));
        QCOMPARE(q.takeFrom(Priority::Read).size(), 2);
        QCOMPARE(q.size(), 1);
        QCOMPARE(q.count(Priority::Command), 1);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestRequestQueue, Guiless)
#include "tst_requestqueue.moc"
