#include "map/registermap.h"
#include "motion/travellimits.h"
#include "profile/profilefile.h"
#include "testpaths.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

#include <cmath>

using namespace stepcom;
using namespace stepcom::test;

Q_DECLARE_METATYPE(stepcom::OverrunInputs)

namespace {

const RegisterMap &map()
{
    return RegisterMap::builtin();
}

// Motor 1 may travel 0 .. 200 mm; motor 2 only has a max at 150.
TravelLimits limits()
{
    TravelLimits l;
    if (!l.setAxis(map(), 1, 0.0, 200.0).isEmpty() ||
        !l.setAxis(map(), 2, std::nullopt, 150.0).isEmpty())
        qFatal("limits");
    return l;
}

QByteArray machineA()
{
    QFile f(sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json")));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("no machine-a.json");
    return f.readAll();
}

QByteArray withStepcom(const QJsonValue &stepcom, int schema = 2)
{
    QJsonObject o = QJsonDocument::fromJson(machineA()).object();
    o.insert("schema", schema);
    o.insert("stepcom", stepcom);
    return QJsonDocument(o).toJson();
}

} // namespace

// Software travel limits: refusing targets, stopping jogs, the overrun, and the profile.
class TestTravelLimits : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void settingAnAxisIsChecked_data()
    {
        QTest::addColumn<double>("min");
        QTest::addColumn<double>("max");
        QTest::addColumn<QString>("message");
        QTest::newRow("ok") << -10.5 << 300.25 << "";
        QTest::newRow("min above max")
            << 200.0 << 100.0
            << "the software travel limit min (200.00 mm) must be below max (100.00 mm)";
        QTest::newRow("equal") << 5.0 << 5.0 << "must be below max";
        QTest::newRow("decimals") << 0.005 << 100.0
                                  << "motor 1, software travel limit min: motor1.position: 0.005";
        QTest::newRow("beyond the register")
            << 0.0 << 3.0e7 << "motor 1, software travel limit max: ";
        QTest::newRow("not finite") << 0.0 << double(INFINITY) << "not a finite number";
    }
    void settingAnAxisIsChecked()
    {
        QFETCH(double, min);
        QFETCH(double, max);
        QFETCH(QString, message);
        TravelLimits l = limits();
        const TravelLimits before = l;
        const QString why = l.setAxis(map(), 1, min, max);
        if (message.isEmpty()) {
            QCOMPARE(why, QString());
            QCOMPARE(l.axis(1).min, std::optional<qint64>(qint64(std::llround(min * 100))));
            return;
        }
        QVERIFY2(why.contains(message), qPrintable(why));
        QVERIFY(l == before);
        QVERIFY(
            l.setAxis(map(), 3, 0.0, 1.0).contains("motor 3: this register map has no such axis"));
    }

    void targets_data()
    {
        QTest::addColumn<int>("motor");
        QTest::addColumn<double>("current");
        QTest::addColumn<double>("target");
        QTest::addColumn<QString>("refusal");
        QTest::newRow("inside") << 1 << 50.0 << 150.0 << "";
        QTest::newRow("onto max") << 1 << 50.0 << 200.0 << "";
        QTest::newRow("steps summing to max") << 1 << 199.9 << 199.9 + 0.1 << "";
        QTest::newRow("past max")
            << 1 << 50.0 << 200.01
            << "motor 1: 200.01 mm is beyond the software travel limit max 200.00 mm";
        QTest::newRow("past min")
            << 1 << 50.0 << -0.01
            << "motor 1: -0.01 mm is beyond the software travel limit min 0.00 mm";
        QTest::newRow("back in from outside") << 1 << 250.0 << 240.0 << "";
        QTest::newRow("further out")
            << 1 << 250.0 << 260.0 << "beyond the software travel limit max";
        QTest::newRow("below min, back") << 1 << -5.0 << -1.0 << "";
        QTest::newRow("below min, further")
            << 1 << -5.0 << -6.0 << "beyond the software travel limit min";
        QTest::newRow("open min") << 2 << 0.0 << -1000.0 << "";
        QTest::newRow("motor 2 max") << 2 << 0.0 << 150.5 << "max 150.00 mm";
        QTest::newRow("not a position") << 1 << 0.0 << double(NAN) << "is not a position";
    }
    void targets()
    {
        QFETCH(int, motor);
        QFETCH(double, current);
        QFETCH(double, target);
        QFETCH(QString, refusal);
        const QString why = limits().refuseTarget(map(), motor, current, target);
        if (refusal.isEmpty())
            QCOMPARE(why, QString());
        else
            QVERIFY2(why.contains(refusal), qPrintable(why));
        QCOMPARE(TravelLimits().refuseTarget(map(), motor, current, 1e6), QString()); // no limits
    }

