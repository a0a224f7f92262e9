#include "map/registermap.h"

#include <QTest>

using namespace stepcom;

class TestParameter : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();
    const Parameter &p(const char *key) { return *map.find(QString::fromLatin1(key)); }

private Q_SLOTS:
    void parse_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("text");
        QTest::addColumn<qint64>("raw");
        QTest::newRow("step angle") << "motor1.step_angle"
                                    << "1.8" << qint64(180);
        QTest::newRow("trailing zeros") << "motor1.step_angle"
                                        << "1.800" << qint64(180);
        QTest::newRow("integer") << "motor1.microsteps"
                                 << "8" << qint64(8);
        QTest::newRow("negative coordinate") << "arc.start_x"
                                             << "-3.25" << qint64(-325);
        QTest::newRow("plus sign") << "arc.end_y"
                                   << "+12.5" << qint64(1250);
        QTest::newRow("enum label") << "motor1.limit_positive"
                                    << "IN2" << qint64(2);
        QTest::newRow("enum label any case") << "motor1.direction"
                                             << "reverse" << qint64(1);
        QTest::newRow("enum chinese") << "motor1.direction"
                                      << "反向" << qint64(1);
        QTest::newRow("enum number") << "device.baud"
                                     << "19200" << qint64(19200);
        QTest::newRow("large distance") << "motor1.move_distance"
                                        << "21474836.47" << qint64(2147483647);
    }
    void parse()
    {
        QFETCH(QString, key);
        QFETCH(QString, text);
        QFETCH(qint64, raw);
        QString error;
        const auto v = map.find(key)->parse(text, &error);
        QVERIFY2(v, qPrintable(error));
        QCOMPARE(*v, raw);
    }

    void parseRejects_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("too many decimals") << "motor1.step_angle"
                                           << "1.234"
                                           << "more than 2 decimal";
        QTest::newRow("decimals on integer") << "motor1.microsteps"
                                             << "8.5"
                                             << "more than 0 decimal";
        QTest::newRow("not a number") << "motor1.speed"
                                      << "fast"
                                      << "'fast' is not a number";
        QTest::newRow("empty") << "motor1.speed"
                               << ""
                               << "no value given";
        QTest::newRow("above range") << "motor1.speed"
                                     << "3001"
                                     << "out of range (1 .. 3000 rpm)";
        QTest::newRow("below range") << "motor1.step_angle"
                                     << "0"
                                     << "out of range";
        QTest::newRow("negative unsigned") << "motor1.pitch"
                                           << "-1"
                                           << "out of range";
        QTest::newRow("not in enum") << "device.baud"
                                     << "115200"
                                     << "is not one of";
        // Regression: IN7 was "not a number"; the allowed names are listed.
        QTest::newRow("unknown choice")
            << "motor1.limit_positive"
            << "IN7"
            << "'IN7' is not one of 0 (None), 1 (IN1), 2 (IN2), 3 (IN3), 4 (IN4)";
        QTest::newRow("huge") << "arc.start_x"
                              << "99999999999999999999"
                              << "far too large";
        QTest::newRow("two points") << "motor1.pitch"
                                    << "1.2.3"
                                    << "is not a number";
    }
    void parseRejects()
    {
        QFETCH(QString, key);
        QFETCH(QString, text);
        QFETCH(QString, message);
        QString error;
        QVERIFY(!map.find(key)->parse(text, &error));
        QVERIFY2(error.contains(message), qPrintable(error));
        QVERIFY2(error.startsWith(key), qPrintable(error)); // names the parameter
    }

    void wordsAreLowFirst_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<qint64>("raw");
        QTest::addColumn<QVector<quint16>>("words");
        QTest::newRow("16 bit") << "motor1.step_angle" << qint64(180) << QVector<quint16>{180};
        QTest::newRow("manual frame 3")
            << "motor1.move_distance" << qint64(200) << QVector<quint16>{0x00C8, 0x0000};
        QTest::newRow("high word")
            << "motor1.pitch" << qint64(0x12345) << QVector<quint16>{0x2345, 0x0001};
        QTest::newRow("negative 32")
            << "motor1.position" << qint64(-2) << QVector<quint16>{0xFFFE, 0xFFFF};
        QTest::newRow("most negative")
            << "arc.start_x" << qint64(-2147483648LL) << QVector<quint16>{0x0000, 0x8000};
        QTest::newRow("negative big")
            << "line.end_y" << qint64(-12345678) << QVector<quint16>{0x9EB2, 0xFF43};
    }
    void wordsAreLowFirst()
    {
        QFETCH(QString, key);
        QFETCH(qint64, raw);
        QFETCH(QVector<quint16>, words);
        const Parameter *param = map.find(key);
        QCOMPARE(param->encode(raw), words);
        QCOMPARE(param->decode(words.constData()), raw); // and back
    }

    void formatting()
    {
        QCOMPARE(p("motor1.step_angle").formatRaw(180), QStringLiteral("1.80"));
        QCOMPARE(p("motor1.position").formatRaw(-5), QStringLiteral("-0.05"));
        QCOMPARE(p("motor1.position").formatRaw(-2147483648LL), QStringLiteral("-21474836.48"));
        QCOMPARE(p("motor1.speed").displayRaw(300), QStringLiteral("300 rpm"));
        QCOMPARE(p("motor1.direction").displayRaw(1), QStringLiteral("Reverse"));
        QCOMPARE(p("motor1.step_angle").registerName(), QStringLiteral("40001 · 0x0000"));
        QCOMPARE(p("estop").registerName(), QStringLiteral("00042 · 0x0029"));
        QCOMPARE(p("mode.system").registerName(), QStringLiteral("40300 · 0x012B"));
    }

    void fromEngineering()
    {
        QString error;
        QCOMPARE(p("motor1.step_angle").fromEngineering(1.8, &error), std::optional<qint64>(180));
        QCOMPARE(p("arc.start_x").fromEngineering(-0.07, &error), std::optional<qint64>(-7));
        QVERIFY(!p("motor1.step_angle").fromEngineering(1.805, &error));
        QVERIFY(error.contains(QStringLiteral("decimal")));
        QVERIFY(!p("motor1.speed").fromEngineering(1e300, &error));
        QVERIFY(
            !p("motor1.speed").fromEngineering(std::numeric_limits<double>::quiet_NaN(), &error));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestParameter, Guiless)
#include "tst_parameter.moc"
