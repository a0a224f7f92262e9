#include "map/registermap.h"
#include "profile/profilecomparison.h"
#include "profile/profilefile.h"
#include "testmaps.h"
#include "testpaths.h"

#include <QFile>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

QByteArray read(const QString &relative)
{
    QFile f(sourcePath(relative));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(relative));
    return f.readAll();
}

} // namespace

// Profiles made with another register map (a model with more axes, a firmware variant that
// lacks registers) against the built-in map, and two profile files compared with each other.
class TestProfileVariants : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();
    RegisterMap threeAxis; // "stepper3/1": a third motor, speeds up to 6000 rpm
    RegisterMap lite;      // "stepper2-lite/1": no line interpolation, no home inputs
    Profile machineA;

    // What StepCom running with `other` saves: machine A's values plus `extra` (raw, by key).
    QByteArray savedWith(const RegisterMap &other, const QHash<QString, qint64> &extra = {}) const
    {
        QHash<QString, qint64> raw;
        for (auto it = machineA.values.cbegin(); it != machineA.values.cend(); ++it)
            raw.insert(it.key(), it.value());
        for (auto it = extra.cbegin(); it != extra.cend(); ++it)
            raw.insert(it.key(), it.value());
        return profileSavedWith(other, raw, QStringLiteral("Machine B"));
    }
    // The motor 3 settings of the three-axis profile: motor 2's values.
    QHash<QString, qint64> motor3() const
    {
        QHash<QString, qint64> out;
        for (const Parameter *p : Profile::profileParameters(threeAxis, false)) {
            if (p->instance == 3)
                out.insert(p->key, machineA.values.value(QStringLiteral("motor2.") + p->localKey));
        }
        return out;
    }
    static QStringList keys(const QList<ProfileNote> &notes)
    {
        QStringList out;
        for (const ProfileNote &n : notes)
            out << n.key;
        return out;
    }
    static QStringList keys(const QList<ProfileDifference> &rows)
    {
        QStringList out;
        for (const ProfileDifference &r : rows)
            out << r.parameter->key;
        return out;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStringList errors;
        auto three = threeAxisMap(&errors);
        QVERIFY2(three, qPrintable(errors.join(QLatin1Char('\n'))));
        threeAxis = *three;
        auto variant = liteVariantMap(&errors);
        QVERIFY2(variant, qPrintable(errors.join(QLatin1Char('\n'))));
        lite = *variant;
        machineA =
            *ProfileFile::parse(read(QStringLiteral("tests/core/profile/data/machine-a.json")), map)
                 .profile;
    }

    void anotherMapIsRefusedUnlessAsked()
    {
        const ProfileParseResult r = ProfileFile::parse(savedWith(threeAxis), map);
        QVERIFY(!r.ok());
        QCOMPARE(r.errors, QStringList{QStringLiteral(
                               "the profile is for register map \"stepper3\" version 1, but the "
                               "controller's map is \"stepper2\" version 1")});
    }

    void threeAxisProfileKeepsWhatThisMapKnows()
    {
        const QByteArray json = savedWith(threeAxis, [&] {
            auto extra = motor3();
            extra.insert(QStringLiteral("motor1.speed"), 4500); // fine there, too fast here
            return extra;
        }());
        const ProfileParseResult r = ProfileFile::parse(json, map, ProfileFile::OtherMaps::Accept);
        QVERIFY2(r.ok(), qPrintable(r.errors.join(QLatin1Char('\n'))));
        const Profile &p = *r.profile;
        const ProfileVariance &v = p.variance;
        QVERIFY(v.isVariant());
        QCOMPARE(v.fileMap, QStringLiteral("stepper3/1"));
        QCOMPARE(v.thisMap, QStringLiteral("stepper2/1"));
        QCOMPARE(p.mapId, QStringLiteral("stepper3"));
        QCOMPARE(p.name, QStringLiteral("Machine B"));
        // Every motor 3 setting is unknown here; nothing this map has is missing.
        QStringList motor3Keys = motor3().keys();
        motor3Keys.sort();
        QCOMPARE(keys(v.unknown), motor3Keys);
        QCOMPARE(motor3Keys.size(), 11);
        QCOMPARE(v.unknown.at(0).reason, QStringLiteral("not in register map \"stepper2/1\""));
        QVERIFY(v.missing.isEmpty());
        // The value beyond this map's range is named, and not among the values.
        QCOMPARE(v.rejected.size(), 1);
        QCOMPARE(v.rejected.at(0).key, QStringLiteral("motor1.speed"));
        QCOMPARE(v.rejected.at(0).fileText(), QStringLiteral("4500"));
        QCOMPARE(v.rejected.at(0).reason,
                 QStringLiteral("motor1.speed: 4500 is out of range (1 .. 3000 rpm)"));
        QVERIFY(!p.values.contains(QStringLiteral("motor1.speed")));
        // Every other value is exactly machine A's.
        QMap<QString, qint64> expected = machineA.values;
        expected.remove(QStringLiteral("motor1.speed"));
        QCOMPARE(p.values, expected);

        const QStringList lines = v.describe(map);
        QCOMPARE(v.describeMaps(),
                 QStringLiteral("the profile was made with register map "
                                "\"stepper3/1\"; this map is \"stepper2/1\": only "
                                "the settings both have can be applied"));
        QVERIFY2(lines.contains(QStringLiteral("unknown to this map: motor3.speed = 300 (not in "
                                               "register map \"stepper2/1\")")),
                 qPrintable(lines.join(QLatin1Char('\n'))));
        QVERIFY(lines.contains(QStringLiteral(
            "cannot be applied: motor1.speed: 4500 is out of range (1 .. 3000 rpm)")));
        QCOMPARE(lines.size(), 11 + 1);
    }

    void variantMissingRegistersListsThem()
    {
        const ProfileParseResult r =
            ProfileFile::parse(savedWith(lite), map, ProfileFile::OtherMaps::Accept);
        QVERIFY2(r.ok(), qPrintable(r.errors.join(QLatin1Char('\n'))));
        const ProfileVariance &v = r.profile->variance;
        QCOMPARE(v.fileMap, QStringLiteral("stepper2-lite/1"));
        QVERIFY(v.unknown.isEmpty());
        QVERIFY(v.rejected.isEmpty());
        // In map order, so a person reads them as the pages show them.
        QCOMPARE(v.missing, (QStringList{"motor1.home_input", "motor2.home_input", "line.enabled",
                                         "line.start_x", "line.start_y", "line.end_x", "line.end_y",
                                         "line.speed"}));
        QCOMPARE(r.profile->values.size(), machineA.values.size() - v.missing.size());
        for (auto it = r.profile->values.cbegin(); it != r.profile->values.cend(); ++it)
            QCOMPARE(it.value(), machineA.values.value(it.key()));
        QVERIFY(v.describe(map).contains(QStringLiteral("not in the profile: line.end_x (End X)")));
        QVERIFY(v.describe(map, QStringLiteral("zh_CN"))
                    .contains(QStringLiteral("not in the profile: line.end_x (终点 X)")));
    }

    // A status value or a command of this map, found in another map's profile, is listed too.
    void readOnlyKeysOfAVariantAreListed()
    {
        QByteArray json = savedWith(lite);
        json.replace("\"motor1.speed\": 300", "\"motor1.speed\": 300, \"motor1.position\": 12, "
                                              "\"estop\": 1");
        const ProfileParseResult r = ProfileFile::parse(json, map, ProfileFile::OtherMaps::Accept);
        QVERIFY2(r.ok(), qPrintable(r.errors.join(QLatin1Char('\n'))));
        QCOMPARE(keys(r.profile->variance.unknown), (QStringList{"estop", "motor1.position"}));
        QCOMPARE(r.profile->variance.unknown.at(0).reason,
                 QStringLiteral("a command in register map \"stepper2/1\", not a setting"));
        QCOMPARE(r.profile->variance.unknown.at(1).reason,
                 QStringLiteral("a status value in register map \"stepper2/1\", not a setting"));
    }

    // Another map's profile is still a profile: what is malformed is refused, precisely.
    void malformedVariantsAreStillRefused_data()
    {
        QTest::addColumn<QByteArray>("from");
        QTest::addColumn<QByteArray>("to");
        QTest::addColumn<QString>("message");
        QTest::newRow("text value of an unknown key")
            << QByteArray("\"motor3.speed\": 300") << QByteArray("\"motor3.speed\": \"fast\"")
            << "motor3.speed: expected a number, found a text \"fast\"";
        QTest::newRow("text value of a known key")
            << QByteArray("\"motor1.pitch\": 5") << QByteArray("\"motor1.pitch\": null")
            << "motor1.pitch: expected a number, found null";
        QTest::newRow("a key twice")
            << QByteArray("\"motor3.speed\": 300,")
            << QByteArray("\"motor3.speed\": 300, \"motor3.speed\": 301,")
            << "\"values\": the key \"motor3.speed\" appears more than once";
        QTest::newRow("metadata") << QByteArray("\"name\": \"Machine B\"")
                                  << QByteArray("\"name\": 7")
                                  << "\"metadata\": \"name\" must be a text, found a number";
        QTest::newRow("map version")
            << QByteArray("\"version\": 1") << QByteArray("\"version\": \"1\"")
            << "\"map\": \"version\" must be a whole number, found a text \"1\"";
    }
    void malformedVariantsAreStillRefused()
    {
        QFETCH(QByteArray, from);
        QFETCH(QByteArray, to);
        QFETCH(QString, message);
        QByteArray json = savedWith(threeAxis, motor3());
        QVERIFY2(json.contains(from), json.constData());
        json.replace(from, to);
        const ProfileParseResult r = ProfileFile::parse(json, map, ProfileFile::OtherMaps::Accept);
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.join(QLatin1Char('\n')).contains(message),
                 qPrintable(r.errors.join(QLatin1Char('\n'))));
    }

    // A profile of this very map must fit it exactly, whether other maps are accepted or not.
    void ownMapStaysStrict()
    {
        for (const char *name : {"unknown-key.json", "missing-key.json", "out-of-range.json",
                                 "read-only-key.json", "too-many-decimals.json"}) {
            const QByteArray json =
                read(QStringLiteral("tests/core/profile/corpus/") + QLatin1String(name));
            const ProfileParseResult strict = ProfileFile::parse(json, map);
            const ProfileParseResult r =
                ProfileFile::parse(json, map, ProfileFile::OtherMaps::Accept);
            QVERIFY2(!r.ok(), name);
            QCOMPARE(r.errors, strict.errors);
        }
        const ProfileParseResult good =
            ProfileFile::parse(read(QStringLiteral("tests/core/profile/data/machine-a.json")), map,
                               ProfileFile::OtherMaps::Accept);
        QVERIFY(good.ok());
        QVERIFY(!good.profile->variance.isVariant());
        QVERIFY(good.profile->variance.isEmpty());
    }

    // Opened and saved again, a variant profile loses nothing its own map needs.
    void variantRoundTripKeepsWhatThisMapCannotTake()
    {
        auto extra = motor3();
        extra.insert(QStringLiteral("motor1.speed"), 4500);
        const Profile p =
            *ProfileFile::parse(savedWith(threeAxis, extra), map, ProfileFile::OtherMaps::Accept)
                 .profile;
        const QByteArray json = ProfileFile::toJson(p, map);
        QVERIFY(json.contains("\"id\": \"stepper3\""));
        QVERIFY(json.contains("\"motor3.speed\": 300"));
        QVERIFY(json.contains("\"motor1.speed\": 4500"));
        const ProfileParseResult again =
            ProfileFile::parse(json, map, ProfileFile::OtherMaps::Accept);
        QVERIFY(again.ok());
        QCOMPARE(again.profile->values, p.values);
        QCOMPARE(again.profile->variance, p.variance);
        // And the three-axis map reads it back whole.
        const ProfileParseResult there = ProfileFile::parse(json, threeAxis);
        QVERIFY2(there.ok(), qPrintable(there.errors.join(QLatin1Char('\n'))));
        QCOMPARE(there.profile->values.value(QStringLiteral("motor1.speed")), 4500);
        QCOMPARE(there.profile->values.value(QStringLiteral("motor3.speed")), 300);
    }

    void sameFilesAreIdentical()
    {
        const ProfileComparison c = ProfileComparison::compare(map, machineA, machineA);
        QVERIFY(c.identical());
        QCOMPARE(c.rows.size(), Profile::profileParameters(map, true).size());
        QCOMPARE(c.same().size(), machineA.values.size());
        QVERIFY(c.differing().isEmpty());
        QVERIFY(c.foreign.isEmpty());
    }

    void twoFilesOfThisMap()
    {
        Profile b = machineA;
        b.values[QStringLiteral("motor1.speed")] = 450;
        b.values[QStringLiteral("arc.end_x")] = -100;
        b.values.insert(QStringLiteral("device.id"), 4); // a link setting only B holds
        const ProfileComparison c = ProfileComparison::compare(map, machineA, b);
        QVERIFY(!c.identical());
        QCOMPARE(keys(c.differing()), (QStringList{"motor1.speed", "arc.end_x"}));
        QCOMPARE(*c.differing().at(0).device, 300); // A in the device column
        QCOMPARE(*c.differing().at(0).profile, 450);
        QVERIFY(c.onlyInA().isEmpty());
        QCOMPARE(keys(c.onlyInB()), QStringList{"device.id"});
    }

    void threeGroupsAcrossVariants()
    {
        auto extra = motor3();
        extra.insert(QStringLiteral("motor1.speed"), 4500);
        const Profile three =
            *ProfileFile::parse(savedWith(threeAxis, extra), map, ProfileFile::OtherMaps::Accept)
                 .profile;
        const Profile variant =
            *ProfileFile::parse(savedWith(lite), map, ProfileFile::OtherMaps::Accept).profile;
        const ProfileComparison c = ProfileComparison::compare(map, three, variant);
        QVERIFY(!c.identical());
        QVERIFY(c.differing().isEmpty()); // what both hold is machine A in both
        // A holds the line and the home inputs; B, the lite firmware, lacks them.
        QCOMPARE(keys(c.onlyInA()), variant.variance.missing);
        QVERIFY(c.onlyInB().isEmpty()); // motor1.speed is B's only, but A holds it out of range
        // This map cannot take motor3.* (A only) nor A's motor1.speed: compared as the files hold
        // them.
        QCOMPARE(c.foreign.size(), 12);
        const auto speed = std::find_if(c.foreign.cbegin(), c.foreign.cend(), [](const auto &f) {
            return f.key == QLatin1String("motor1.speed");
        });
        QVERIFY(speed != c.foreign.cend());
        QCOMPARE(speed->a.value_or(-1), 4500.0);
        QCOMPARE(speed->b.value_or(-1), 300.0);
        QCOMPARE(speed->reason,
                 QStringLiteral("motor1.speed: 4500 is out of range (1 .. 3000 rpm)"));
        const auto m3 = std::find_if(c.foreign.cbegin(), c.foreign.cend(), [](const auto &f) {
            return f.key == QLatin1String("motor3.pitch");
        });
        QVERIFY(m3 != c.foreign.cend());
        QCOMPARE(m3->a.value_or(-1), 5.0); // engineering units, as the file holds it
        QVERIFY(!m3->b);
        QCOMPARE(c.foreignDiffering().size(), 12);

        // Two three-axis files that agree: identical, motor 3 included.
        const ProfileComparison same = ProfileComparison::compare(map, three, three);
        QVERIFY(same.identical());
        QCOMPARE(same.foreign.size(), 12);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProfileVariants, Guiless)
#include "tst_profilevariants.moc"