    void jogs_data()
    {
        QTest::addColumn<bool>("positive");
        QTest::addColumn<double>("position");
        QTest::addColumn<bool>("mayStart");
        QTest::addColumn<bool>("mustStop");
        QTest::newRow("+ inside") << true << 100.0 << true << false;
        QTest::newRow("+ just before") << true << 199.99 << true << false;
        QTest::newRow("+ at max") << true << 200.0 << false << true;
        QTest::newRow("+ past max") << true << 208.1 << false << true;
        QTest::newRow("- at max") << false << 200.0 << true << false;
        QTest::newRow("- at min") << false << 0.0 << false << true;
        QTest::newRow("- past min") << false << -3.0 << false << true;
        QTest::newRow("+ below min") << true << -3.0 << true << false;
    }
    void jogs()
    {
        QFETCH(bool, positive);
        QFETCH(double, position);
        QFETCH(bool, mayStart);
        QFETCH(bool, mustStop);
        const TravelLimits l = limits();
        QCOMPARE(l.refuseJog(map(), 1, positive, position).isEmpty(), mayStart);
        const QString stop = l.crossed(map(), 1, positive, position);
        QCOMPARE(!stop.isEmpty(), mustStop);
        if (mustStop)
            QVERIFY2(stop.contains(positive ? "reached its software travel limit max 200.00 mm"
                                            : "reached its software travel limit min 0.00 mm"),
                     qPrintable(stop));
    }

    void overrun_data()
    {
        QTest::addColumn<OverrunInputs>("in");
        QTest::addColumn<double>("reactionMs");
        QTest::addColumn<double>("distance");
        // 300 rpm on a 5 mm pitch = 25 mm/s; poll every 200 ms, positions read in 64 ms at 9600,
        // the stop 60 ms: 324 ms, 8.1 mm.
        QTest::newRow("9600, 5 Hz poll") << OverrunInputs{25, 200, 64, 60, 0, 0} << 324.0 << 8.1;
        // A stop that waits for a full live-status read (199 ms) in flight.
        QTest::newRow("stop behind a read")
            << OverrunInputs{25, 200, 64, 60 + 199, 0, 0} << 523.0 << 13.075;
        // A drive that ramps down 95 ms from 25 to 1.25 mm/s adds (25 + 1.25) / 2 × 0.095.
        QTest::newRow("with a ramp down")
            << OverrunInputs{25, 200, 64, 60, 95, 1.25} << 324.0 << 8.1 + 1.246875;
        QTest::newRow("slow jog") << OverrunInputs{1, 100, 30, 40, 0, 0} << 170.0 << 0.17;
        QTest::newRow("nonsense is zero")
            << OverrunInputs{-5, double(NAN), -1, 0, 0, 0} << 0.0 << 0.0;
    }
    void overrun()
    {
        QFETCH(OverrunInputs, in);
        QFETCH(double, reactionMs);
        QFETCH(double, distance);
        const OverrunEstimate e = TravelLimits::overrun(in);
        QCOMPARE(e.reactionMs, reactionMs);
        QVERIFY2(std::fabs(e.distance - distance) < 1e-9,
                 qPrintable(QString::number(e.distance, 'g', 17)));
        QCOMPARE(
            TravelLimits::describeOverrun({25, 200, 64, 60, 0, 0}, "mm"),
            QStringLiteral("up to 8.10 mm beyond a software limit at 25.00 mm/s (reaction 324 ms: "
                           "poll 200 ms, read 64 ms, stop 60 ms)"));
    }

