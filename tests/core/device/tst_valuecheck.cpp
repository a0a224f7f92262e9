#include "device/valuecheck.h"
#include "i18n/translators.h"
#include "map/registermap.h"

#include <QTest>

using namespace stepcom;

// A refused value is explained for the person at the field: label, range, unit, no key.
class TstValueCheck : public QObject
{
    Q_OBJECT
    Translators m_translators;

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_translators.install(QStringLiteral("en"))); }
    void explains_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<int>("problem");
        QTest::addColumn<QString>("text");
        QTest::newRow("ok") << "motor1.speed"
                            << "300" << int(ValueCheck::Problem::None) << "";
        QTest::newRow("too big") << "motor1.speed"
                                 << "9999" << int(ValueCheck::Problem::OutOfRange)
                                 << "Speed: 9999 is outside the allowed range 1 – 3000 rpm.";
        QTest::newRow("negative") << "motor1.speed"
                                  << "-100" << int(ValueCheck::Problem::OutOfRange)
                                  << "Speed: -100 is outside the allowed range 1 – 3000 rpm.";
        QTest::newRow("text") << "motor1.speed"
                              << "abc" << int(ValueCheck::Problem::NotANumber)
                              << "Speed: “abc” is not a number. Allowed: 1 – 3000 rpm.";
        QTest::newRow("decimals") << "motor1.pitch"
                                  << "5.125" << int(ValueCheck::Problem::TooManyDecimals)
                                  << "Pitch: at most 2 decimals. Allowed: 0.01 – 21474836.47 mm.";
        QTest::newRow("empty") << "motor1.speed"
                               << "  " << int(ValueCheck::Problem::Empty)
                               << "Speed: enter a value (1 – 3000 rpm).";
        QTest::newRow("choice") << "motor1.direction"
                                << "sideways" << int(ValueCheck::Problem::NotAChoice)
                                << "Direction: “sideways” is not one of Forward, Reverse.";
    }
    void explains()
    {
        QFETCH(QString, key);
        QFETCH(QString, typed);
        QFETCH(int, problem);
        QFETCH(QString, text);
        const Parameter *p = RegisterMap::builtin().find(key);
        QVERIFY(p);
        ValueCheck::Problem found = ValueCheck::Problem::Empty;
        const auto raw = ValueCheck::check(*p, typed, &found);
        QCOMPARE(int(found), problem);
        QCOMPARE(raw.has_value(), problem == int(ValueCheck::Problem::None));
        QCOMPARE(ValueCheck::text(*p, found, typed), text);
        QVERIFY(!ValueCheck::text(*p, found, typed).contains(key));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstValueCheck, Guiless)
#include "tst_valuecheck.moc"
