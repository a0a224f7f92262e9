#include "device/wiringcheck.h"

#include <QTest>

using namespace stepcom;

// One row per kind of suspicious wiring, and clean wirings that must stay quiet.
class TstWiringCheck : public QObject
{
    Q_OBJECT

private:
    static QString kindName(WiringWarning::Kind kind)
    {
        switch (kind) {
        case WiringWarning::Kind::BothLimitsOneInput:
            return QStringLiteral("both");
        case WiringWarning::Kind::InputSharedByMotors:
            return QStringLiteral("shared");
        case WiringWarning::Kind::HomeNotALimit:
            return QStringLiteral("home-not-limit");
        case WiringWarning::Kind::HomeOnPositiveLimit:
            return QStringLiteral("home-positive");
        case WiringWarning::Kind::OneSidedLimits:
            return QStringLiteral("one-sided");
        case WiringWarning::Kind::NoHomeInput:
            return QStringLiteral("no-home");
        case WiringWarning::Kind::LimitIgnoredInMode:
            return QStringLiteral("mode");
        }
        return {};
    }
    static std::optional<int> opt(int v) { return v < 0 ? std::nullopt : std::optional<int>(v); }

private Q_SLOTS:
    void check_data()
    {
        // Motor 1 and motor 2: positive, negative, home (-1 = not known); the system mode.
        QTest::addColumn<QList<int>>("wiring");
        QTest::addColumn<int>("mode");
        QTest::addColumn<QStringList>("kinds");
        QTest::addColumn<QList<int>>("motors");
        QTest::addColumn<QString>("message"); // the first warning's text, exactly

        QTest::newRow("simulator factory wiring is clean")
            << QList<int>{1, 2, 2, 3, 4, 4} << 0 << QStringList() << QList<int>() << QString();
        QTest::newRow("nothing wired (the manual's factory) is clean")
            << QList<int>{0, 0, 0, 0, 0, 0} << 0 << QStringList() << QList<int>() << QString();
        QTest::newRow("round-trip mode keeps the limits")
            << QList<int>{1, 2, 2, 3, 4, 4} << 1 << QStringList() << QList<int>() << QString();
        QTest::newRow("unknown values say nothing")
            << QList<int>{-1, -1, -1, 3, 4, 4} << -1 << QStringList() << QList<int>() << QString();

        QTest::newRow("one input as both limits")
            << QList<int>{2, 2, 2, 3, 4, 4} << 0 << QStringList{"both"} << QList<int>{1}
            << "Motor 1: IN2 is both the positive and the negative limit";
        QTest::newRow("the same input as a limit of two motors")
            << QList<int>{1, 2, 2, 3, 1, 1} << 0 << QStringList{"shared"} << QList<int>{1}
            << "IN1 is wired to more than one motor (motor 1 positive limit, motor 2 negative "
               "limit, motor 2 "
               "home input): its switch acts on all of them";
        QTest::newRow("home input that is no limit")
            << QList<int>{1, 2, 3, 0, 0, 0} << 0 << QStringList{"home-not-limit"} << QList<int>{1}
            << "Motor 1: the home input IN3 is neither of its limits; usually the home input is "
               "the negative "
               "limit (IN2)";
        QTest::newRow("home input on the positive limit")
            << QList<int>{1, 2, 2, 3, 4, 3} << 0 << QStringList{"home-positive"} << QList<int>{2}
            << "Motor 2: the home input IN3 is the positive limit, but homing runs in reverse, "
               "away from it; "
               "use the negative limit's input";
        QTest::newRow("only the negative limit")
            << QList<int>{0, 2, 2, 3, 4, 4} << 0 << QStringList{"one-sided"} << QList<int>{1}
            << "Motor 1: only the negative limit is set (IN2); nothing stops the motor at the "
               "positive end";
        QTest::newRow("only the positive limit")
            << QList<int>{1, 2, 2, 3, 0, 3} << 0 << QStringList{"one-sided", "home-positive"}
            << QList<int>{2, 2}
            << "Motor 2: only the positive limit is set (IN3); nothing stops the motor at the "
               "negative end";
        QTest::newRow("limits without a home input")
            << QList<int>{1, 2, 0, 3, 4, 4} << 0 << QStringList{"no-home"} << QList<int>{1}
            << "Motor 1: no home input; homing runs in reverse until the negative limit or a stop "
               "and does "
               "not zero the position";
        QTest::newRow("single-trigger mode ignores the limits")
            << QList<int>{1, 2, 2, 0, 0, 0} << 2 << QStringList{"mode", "mode"} << QList<int>{1, 1}
            << "Motor 1: IN1 is set as the positive limit, but system mode 2 (single trigger) "
               "ignores the limit "
               "settings and uses IN1 to start motor 1";
        QTest::newRow("hold-to-jog mode, motor 2's limits")
            << QList<int>{0, 0, 0, 3, 4, 4} << 4 << QStringList{"mode", "mode"} << QList<int>{2, 2}
            << "Motor 2: IN3 is set as the positive limit, but system mode 4 (hold-to-jog) ignores "
               "the limit "
               "settings and uses IN3 as motor 1's positive limit";
    }
    void check()
    {
        QFETCH(QList<int>, wiring);
        QFETCH(int, mode);
        QFETCH(QStringList, kinds);
        QFETCH(QList<int>, motors);
        QFETCH(QString, message);
        QList<MotorWiring> in;
        for (int m = 0; m < 2; ++m) {
            MotorWiring w;
            w.motor = m + 1;
            w.positive = opt(wiring.at(m * 3));
            w.negative = opt(wiring.at(m * 3 + 1));
            w.home = opt(wiring.at(m * 3 + 2));
            in << w;
        }
        const QList<WiringWarning> out = checkWiring(in, opt(mode));
        QStringList gotKinds;
        QList<int> gotMotors;
        for (const WiringWarning &w : out) {
            gotKinds << kindName(w.kind);
            gotMotors << w.motor;
        }
        QCOMPARE(gotKinds, kinds);
        QCOMPARE(gotMotors, motors);
        if (!message.isEmpty())
            QCOMPARE(out.first().message, message);
    }

    void severities()
    {
        const QList<MotorWiring> both = {{1, 2, 2, 2}};
        QCOMPARE(checkWiring(both, 0).first().severity, WiringWarning::Severity::Error);
        const QList<MotorWiring> noHome = {{1, 1, 2, 0}};
        QCOMPARE(checkWiring(noHome, 0).first().severity, WiringWarning::Severity::Info);
        QCOMPARE(inputName(0), QStringLiteral("none"));
        QCOMPARE(inputName(4), QStringLiteral("IN4"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstWiringCheck, Guiless)
#include "tst_wiringcheck.moc"
