#include "map/registermap.h"

#include "testmaps.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

int registerCount(const RegisterMap &map, bool writableOnly)
{
    int n = 0;
    for (const Parameter *p : map.holdings()) {
        if (!writableOnly || p->writable())
            n += p->words;
    }
    return n;
}

// A small valid map to break in controlled ways.
QJsonObject miniMap()
{
    const QJsonObject text{{QStringLiteral("en"), QStringLiteral("X")},
                           {QStringLiteral("zh_CN"), QStringLiteral("甲")}};
    auto entry = [&](const QString &key, int plc) {
        return QJsonObject{{QStringLiteral("key"), key},
                           {QStringLiteral("kind"), QStringLiteral("holding")},
                           {QStringLiteral("plc"), plc},
                           {QStringLiteral("words"), 1},
                           {QStringLiteral("scale"), 1},
                           {QStringLiteral("unit"), QString()},
                           {QStringLiteral("min"), 0},
                           {QStringLiteral("max"), 10},
                           {QStringLiteral("access"), QStringLiteral("rw")},
                           {QStringLiteral("group"), QStringLiteral("g")},
                           {QStringLiteral("label"), text},
                           {QStringLiteral("help"), text}};
    };
    return QJsonObject{
        {QStringLiteral("format"), QStringLiteral("stepcom-register-map")},
        {QStringLiteral("schema"), 1},
        {QStringLiteral("id"), QStringLiteral("mini")},
        {QStringLiteral("version"), 1},
        {QStringLiteral("name"), text},
        {QStringLiteral("groups"),
         QJsonArray{QJsonObject{{QStringLiteral("id"), QStringLiteral("g")},
                                {QStringLiteral("label"), text}}}},
        {QStringLiteral("entries"),
         QJsonArray{entry(QStringLiteral("a.one"), 40001), entry(QStringLiteral("a.two"), 40002)}}};
}

QJsonObject withEntry(int index, const QString &field, const QJsonValue &value)
{
    QJsonObject map = miniMap();
    QJsonArray entries = map.value(QStringLiteral("entries")).toArray();
    QJsonObject e = entries.at(index).toObject();
    if (value.isUndefined())
        e.remove(field);
    else
        e.insert(field, value);
    entries[index] = e;
    map.insert(QStringLiteral("entries"), entries);
    return map;
}

QByteArray json(const QJsonObject &o)
{
    return QJsonDocument(o).toJson();
}

} // namespace

