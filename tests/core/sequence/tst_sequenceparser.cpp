#include "map/registermap.h"
#include "motion/travellimits.h"
#include "sequence/sequencecheck.h"
#include "sequence/sequenceparser.h"
#include "sequence/sequencewriter.h"

#include <QTest>

using namespace stepcom;

namespace {

QByteArray file(const QByteArray &steps, const QByteArray &extra = QByteArray())
{
    return "{\"format\": \"stepcom-sequence\", \"version\": 1,\n"
           " \"points\": {\"load\": {\"motor1\": 30.0}, \"unload\": {\"motor1\": 10.0, "
           "\"motor2\": 0.0}},\n"
           " \"limits\": {\"motor1\": {\"min\": 0, \"max\": 300}},\n" +
           extra + " \"steps\": " + steps + "}";
}

QStringList problems(const QByteArray &json, int cycles = 1)
{
    QStringList errors;
    const RegisterMap &map = RegisterMap::builtin();
    const auto s = SequenceParser::parse(json, QStringLiteral("t.stepseq"), map, &errors);
    if (s) {
        SequenceCheck::Start start;
        start.axes.insert(1, {});
        start.axes.insert(2, {});
        errors << SequenceCheck::check(*s, map, TravelLimits(), start, cycles);
    }
    return errors;
}

} // namespace

