#include "map/registermap.h"
#include "profile/profilediff.h"
#include "profile/profilefile.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

// The profile file format: what it accepts, and a clear message for everything it does not.
class TestProfileFile : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();

    static QByteArray read(const QString &relative)
    {
        QFile f(sourcePath(relative));
        if (!f.open(QIODevice::ReadOnly))
            qFatal("cannot read %s", qPrintable(relative));
        return f.readAll();
    }
    QByteArray good() const
    {
        return read(QStringLiteral("tests/core/profile/data/machine-a.json"));
    }

private Q_SLOTS:
    void theMapHasAnIdentity()
    {
        QCOMPARE(map.id(), QStringLiteral("stepper2"));
        QCOMPARE(map.version(), 1);
        QCOMPARE(map.identity(), QStringLiteral("stepper2/1"));
    }

    void readsAGoodProfile()
    {
        const ProfileParseResult r = ProfileFile::parse(good(), map);
        QVERIFY2(r.ok(), qPrintable(r.errors.join(QLatin1Char('\n'))));
        const Profile &p = *r.profile;
        QCOMPARE(p.name, QStringLiteral("Machine A"));
        QCOMPARE(p.notes, QStringLiteral("XY table, lead screws 5 mm"));
        QCOMPARE(p.created, QDateTime(QDate(2024, 5, 31), QTime(14, 2), Qt::UTC));
        QCOMPARE(p.deviceId, 1);
        QCOMPARE(p.baud, 9600);
        QCOMPARE(p.values.size(), Profile::profileParameters(map, false).size());
        QCOMPARE(p.values.value(QStringLiteral("motor1.step_angle")), 180); // 1.8 exactly
        QCOMPARE(p.values.value(QStringLiteral("motor2.pitch")), 500);
        QCOMPARE(p.values.value(QStringLiteral("line.end_y")), 1000);
        QVERIFY(!p.values.contains(QStringLiteral("device.id"))); // optional, absent here
    }

    void roundTripKeepsEverything()
    {
        Profile p = *ProfileFile::parse(good(), map).profile;
        p.values.insert(QStringLiteral("arc.start_x"), -123456); // -1234.56, 32-bit signed
        p.values.insert(QStringLiteral("device.id"), 7);
        p.values.insert(QStringLiteral("device.baud"), 19200);
        p.notes = QStringLiteral("第二台机器\nline two");
        const QByteArray json = ProfileFile::toJson(p, map);
        const ProfileParseResult again = ProfileFile::parse(json, map);
        QVERIFY2(again.ok(), qPrintable(again.errors.join(QLatin1Char('\n'))));
        QCOMPARE(again.profile->values, p.values);
        QCOMPARE(again.profile->notes, p.notes);
        QCOMPARE(again.profile->created, p.created);
        QVERIFY(json.contains("\"arc.start_x\": -1234.56"));
        QVERIFY(json.contains("\"motor1.step_angle\": 1.8"));
    }

    void saveIsAtomicAndLoadNamesTheFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.json"));
        const Profile p = *ProfileFile::parse(good(), map).profile;
        QCOMPARE(ProfileFile::save(path, p, map), QString());
        const ProfileParseResult loaded = ProfileFile::load(path, map);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.profile->values, p.values);
        // No temporary left behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("a.json")});

        const QString bad = dir.filePath(QStringLiteral("missing-dir/b.json"));
        const QString error = ProfileFile::save(bad, p, map);
        QVERIFY2(error.contains(bad), qPrintable(error));
        QVERIFY(!QFile::exists(bad));

        const ProfileParseResult none =
            ProfileFile::load(dir.filePath(QStringLiteral("x.json")), map);
        QVERIFY(!none.ok());
        QVERIFY2(none.errors.value(0).contains(QStringLiteral("no such file")),
                 qPrintable(none.errors.value(0)));

        QFile broken(dir.filePath(QStringLiteral("broken.json")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{\n  \"format\": \"stepcom-profile\",\n  \"schema\": 1,\n  oops\n}\n");
        broken.close();
        const ProfileParseResult b = ProfileFile::load(broken.fileName(), map);
        QVERIFY(!b.ok());
        QVERIFY2(b.errors.value(0).startsWith(QStringLiteral("broken.json: not valid JSON at "
                                                             "line 4, column 3: ")),
                 qPrintable(b.errors.value(0)));
    }

    void lineAndColumn_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("offset");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::newRow("start") << QByteArray("abc") << 0 << 1 << 1;
        QTest::newRow("first line") << QByteArray("abc") << 2 << 1 << 3;
        QTest::newRow("second line") << QByteArray("ab\ncd") << 4 << 2 << 2;
        QTest::newRow("after newline") << QByteArray("ab\n") << 3 << 2 << 1;
        QTest::newRow("utf-8 counts characters")
            << QByteArray("{\"名称\": x") << 11 << 1 << 8; // 名 and 称 are 3 bytes each
        QTest::newRow("beyond the end") << QByteArray("a\nb") << 99 << 2 << 2;
        QTest::newRow("negative") << QByteArray("a\nb") << -5 << 1 << 1;
    }
    void lineAndColumn()
    {
        QFETCH(QByteArray, text);
        QFETCH(int, offset);
        QFETCH(int, line);
        QFETCH(int, column);
        int l = 0;
        int c = 0;
        ProfileFile::lineColumn(text, offset, &l, &c);
        QCOMPARE(l, line);
        QCOMPARE(c, column);
    }

    // Every file of tests/core/profile/corpus is a broken profile with the message it must give.
    void corpus_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("expected");
        const QByteArray table = read(QStringLiteral("tests/core/profile/corpus/expected.tsv"));
        QHash<QString, QString> expected;
        for (const QByteArray &line : table.split('\n')) {
            if (line.isEmpty() || line.startsWith('#'))
                continue;
            const QList<QByteArray> cells = line.split('\t');
            QCOMPARE(cells.size(), 2);
            expected.insert(QString::fromUtf8(cells.at(0)), QString::fromUtf8(cells.at(1)));
        }
        const QDir dir(sourcePath(QStringLiteral("tests/core/profile/corpus")));
        const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files);
        QVERIFY(files.size() >= 30);
        for (const QString &f : files) {
            QVERIFY2(expected.contains(f), qPrintable(f + QStringLiteral(" has no line in "
                                                                         "expected.tsv")));
            QTest::newRow(qPrintable(f)) << dir.filePath(f) << expected.value(f);
        }
        QCOMPARE(expected.size(), files.size()); // no stale lines either
    }
    void corpus()
    {
        QFETCH(QString, file);
        QFETCH(QString, expected);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const ProfileParseResult r = ProfileFile::parse(f.readAll(), map);
        QVERIFY(!r.ok());
        QVERIFY(!r.errors.isEmpty());
        const QString all = r.errors.join(QLatin1Char('\n'));
        QVERIFY2(all.contains(expected), qPrintable(all));
        QVERIFY(r.errors.size() <= ProfileFile::MaxErrors + 1);

        // Accepting profiles of other maps (stepcomctl does) changes nothing for a broken file
        // or a file of this map; only the two files of another map open, as variants that hold
        // every setting of this map.
        f.seek(0);
        const ProfileParseResult lenient =
            ProfileFile::parse(f.readAll(), map, ProfileFile::OtherMaps::Accept);
        const QString name = QFileInfo(file).fileName();
        if (name == QLatin1String("other-map.json") ||
            name == QLatin1String("other-map-version.json")) {
            QVERIFY2(lenient.ok(), qPrintable(lenient.errors.join(QLatin1Char('\n'))));
            QCOMPARE(lenient.profile->variance.fileMap, name == QLatin1String("other-map.json")
                                                            ? QStringLiteral("stepper5/1")
                                                            : QStringLiteral("stepper2/7"));
            QVERIFY(lenient.profile->variance.isEmpty());
            QCOMPARE(lenient.profile->values.size(), Profile::profileParameters(map, false).size());
        } else {
            QCOMPARE(lenient.errors, r.errors);
        }
    }

    void linkSettingsAreOptionalButChecked()
    {
        QByteArray json = good();
        json.replace("\"mode.round_trips\": 0", "\"mode.round_trips\": 0, \"device.id\": 9, "
                                                "\"device.baud\": 38400");
        const ProfileParseResult r = ProfileFile::parse(json, map);
        QVERIFY2(r.ok(), qPrintable(r.errors.join(QLatin1Char('\n'))));
        QCOMPARE(r.profile->values.value(QStringLiteral("device.id")), 9);
        QCOMPARE(r.profile->values.value(QStringLiteral("device.baud")), 38400);
        json.replace("\"device.id\": 9", "\"device.id\": 256");
        json.replace("\"device.baud\": 38400", "\"device.baud\": 115200");
        const ProfileParseResult bad = ProfileFile::parse(json, map);
        QVERIFY(!bad.ok());
        QCOMPARE(bad.errors.size(), 2);
        QVERIFY2(bad.errors.join(QLatin1Char('\n')).contains(QStringLiteral("device.id: 256")),
                 qPrintable(bad.errors.join(QLatin1Char('\n'))));
    }

    void everyProblemIsListedOnce()
    {
        QByteArray json = good();
        json.replace("\"motor1.speed\": 300", "\"motor1.speed\": 0");
        json.replace("\"motor2.speed\": 300", "\"motor2.speed\": \"fast\"");
        json.replace("\"arc.speed\": 100,", "");
        const ProfileParseResult r = ProfileFile::parse(json, map);
        QVERIFY(!r.ok());
        QCOMPARE(r.errors.size(), 3);
        QVERIFY(r.errors.at(0).contains(QStringLiteral("motor1.speed: 0 is out of range")) ||
                r.errors.join(QLatin1Char('\n')).contains(QStringLiteral("motor1.speed: 0")));
        QVERIFY(r.errors.join(QLatin1Char('\n')).contains(QStringLiteral("missing \"arc.speed\"")));
    }

    void errorsAreCapped()
    {
        QByteArray json = good();
        QByteArray extra;
        for (int i = 0; i < 200; ++i)
            extra += "\"nope" + QByteArray::number(i) + "\": 1, ";
        json.replace("\"motor1.speed\"", extra + "\"motor1.speed\"");
        const ProfileParseResult r = ProfileFile::parse(json, map);
        QCOMPARE(r.errors.size(), ProfileFile::MaxErrors + 1);
        QVERIFY(r.errors.last().contains(QStringLiteral("160 more")));
    }

    void tooLargeIsRefusedUnread()
    {
        QByteArray json = good();
        json.append(QByteArray(ProfileFile::MaxBytes, ' '));
        const ProfileParseResult r = ProfileFile::parse(json, map);
        QVERIFY(!r.ok());
        QVERIFY(r.errors.value(0).contains(QStringLiteral("far too large")));
    }

    // The pure entry point never crashes: every truncation, and many random corruptions.
    void everyTruncationIsRefused()
    {
        const QByteArray json = good();
        const qsizetype end = json.trimmed().size();
        for (qsizetype n = 0; n < end; ++n) {
            const ProfileParseResult r = ProfileFile::parse(json.left(n), map);
            QVERIFY2(!r.ok() && !r.errors.isEmpty(), qPrintable(QString::number(n)));
        }
        QVERIFY(ProfileFile::parse(json.left(end), map).ok());
    }
    void randomCorruptionsNeverCrash()
    {
        const QByteArray json = good();
        QRandomGenerator random(20240531); // fixed: a failure can be replayed
        int accepted = 0;
        for (int round = 0; round < 3000; ++round) {
            QByteArray mutated = json;
            const int changes = 1 + int(random.bounded(4));
            for (int i = 0; i < changes; ++i) {
                const qsizetype at = random.bounded(int(mutated.size()));
                switch (random.bounded(3)) {
                case 0:
                    mutated[at] = char(random.bounded(256));
                    break;
                case 1:
                    mutated.remove(at, 1 + random.bounded(8));
                    break;
                default:
                    mutated.insert(at, "{[\",:}]0e9-"[random.bounded(11)]);
                }
            }
            const ProfileParseResult r = ProfileFile::parse(mutated, map);
            QCOMPARE(r.ok(), r.errors.isEmpty());
            if (r.ok()) {
                ++accepted;
                // Whatever is accepted is valid for the map.
                for (auto it = r.profile->values.cbegin(); it != r.profile->values.cend(); ++it)
                    QCOMPARE(map.find(it.key())->checkRaw(it.value()), QString());
            }
        }
        QVERIFY(accepted < 3000);
    }

    void diffAndWrites()
    {
        const Profile p = *ProfileFile::parse(good(), map).profile;
        QHash<QString, qint64> device;
        for (auto it = p.values.cbegin(); it != p.values.cend(); ++it)
            device.insert(it.key(), it.value());
        device[QStringLiteral("motor1.speed")] = 450;
        device[QStringLiteral("arc.end_x")] = -100;
        device.insert(QStringLiteral("device.id"), 3);
        const QList<ProfileDifference> rows = ProfileDiff::compare(map, p, device);
        QCOMPARE(rows.size(), Profile::profileParameters(map, true).size());
        const QList<ProfileDifference> diffs = ProfileDiff::differences(rows);
        QCOMPARE(diffs.size(), 2); // device.id is not in the profile: nothing to differ from
        QCOMPARE(ProfileDiff::describe(diffs.at(0)),
                 QStringLiteral("motor1.speed: 450 rpm -> 300 rpm"));
        QCOMPARE(ProfileDiff::describe(diffs.at(1)),
                 QStringLiteral("arc.end_x: -1.00 mm -> 10.00 mm"));

        Profile withLink = p;
        withLink.values.insert(QStringLiteral("device.id"), 5);
        QStringList errors;
        auto writes = ProfileDiff::writesFor(
            map, withLink, {QStringLiteral("device.id"), QStringLiteral("arc.end_x")}, false,
            &errors);
        QVERIFY(errors.isEmpty());
        QCOMPARE(writes.size(), 1); // the link setting only when asked for
        QCOMPARE(writes.at(0).parameter->key, QStringLiteral("arc.end_x"));
        QCOMPARE(writes.at(0).raw, 1000);
        writes =
            ProfileDiff::writesFor(map, withLink, {QStringLiteral("device.id")}, true, &errors);
        QCOMPARE(writes.size(), 1);
        QCOMPARE(writes.at(0).raw, 5);
        writes = ProfileDiff::writesFor(map, p, {QStringLiteral("device.baud")}, true, &errors);
        QVERIFY(writes.isEmpty());
        QCOMPARE(errors.size(), 1);
        QVERIFY(errors.at(0).contains(QStringLiteral("device.baud")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProfileFile, Guiless)
#include "tst_profilefile.moc"