class TestRegisterMap : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    // Regression: --map /dev/zero grew to 24 GB and was killed.
    void hugeOrEndlessMapFilesAreRefusedBeforeReading()
    {
        QStringList errors;
        QVERIFY(!RegisterMap::loadFile(QStringLiteral("/dev/zero"), &errors));
        QVERIFY2(errors.join(QLatin1Char(' ')).contains(QStringLiteral("not a regular file")),
                 qPrintable(errors.join(QLatin1Char(' '))));
        QTemporaryDir dir;
        QFile big(dir.filePath(QStringLiteral("big.json")));
        QVERIFY(big.open(QIODevice::WriteOnly));
        QVERIFY(big.resize(RegisterMap::kMaxFileBytes + 1)); // sparse: costs no disk
        big.close();
        errors.clear();
        QVERIFY(!RegisterMap::loadFile(big.fileName(), &errors));
        QVERIFY2(errors.join(QLatin1Char(' ')).contains(QStringLiteral("too large")),
                 qPrintable(errors.join(QLatin1Char(' '))));
    }
    void builtinMatchesTheManual()
    {
        const RegisterMap &map = RegisterMap::builtin();
        QVERIFY(map.isValid());
        QCOMPARE(map.blockCount(QStringLiteral("motor")), 2);
        QCOMPARE(registerCount(map, false), 75); // everything readable (design notes)
        QCOMPARE(registerCount(map, true), 62);  // every writable parameter
        QCOMPARE(map.maxRegistersPerRequest(), 49);

        const Parameter *speed2 = map.find(QStringLiteral("motor2.speed"));
        QVERIFY(speed2);
        QCOMPARE(speed2->plc, 40016);
        QCOMPARE(speed2->address, quint16(15));
        QCOMPARE(map.find(QStringLiteral("mode.system"))->address, quint16(0x012B));
        const Parameter *pos = map.find(QStringLiteral("motor1.position"));
        QCOMPARE(pos->words, 2);
        QVERIFY(pos->isSigned);
        QCOMPARE(pos->access, Access::ReadOnly);
        const Parameter *estop = map.find(QStringLiteral("estop"));
        QVERIFY(estop && estop->isCoil());
        QCOMPARE(estop->address, quint16(41));
        QCOMPARE(estop->command, CommandClass::Emergency);
        QCOMPARE(map.find(QStringLiteral("motor2.reverse"))->address, quint16(7));
        QCOMPARE(map.find(QStringLiteral("factory_reset"))->command, CommandClass::Destructive);
        QCOMPARE(map.blockParameter(QStringLiteral("motor"), 2, QStringLiteral("home_input"))->plc,
                 40086);
        // Every entry speaks both languages.
        for (const Parameter &p : map.parameters()) {
            QVERIFY2(!p.label.en.isEmpty() && !p.label.zh.isEmpty(), qPrintable(p.key));
            QVERIFY2(!p.help.en.isEmpty() && !p.help.zh.isEmpty(), qPrintable(p.key));
        }
        QCOMPARE(map.find(QStringLiteral("motor1.microsteps"))->label.zh, QStringLiteral("细分"));
    }

    void moreAxesIsAChangeOfData()
    {
        QStringList errors;
        const auto map = stepcom::test::builtinMapWithMotors(3, &errors);
        QVERIFY2(map, qPrintable(errors.join(QLatin1Char('\n'))));
        QCOMPARE(map->blockCount(QStringLiteral("motor")), 3);
        QCOMPARE(map->find(QStringLiteral("motor3.step_angle"))->plc, 40021);
        QCOMPARE(map->find(QStringLiteral("motor3.stop"))->plc, 15);
        QCOMPARE(map->find(QStringLiteral("motor3.position"))->plc, 40112);
    }

    void validationErrorsNameEntryAndField_data()
    {
        QTest::addColumn<QByteArray>("input");
        QTest::addColumn<QString>("expected");
        QTest::newRow("overlap") << json(withEntry(1, QStringLiteral("plc"), 40001))
                                 << QStringLiteral("overlaps 'a.one'");
        QTest::newRow("two words overlap")
            << json(withEntry(0, QStringLiteral("words"), 2)) << QStringLiteral("overlaps");
        QTest::newRow("bad width")
            << json(withEntry(0, QStringLiteral("words"), 3))
            << QStringLiteral("entry 'a.one', field 'words': must be 1 or 2, got 3");
        QTest::newRow("unknown kind")
            << json(withEntry(0, QStringLiteral("kind"), QStringLiteral("input")))
            << QStringLiteral("entry 'a.one', field 'kind': unknown kind 'input'");
        QTest::newRow("unknown group")
            << json(withEntry(1, QStringLiteral("group"), QStringLiteral("nope")))
            << QStringLiteral("entry 'a.two', field 'group': unknown group 'nope'");
        QTest::newRow("missing label")
            << json(withEntry(0, QStringLiteral("label"), QJsonValue(QJsonValue::Undefined)))
            << QStringLiteral("entry 'a.one', field 'label': missing");
        QTest::newRow("missing chinese")
            << json(withEntry(0, QStringLiteral("help"),
                              QJsonObject{{QStringLiteral("en"), QStringLiteral("x")}}))
            << QStringLiteral("entry 'a.one', field 'help': the Chinese (zh_CN) text is missing");
        QTest::newRow("unknown field")
            << json(withEntry(0, QStringLiteral("colour"), 1))
            << QStringLiteral("entry 'a.one', field 'colour': unknown field");
        QTest::newRow("scale") << json(withEntry(0, QStringLiteral("scale"), 7))
                               << QStringLiteral("field 'scale': must be 1, 10, 100 or 1000");
        QTest::newRow("min over max") << json(withEntry(0, QStringLiteral("min"), 20))
                                      << QStringLiteral("field 'min': is greater than max");
        QTest::newRow("too wide") << json(withEntry(0, QStringLiteral("max"), 70000))
                                  << QStringLiteral("field 'max': does not fit unsigned 16 bits");
        QTest::newRow("plc range") << json(withEntry(0, QStringLiteral("plc"), 30001))
                                   << QStringLiteral("field 'plc': 30001 is outside 40001-49999");
        QTest::newRow("duplicate key")
            << json(withEntry(1, QStringLiteral("key"), QStringLiteral("a.one")))
            << QStringLiteral("entry 'a.one', field 'key': defined twice");
        QTest::newRow("unknown enum")
            << json(withEntry(0, QStringLiteral("enum"), QStringLiteral("nope")))
            << QStringLiteral("field 'enum': unknown enum 'nope'");
        QTest::newRow("bad access")
            << json(withEntry(0, QStringLiteral("access"), QStringLiteral("x")))
            << QStringLiteral("field 'access': must be \"r\" or \"rw\"");
        // Found by fuzzing (tests/fuzz): numbers far beyond any register were undefined
        // conversions or an int overflow; now they are plain errors.
        QJsonObject hugeVersion = miniMap();
        hugeVersion.insert(QStringLiteral("version"), 1e300);
        QTest::newRow("huge version")
            << json(hugeVersion) << QStringLiteral("field 'version': must be a whole number");
        QTest::newRow("huge max") << json(withEntry(0, QStringLiteral("max"), 1e300))
                                  << QStringLiteral("field 'max': does not fit unsigned 16 bits");
        QTest::newRow("huge min") << json(withEntry(0, QStringLiteral("min"), -1e300))
                                  << QStringLiteral("field 'min': does not fit unsigned 16 bits");
        QJsonObject hugeStride = miniMap();
        QJsonObject strided = withEntry(0, QStringLiteral("stride"), 2147483647)
                                  .value(QStringLiteral("entries"))
                                  .toArray()
                                  .at(0)
                                  .toObject();
        strided.insert(QStringLiteral("key"), QStringLiteral("speed"));
        hugeStride.insert(QStringLiteral("blocks"),
                          QJsonArray{QJsonObject{
                              {QStringLiteral("prefix"), QStringLiteral("m")},
                              {QStringLiteral("count"), 32},
                              {QStringLiteral("label"), miniMap().value(QStringLiteral("name"))},
                              {QStringLiteral("entries"), QJsonArray{strided}}}});
        QTest::newRow("huge stride")
            << json(hugeStride)
            << QStringLiteral("entry 'm2.speed', field 'plc': 2147523648 is outside 40001-49999");
        QJsonObject hugeEnum = miniMap();
        hugeEnum.insert(
            QStringLiteral("enums"),
            QJsonObject{{QStringLiteral("e"),
                         QJsonArray{QJsonObject{{QStringLiteral("value"), 1e300},
                                                {QStringLiteral("label"),
                                                 miniMap().value(QStringLiteral("name"))}}}}});
        QTest::newRow("huge enum value")
            << json(hugeEnum)
            << QStringLiteral("enum 'e'[0], field 'value': must be a whole number");
        QTest::newRow("broken json")
            << QByteArray("{\n  \"format\": \"stepcom-register-map\",\n  oops\n}")
            << QStringLiteral("invalid JSON at line 3");
        QTest::newRow("not a map")
            << QByteArray("[1, 2]") << QStringLiteral("must be a JSON object");
        QTest::newRow("wrong format")
            << QByteArray("{\"format\": \"x\"}") << QStringLiteral("field 'format'");
    }

    void validationErrorsNameEntryAndField()
    {
        QFETCH(QByteArray, input);
        QFETCH(QString, expected);
        QStringList errors;
        QVERIFY(RegisterMap::fromJson(json(miniMap()), &errors)); // the base case is valid
        QVERIFY(errors.isEmpty());
        const auto map = RegisterMap::fromJson(input, &errors);
        QVERIFY(!map);
        const QString all = errors.join(QLatin1Char('\n'));
        QVERIFY2(all.contains(expected), qPrintable(all));
    }

    void loadFileNamesTheFile()
    {
        QStringList errors;
        QVERIFY(!RegisterMap::loadFile(QStringLiteral("/nonexistent/map.json"), &errors));
        QVERIFY(errors.join(QString()).contains(QStringLiteral("/nonexistent/map.json")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestRegisterMap, Guiless)
#include "tst_registermap.moc"
