// EstopConfirmation frame by frame, on its own clock: the E-STOP's copies past an adapter's
// echo, the echo learnt when the option is off, the motion state read back deciding the
// verdict (an axis still running sends the E-STOP again), and the other master's answer never
// taken for the read's.
#include "listen/estopconfirmation.h"
#include "listenframes.h"
#include "map/registermap.h"

#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

const QByteArray kStop = rtu("01 05 00 29 FF 00");
const QByteArray kRunningRead = rtu("01 03 00 A7 00 02");
const QByteArray kStopped = rtu("01 03 04 00 00 00 00");
const QByteArray kMotor2Running = rtu("01 03 04 00 00 00 01");

// Sends what is due at `ms` and says what it was ("" for nothing).
QByteArray step(EstopConfirmation &c, qint64 ms)
{
    const QByteArray f = c.due(ms);
    if (!f.isEmpty())
        c.sent(ms);
    return f;
}

bool hear(EstopConfirmation &c, const QByteArray &bytes, qint64 ms,
          const QByteArray &otherRequest = {})
{
    return c.heard(HeardFrame{bytes, ms}, otherRequest);
}

} // namespace

class TestEstopConfirmation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void frames()
    {
        const EstopConfirmation c(RegisterMap::builtin(), 1, false);
        QVERIFY(c.isValid());
        QCOMPARE(c.stopFrame(), kStop);        // coil 00042, all motors and outputs
        QCOMPARE(c.readFrame(), kRunningRead); // 40168-40169, motor 1-2 running
    }

    // The echo option on: the first copy is the echo; the second is the controller's answer.
    void echoThenAnswer()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, true);
        c.start();
        QCOMPARE(step(c, 0), kStop);
        QVERIFY(hear(c, kStop, 2));
        QVERIFY(hear(c, kStop, 40));
        QCOMPARE(step(c, 100), QByteArray()); // its answer may still come
        QCOMPARE(step(c, 400), kRunningRead);
        QVERIFY(hear(c, kRunningRead, 402)); // the read's echo
        QVERIFY(hear(c, kStopped, 440));
        QCOMPARE(c.verdict(), EstopConfirmation::Verdict::Acknowledged);
        QCOMPARE(c.text(),
                 QStringLiteral("E-STOP acknowledged by controller 1: both axes stopped"));
        QVERIFY(!c.takeEchoLearned()); // the option said so already
        QVERIFY(!c.isActive());
    }

    // The option on and the controller silent: only the echo, every try; never acknowledged.
    void onlyTheEcho()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, true);
        c.start();
        qint64 ms = 0;
        int stops = 0;
        int reads = 0;
        while (c.isActive() && ms < 60000) {
            const QByteArray f = step(c, ms);
            stops += f == kStop ? 1 : 0;
            reads += f == kRunningRead ? 1 : 0;
            if (!f.isEmpty())
                QVERIFY(hear(c, f, ms + 1));
            ms += 50;
        }
        QCOMPARE(c.verdict(), EstopConfirmation::Verdict::NotAcknowledged);
        QVERIFY2(c.text().contains(u"only our own echo heard"), qPrintable(c.text()));
        QCOMPARE(stops, EstopConfirmation::kSendTries);
        QCOMPARE(reads, 1); // the read showed the copy was the echo; no more reads after
    }

    // The option off, the adapter echoing: a copy that looked like the answer, then the read
    // came back as sent -- the echo, said once; the E-STOP goes again and its second copy is
    // the controller's.
    void echoLearntFromTheRead()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, false);
        c.start();
        QCOMPARE(step(c, 0), kStop);
        QVERIFY(hear(c, kStop, 1)); // the echo; the controller did not hear it (a collision)
        QCOMPARE(step(c, 300), kRunningRead);
        QVERIFY(hear(c, kRunningRead, 301));
        QVERIFY(c.takeEchoLearned());
        QVERIFY(!c.takeEchoLearned());   // once
        QVERIFY(hear(c, kStopped, 330)); // read answered, but the E-STOP was only echoed
        QVERIFY(c.isActive());
        QCOMPARE(step(c, 331), kStop);
        QVERIFY(hear(c, kStop, 332));
        QVERIFY(hear(c, kStop, 370));
        QCOMPARE(step(c, 700), kRunningRead);
        QVERIFY(hear(c, kRunningRead, 701));
        QVERIFY(hear(c, kStopped, 730));
        QCOMPARE(c.verdict(), EstopConfirmation::Verdict::Acknowledged);
    }

    // The option off, one E-STOP coming back twice: the adapter echoes.
    void echoLearntFromTwoCopies()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, false);
        c.start();
        QCOMPARE(step(c, 0), kStop);
        QVERIFY(hear(c, kStop, 1));
        QVERIFY(!c.takeEchoLearned());
        QVERIFY(hear(c, kStop, 40));
        QVERIFY(c.takeEchoLearned());
        QVERIFY(c.echoes());
    }

    // The option on, but no echo: the read answered with no copy first shows the one copy was
    // the controller's answer.
    void optionOnWithoutEcho()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, true);
        c.start();
        QCOMPARE(step(c, 0), kStop);
        QVERIFY(hear(c, kStop, 30));
        QCOMPARE(step(c, 300), kRunningRead);
        QVERIFY(hear(c, kStopped, 330));
        QCOMPARE(c.verdict(), EstopConfirmation::Verdict::Acknowledged);
        QVERIFY(!c.echoes());
    }

    // An axis still running: the E-STOP again, and read back again; running every time, not
    // acknowledged, and the motor said.
    void stillRunning()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, false);
        c.start();
        qint64 ms = 0;
        int stops = 0;
        while (c.isActive() && ms < 60000) {
            const QByteArray f = step(c, ms);
            if (f == kStop) {
                ++stops;
                QVERIFY(hear(c, kStop, ms + 20));
            } else if (f == kRunningRead) {
                QVERIFY(hear(c, kMotor2Running, ms + 20));
            }
            ms += 50;
        }
        QCOMPARE(c.verdict(), EstopConfirmation::Verdict::NotAcknowledged);
        QCOMPARE(stops, EstopConfirmation::kSendTries);
        QVERIFY2(c.text().contains(u"motor 2 still running"), qPrintable(c.text()));
    }

    // The other master's read waiting: an answer that fits it is its, not the read's.
    void theOtherMastersAnswer()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, false);
        c.start();
        QCOMPARE(step(c, 0), kStop);
        QVERIFY(hear(c, kStop, 20));
        QCOMPARE(step(c, 300), kRunningRead);
        const QByteArray plcRead = rtu("01 03 00 6B 00 02");
        QVERIFY(!hear(c, kStopped, 320, plcRead));
        QVERIFY(c.isActive());
        QVERIFY(!hear(c, rtu("01 03 08 00 00 00 00 00 00 00 00"), 330)); // no fit for the read
        QVERIFY(!hear(c, rtu("02 03 04 00 00 00 00"), 340));             // another id
        QVERIFY(hear(c, kStopped, 350, rtu("01 03 00 00 00 0A")));
        QCOMPARE(c.verdict(), EstopConfirmation::Verdict::Acknowledged);
    }

    // Nobody answers and nothing comes back: never answered, after every try.
    void silence()
    {
        EstopConfirmation c(RegisterMap::builtin(), 1, false);
        c.start();
        qint64 ms = 0;
        while (c.isActive() && ms < 60000) {
            QVERIFY(step(c, ms) != kRunningRead);
            ms += 50;
        }
        QVERIFY2(c.text().contains(u"controller 1 never answered it"), qPrintable(c.text()));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestEstopConfirmation, Guiless)
#include "tst_estopconfirmation.moc"