    void profileKeepsTheLimits()
    {
        ProfileParseResult r = ProfileFile::parse(machineA(), map());
        QVERIFY(r.ok());
        QVERIFY(r.profile->travelLimits.isEmpty()); // an old file: no limits
        // Without StepCom settings a profile is still written as schema 1, with no "stepcom".
        QJsonObject saved =
            QJsonDocument::fromJson(ProfileFile::toJson(*r.profile, map())).object();
        QCOMPARE(saved.value("schema").toInt(), 1);
        QVERIFY(!saved.contains("stepcom"));

        Profile p = *r.profile;
        p.travelLimits = limits();
        const QByteArray bytes = ProfileFile::toJson(p, map());
        saved = QJsonDocument::fromJson(bytes).object();
        QCOMPARE(saved.value("schema").toInt(), 2);
        QCOMPARE(saved.value("stepcom").toObject().value("travelLimits").toObject(),
                 QJsonObject({{"motor1", QJsonObject{{"min", 0}, {"max", 200}}},
                              {"motor2", QJsonObject{{"max", 150}}}}));
        r = ProfileFile::parse(bytes, map());
        QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
        QVERIFY(r.profile->travelLimits == limits());
        QCOMPARE(r.profile->values, p.values);
    }

    void badLimitsInAProfile_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("message");
        auto limit = [](const QJsonValue &v) {
            return withStepcom(QJsonObject{{"travelLimits", v}});
        };
        QTest::newRow("schema 1 knows no stepcom")
            << withStepcom(QJsonObject{{"travelLimits", QJsonObject{}}}, 1)
            << "unknown field \"stepcom\"";
        QTest::newRow("not an object")
            << withStepcom(5) << "\"stepcom\" must be an object, found a number";
        QTest::newRow("unknown setting")
            << withStepcom(QJsonObject{{"speedLimit", 1}})
            << "\"stepcom\": unknown field \"speedLimit\" (allowed: travelLimits)";
        QTest::newRow("list") << limit(QJsonArray{}) << "\"travelLimits\" must be an object";
        QTest::newRow("unknown axis")
            << limit(QJsonObject{{"motor3", QJsonObject{{"max", 1}}}})
            << "\"travelLimits\": unknown axis \"motor3\" (this map has motor1 .. motor2)";
        QTest::newRow("axis 01") << limit(QJsonObject{{"motor01", QJsonObject{{"max", 1}}}})
                                 << "unknown axis \"motor01\"";
        QTest::newRow("unknown end") << limit(QJsonObject{{"motor1", QJsonObject{{"top", 1}}}})
                                     << "\"motor1\": unknown field \"top\" (allowed: min, max)";
        QTest::newRow("text") << limit(QJsonObject{{"motor1", QJsonObject{{"max", "200"}}}})
                              << "\"motor1\": \"max\" must be a number";
        QTest::newRow("empty axis") << limit(QJsonObject{{"motor1", QJsonObject{}}})
                                    << "\"motor1\" sets neither min nor max";
        QTest::newRow("min above max")
            << limit(QJsonObject{{"motor1", QJsonObject{{"min", 9}, {"max", 1}}}})
            << "motor 1: the software travel limit min (9.00 mm) must be below max (1.00 mm)";
        QTest::newRow("decimals") << limit(QJsonObject{{"motor2", QJsonObject{{"max", 1.001}}}})
                                  << "has more than 2 decimal(s)";
    }
    void badLimitsInAProfile()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, message);
        const ProfileParseResult r = ProfileFile::parse(bytes, map());
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.join('\n').contains(message), qPrintable(r.errors.join('\n')));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestTravelLimits, Guiless)
#include "tst_travellimits.moc"
