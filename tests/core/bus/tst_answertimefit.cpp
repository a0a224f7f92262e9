#include "bus/answertimefit.h"

#include <QTest>

using namespace stepcom;

// The controller's own answer time told apart from the wire's, from round trips alone.
class TestAnswerTimeFit : public QObject
{
    Q_OBJECT

    static constexpr double kCharMs9600 = 11.0 / 9600.0 * 1000.0;

    // Round trips of reads of 1..60 registers on a wire at `charMs` with `answerMs` of the
    // controller's own, each with up to `jitterMs` more (a busy computer only ever adds).
    static AnswerTimeFit line(double charMs, double answerMs, double jitterMs = 0)
    {
        AnswerTimeFit fit;
        int turn = 0;
        for (int round = 0; round < 8; ++round) {
            for (int registers : {1, 4, 13, 20, 22, 40, 60}) {
                const int characters = 8 + 5 + 2 * registers + 7;
                const double extra = jitterMs * double((turn++ * 7) % 5) / 4.0;
                fit.add(characters, characters * charMs + answerMs + extra);
            }
        }
        return fit;
    }

private Q_SLOTS:
    void aFastControllerOnAWire_data()
    {
        QTest::addColumn<double>("charMs");
        QTest::addColumn<double>("answerMs");
        for (int baud : {9600, 19200, 38400, 115200}) {
            for (double answer : {0.0, 2.0, 5.0, 15.0, 35.0, 80.0})
                QTest::addRow("%g ms at %d", answer, baud) << 11000.0 / baud << answer;
        }
    }
    void aFastControllerOnAWire()
    {
        QFETCH(double, charMs);
        QFETCH(double, answerMs);
        const AnswerTimeFit fit = line(charMs, answerMs);
        const auto fitted = fit.fit(charMs);
        QVERIFY(fitted);
        QVERIFY2(std::abs(fitted->msPerChar - charMs) < 1e-6,
                 qPrintable(QString::number(fitted->msPerChar)));
        QVERIFY(fit.answerMs(charMs));
        QVERIFY2(std::abs(*fit.answerMs(charMs) - answerMs) < 1e-6,
                 qPrintable(QString::number(*fit.answerMs(charMs))));
    }

    // A busy computer adds to some round trips: the lower quartile of each length keeps the
    // line.
    void jitterDoesNotTipTheLine()
    {
        const AnswerTimeFit fit = line(kCharMs9600, 2.0, 6.0);
        const auto answer = fit.answerMs(kCharMs9600);
        QVERIFY(answer);
        QVERIFY2(*answer >= 2.0 && *answer < 6.0, qPrintable(QString::number(*answer)));
    }

    // A pseudo-terminal has no wire: every length takes the controller's time alone. The fit
    // sees no time per character and tells nothing, so the manual's answer time stays.
    void noWireTellsNothing()
    {
        const AnswerTimeFit fit = line(0.0, 35.0);
        const auto fitted = fit.fit(kCharMs9600);
        QVERIFY(fitted);
        QVERIFY(std::abs(fitted->msPerChar) < 1e-9);
        QVERIFY(!fit.answerMs(kCharMs9600));
        // A wire three times as fast as the baud set (a gateway's buffer, say): not believed.
        QVERIFY(!line(kCharMs9600 / 3, 2.0).answerMs(kCharMs9600));
    }

    // Too little seen: one length, or lengths too close together.
    void tooLittleToTell()
    {
        AnswerTimeFit fit;
        QVERIFY(!fit.answerMs(kCharMs9600));
        fit.add(60, 100.0);
        fit.add(60, 101.0);
        QVERIFY(!fit.answerMs(kCharMs9600));
        fit.add(64, 105.0); // 4 characters apart: 4.6 ms, less than the spread asked
        QVERIFY(!fit.fit(kCharMs9600));
        fit.add(160, 2.0 + 160 * kCharMs9600);
        QVERIFY(fit.fit(kCharMs9600));
        fit.clear();
        QVERIFY(!fit.fit(kCharMs9600));
        // Nonsense is not counted.
        fit.add(0, 10.0);
        fit.add(20, -1.0);
        fit.add(200, 10.0);
        QVERIFY(!fit.fit(kCharMs9600));
    }

    // Only the latest lengths are kept: a plan that stopped using some forgets them.
    void theLatestLengthsAreKept()
    {
        AnswerTimeFit fit;
        for (int characters = 20; characters < 20 + 3 * AnswerTimeFit::kLengths; characters += 3)
            fit.add(characters, 500.0); // an old, slow time
        for (int characters = 100; characters < 100 + 3 * AnswerTimeFit::kLengths; characters += 3)
            fit.add(characters, 2.0 + characters * kCharMs9600);
        QVERIFY(fit.answerMs(kCharMs9600));
        QVERIFY(std::abs(*fit.answerMs(kCharMs9600) - 2.0) < 1e-6);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestAnswerTimeFit, Guiless)
#include "tst_answertimefit.moc"