class TestSequenceParser : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    // What the window saves reloads to the same sequence.
    void writeRoundTrip()
    {
        const QByteArray json =
            file("[{\"home\": \"order\"}, {\"speed\": {\"motor1\": 120}}, {\"repeat\": 3, "
                 "\"steps\": [{\"move_to\": \"load\"}, {\"move_to\": {\"motor2\": 5.5}}, "
                 "{\"move_by\": {\"motor1\": -2}}, {\"wait_input\": 3, \"on\": true, "
                 "\"timeout_s\": 20}, {\"output\": 1, \"on\": true}, {\"outputs\": \"all_off\"}, "
                 "{\"dwell_ms\": 500}, {\"repeat\": 2, \"steps\": [{\"home\": \"motor2\"}]}]}]",
                 " \"on_stop\": {\"outputs\": \"all_off\"},\n");
        const RegisterMap &map = RegisterMap::builtin();
        QStringList errors;
        const auto first = SequenceParser::parse(json, QStringLiteral("t.stepseq"), map, &errors);
        QVERIFY2(first, qPrintable(errors.join('\n')));
        const QByteArray written = SequenceWriter::write(*first, map);
        const auto again =
            SequenceParser::parse(written, QStringLiteral("t.stepseq"), map, &errors);
        QVERIFY2(again, qPrintable(errors.join('\n') + '\n' + QString::fromUtf8(written)));
        QCOMPARE(SequenceWriter::write(*again, map), written);
        QCOMPARE(again->points, first->points);
        QCOMPARE(again->limits.axes(), first->limits.axes());
        QVERIFY(again->outputsOffOnStop);
        QCOMPARE(again->allSteps().size(), first->allSteps().size());
        QCOMPARE(again->steps.at(2).steps.at(3).timeoutMs, 20000);
        QCOMPARE(again->steps.at(2).steps.at(7).steps.at(0).homeMotors, QList<int>{2});
    }
    void example()
    {
        const QByteArray json = file(
            "[{\"home\": \"order\"}, {\"repeat\": 3, \"steps\": [{\"move_to\": \"load\"}, "
            "{\"wait_input\": 3, \"on\": true, \"timeout_s\": 20}, {\"output\": 1, \"on\": true}, "
            "{\"dwell_ms\": 500}, {\"move_to\": \"unload\"}, {\"output\": 1, \"on\": false}]}]");
        QStringList errors;
        const auto s = SequenceParser::parse(json, QStringLiteral("t.stepseq"),
                                             RegisterMap::builtin(), &errors);
        QVERIFY2(s, qPrintable(errors.join('\n')));
        QCOMPARE(s->steps.size(), 2);
        QVERIFY(s->steps.at(0).homeInOrder);
        QCOMPARE(s->steps.at(1).count, 3);
        QCOMPARE(s->steps.at(1).steps.size(), 6);
        QCOMPARE(s->steps.at(1).steps.at(4).axes.value(2), 0.0);
        QCOMPARE(s->steps.at(1).steps.at(1).timeoutMs, 20000);
        QCOMPARE(s->steps.at(1).steps.at(0).path, QStringLiteral("steps[1].steps[0]"));
        QVERIFY(problems(json).isEmpty());
        QCOMPARE(s->motors(), (QList<int>{1, 2}));
    }

    void refused_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        const QByteArray home = "{\"home\": \"order\"}, ";
        QTest::newRow("invalid json") << QByteArray("{\"format\": \n  \"x\",, }")
                                      << "t.stepseq: not valid JSON at line 2, column";
        QTest::newRow("format") << QByteArray("{\"format\": \"other\", \"version\": 1}")
                                << "t.stepseq: format: not a sequence file";
        QTest::newRow("version")
            << QByteArray("{\"format\": \"stepcom-sequence\", \"version\": 2, \"steps\": []}")
            << "t.stepseq: version: version 2 is not known";
        QTest::newRow("unknown point") << file("[" + home + "{\"move_to\": \"lod\"}]")
                                       << "t.stepseq: steps[1].move_to: unknown point \"lod\"";
        QTest::newRow("unknown key") << file("[" + home + "{\"dwell_ms\": 5, \"speed_x\": 1}]")
                                     << "t.stepseq: steps[1]: unknown key \"speed_x\"";
        QTest::newRow("unknown step")
            << file("[{\"dwel_ms\": 5}]") << "t.stepseq: steps[0]: unknown key \"dwel_ms\"";
        QTest::newRow("unknown top key")
            << file("[" + home + "{\"dwell_ms\": 5}]", "\"loops\": 3,\n")
            << "t.stepseq: file: unknown key \"loops\"";
        QTest::newRow("no such input") << file("[{\"wait_input\": 5, \"on\": true}]")
                                       << "steps[0].wait_input: the controller has no input 5";
        QTest::newRow("no such output") << file("[{\"output\": 4, \"on\": true}]")
                                        << "steps[0].output: the controller has no output 4";
        QTest::newRow("output not alone")
            << file("[{\"output\": 2, \"on\": true}]") << "cannot switch output 2 alone";
        QTest::newRow("wrong type") << file("[{\"dwell_ms\": \"500\"}]")
                                    << "steps[0].dwell_ms: must be a whole number, not a text";
        QTest::newRow("on not bool") << file("[{\"output\": 1, \"on\": 1}]")
                                     << "steps[0].on: must be true or false, not a number";
        QTest::newRow("unknown axis") << file("[{\"move_by\": {\"motor3\": 1}}]")
                                      << "steps[0].move_by.motor3: unknown axis \"motor3\"";
        QTest::newRow("third decimal") << file("[{\"move_by\": {\"motor1\": 0.005}}]")
                                       << "steps[0].move_by.motor1: motor1.move_distance";
        QTest::newRow("outside file limits")
            << file("[" + home + "{\"move_to\": {\"motor1\": 301}}]")
            << "steps[1]: motor 1 would go to 301.00 mm, outside the file's limits";
        QTest::newRow("relative beyond, in a loop")
            << file("[" + home + "{\"repeat\": 4, \"steps\": [{\"move_by\": {\"motor1\": 100}}]}]")
            << "steps[1].steps[0]: motor 1 would go to 400.00 mm";
        QTest::newRow("nested loops")
            << file("[" + home +
                    "{\"repeat\": 2, \"steps\": [{\"repeat\": 2, \"steps\": [{\"move_by\": "
                    "{\"motor1\": 80}}]}]}]")
            << "steps[1].steps[0].steps[0]: motor 1 would go to 320.00 mm";
        QTest::newRow("move_to before home")
            << file("[{\"move_to\": \"load\"}, {\"home\": \"motor1\"}]")
            << "steps[0]: motor 1 is not referenced";
        QTest::newRow("other motor homed")
            << file("[{\"home\": \"motor1\"}, {\"move_to\": \"unload\"}]")
            << "steps[1]: motor 2 is not referenced";
        QTest::newRow("repeat zero") << file("[{\"repeat\": 0, \"steps\": [{\"dwell_ms\": 1}]}]")
                                     << "steps[0].repeat: must be a whole number from 1";
        QTest::newRow("repeat without steps")
            << file("[{\"repeat\": 2}]") << "steps[0]: a repeat needs \"steps\"";
        QTest::newRow("two kinds")
            << file("[{\"dwell_ms\": 1, \"home\": \"order\"}]") << "one step does one thing";
        QTest::newRow("on_stop") << file("[{\"dwell_ms\": 1}]", "\"on_stop\": {\"outputs\": "
                                                                "\"off\"},\n")
                                 << "on_stop.outputs: must be \"leave\" or \"all_off\"";
        QTest::newRow("limits min above max")
            << QByteArray("{\"format\": \"stepcom-sequence\", \"version\": 1, \"limits\": "
                          "{\"motor1\": {\"min\": 5, \"max\": 1}}, \"steps\": [{\"dwell_ms\": 1}]}")
            << "t.stepseq: limits.motor1:";
        QTest::newRow("timeout") << file("[{\"wait_input\": 1, \"on\": true, \"timeout_s\": 0}]")
                                 << "steps[0].timeout_s: must be more than 0";
    }
    void refused()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        const QStringList errors = problems(json);
        QVERIFY2(!errors.isEmpty(), "accepted");
        QVERIFY2(errors.join('\n').contains(message), qPrintable(errors.join('\n')));
    }

    void cyclesWalkThePositions()
    {
        // One cycle fits, the third goes beyond max 300: cycles are walked too.
        const QByteArray json = file("[{\"move_by\": {\"motor1\": 100}}]");
        QStringList errors;
        const auto s = SequenceParser::parse(json, QStringLiteral("t.stepseq"),
                                             RegisterMap::builtin(), &errors);
        QVERIFY(s);
        SequenceCheck::Start start;
        start.axes.insert(1, SequenceCheck::Axis{false, 50.0});
        QVERIFY(
            SequenceCheck::check(*s, RegisterMap::builtin(), TravelLimits(), start, 2).isEmpty());
        QVERIFY(
            !SequenceCheck::check(*s, RegisterMap::builtin(), TravelLimits(), start, 3).isEmpty());
        // StepCom's own travel limits apply as well.
        TravelLimits travel;
        QVERIFY(travel.setAxis(RegisterMap::builtin(), 1, std::nullopt, 120.0).isEmpty());
        QVERIFY(SequenceCheck::check(*s, RegisterMap::builtin(), travel, start, 1)
                    .join(' ')
                    .contains(QStringLiteral("software travel limit")));
        // The homing order read from the controller: motor 2 only leaves motor 1 unreferenced.
        const auto homed =
            SequenceParser::parse(file("[{\"home\": \"order\"}, {\"move_to\": "
                                       "\"load\"}]"),
                                  QStringLiteral("t.stepseq"), RegisterMap::builtin(), &errors);
        QVERIFY(homed);
        start.homingOrder = SequenceCheck::homingOrder(2, 0);
        QVERIFY(SequenceCheck::check(*homed, RegisterMap::builtin(), TravelLimits(), start, 1)
                    .join(' ')
                    .contains(QStringLiteral("motor 1 is not referenced")));
        start.homingOrder = SequenceCheck::homingOrder(2, 1);
        QVERIFY(SequenceCheck::check(*homed, RegisterMap::builtin(), TravelLimits(), start, 1)
                    .isEmpty());
    }
};

STEPCOM_TEST(TestSequenceParser, Guiless)
#include "tst_sequenceparser.moc"
