// Requests of another master paired with their answers and decoded by the register map: reads
// with the values answered, writes with the parameter's name and engineering value, commands,
// exceptions, a request whose answer never comes, an answer whose request was not heard; the
// heard state and the answer times per device.
#include "listen/framefinder.h"
#include "listen/listendecoder.h"
#include "listenframes.h"
#include "map/registermap.h"

#include <QJsonDocument>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

struct Heard
{
    QByteArray hex;
    qint64 ms;
};

QList<HeardEvent> decodeAll(ListenDecoder &decoder, const QList<Heard> &frames)
{
    QList<HeardEvent> out;
    for (const Heard &h : frames)
        out << decoder.frame(HeardFrame{rtu(h.hex.constData()), h.ms});
    out << decoder.finish();
    return out;
}

QString json(const HeardEvent &e)
{
    QStringList lines;
    for (const QJsonObject &o : e.toJson(0))
        lines << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));
    return lines.join(u'\n');
}

} // namespace

Q_DECLARE_METATYPE(Heard)

class TestListenDecoder : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void decodes_data()
    {
        QTest::addColumn<QList<Heard>>("frames");
        QTest::addColumn<QStringList>("kinds");
        QTest::addColumn<QStringList>("texts");

        QTest::newRow("FC03 read paired with its values")
            << QList<Heard>{{"01 03 00 00 00 02", 0}, {"01 03 04 00 B4 00 08", 20}}
            << QStringList{"read"}
            << QStringList{"PLC read 40001-40002 from id 1: motor1.step_angle = 1.80 °, "
                           "motor1.microsteps = 8 (answered in 17.7 ms)"};
        QTest::newRow("FC06 write of motor1.speed")
            << QList<Heard>{{"01 06 00 05 03 09", 0}, {"01 06 00 05 03 09", 10}}
            << QStringList{"write"}
            << QStringList{"PLC wrote motor1.speed = 777 rpm to id 1 (answered in 7.9 ms)"};
        QTest::newRow("FC10 write of a 2-word value, low word first")
            << QList<Heard>{{"02 10 00 06 00 02 04 04 D2 00 00", 0}, {"02 10 00 06 00 02", 5}}
            << QStringList{"write"}
            << QStringList{"PLC wrote motor1.pitch = 12.34 mm to id 2 (answered in 2.9 ms)"};
        QTest::newRow("FC05 command")
            << QList<Heard>{{"01 05 00 29 FF 00", 0}, {"01 05 00 29 FF 00", 3}}
            << QStringList{"command"}
            << QStringList{"PLC sent estop = on to id 1 (answered in 0.9 ms)"};
        QTest::newRow("FC0F coils")
            << QList<Heard>{{"01 0F 00 00 00 02 01 01", 0}, {"01 0F 00 00 00 02", 3}}
            << QStringList{"command"}
            << QStringList{"PLC sent motor1.move = on, motor1.forward = off to id 1 "
                           "(answered in 0.9 ms)"};
        QTest::newRow("FC04 input registers")
            << QList<Heard>{{"01 04 00 10 00 01", 0}, {"01 04 02 12 34", 4}} << QStringList{"read"}
            << QStringList{"PLC read 30017 from id 1: 30017 = 4660 (answered in 2.2 ms)"};
        QTest::newRow("exception")
            << QList<Heard>{{"01 03 00 70 00 0C", 0}, {"01 83 02", 5}} << QStringList{"exception"}
            << QStringList{"id 1 refused the PLC's FC03 at 40113-40124: illegal data address (02)"};
        QTest::newRow("a request whose answer never comes, then the next")
            << QList<Heard>{{"03 03 00 00 00 02", 0},
                            {"01 06 00 05 03 09", 200},
                            {"01 06 00 05 03 09", 210}}
            << QStringList{"no-answer", "write"}
            << QStringList{"id 3 did not answer the PLC's FC03 at 40001-40002",
                           "PLC wrote motor1.speed = 777 rpm to id 1 (answered in 7.9 ms)"};
        QTest::newRow("an unanswered write says what it would have written")
            << QList<Heard>{{"01 06 00 05 03 09", 0}} << QStringList{"no-answer"}
            << QStringList{"id 1 did not answer the PLC's FC06 at 40006 (motor1.speed = 777 rpm)"};
        QTest::newRow("an answer whose request was not heard")
            << QList<Heard>{{"01 03 04 00 B4 00 08", 0}, {"01 03 00 00 00 02", 10}}
            << QStringList{"stray-answer", "no-answer"}
            << QStringList{"an answer from id 1 (FC03) whose request was not heard",
                           "id 1 did not answer the PLC's FC03 at 40001-40002"};
        QTest::newRow("an answer of another count is no answer")
            << QList<Heard>{{"01 03 00 00 00 03", 0}, {"01 03 04 00 B4 00 08", 10}}
            << QStringList{"stray-answer", "no-answer"}
            << QStringList{"an answer from id 1 (FC03) whose request was not heard",
                           "id 1 did not answer the PLC's FC03 at 40001-40003"};
        QTest::newRow("an answer from another id is no answer")
            << QList<Heard>{{"01 06 00 05 03 09", 0}, {"02 83 02", 10}}
            << QStringList{"stray-answer", "no-answer"}
            << QStringList{"an answer from id 2 (FC03) whose request was not heard",
                           "id 1 did not answer the PLC's FC06 at 40006 (motor1.speed = 777 rpm)"};
        QTest::newRow("broadcast")
            << QList<Heard>{{"00 06 00 05 03 09", 0}} << QStringList{"broadcast"}
            << QStringList{"PLC broadcast FC06 at 40006 to every id: motor1.speed = 777 rpm"};
    }

    void decodes()
    {
        QFETCH(QList<Heard>, frames);
        QFETCH(QStringList, kinds);
        QFETCH(QStringList, texts);
        ListenDecoder decoder(&RegisterMap::builtin(), 38400);
        const QList<HeardEvent> events = decodeAll(decoder, frames);
        QStringList gotKinds;
        QStringList gotTexts;
        for (const HeardEvent &e : events) {
            gotKinds << HeardEvent::kindName(e.kind);
            gotTexts << e.text();
        }
        QCOMPARE(gotTexts, texts);
        QCOMPARE(gotKinds, kinds);
    }

    // The JSON line of a write: its key, engineering value and unit, as `params --json` names
    // them; a read lists its keys and values.
    void jsonLines()
    {
        ListenDecoder decoder(&RegisterMap::builtin(), 38400);
        const QList<HeardEvent> write =
            decodeAll(decoder, {{"01 06 00 05 03 09", 1000}, {"01 06 00 05 03 09", 1010}});
        QCOMPARE(json(write.first()),
                 QStringLiteral("{\"address\":40006,\"answer_ms\":7.9,\"count\":1,\"fc\":6,"
                                "\"from\":\"other master\",\"id\":1,\"key\":\"motor1.speed\","
                                "\"kind\":\"write\",\"t\":1.01,\"unit\":\"rpm\",\"value\":777}"));
        const QList<HeardEvent> read =
            decodeAll(decoder, {{"01 03 00 00 00 02", 0}, {"01 03 04 00 B4 00 08", 20}});
        const QJsonObject o = read.first().toJson(0).first();
        QCOMPARE(o.value(u"kind").toString(), QStringLiteral("read"));
        QCOMPARE(o.value(u"keys").toArray().size(), 2);
        QCOMPARE(o.value(u"values").toObject().value(u"motor1.step_angle").toDouble(), 1.8);
        QCOMPARE(o.value(u"values").toObject().value(u"motor1.microsteps").toInt(), 8);
        // A write of several parameters is a line each.
        const QList<HeardEvent> two = decodeAll(
            decoder, {{"01 10 00 05 00 03 06 00 64 04 D2 00 00", 0}, {"01 10 00 05 00 03", 5}});
        const QList<QJsonObject> lines = two.first().toJson(0);
        QCOMPARE(lines.size(), 2);
        QCOMPARE(lines.at(0).value(u"key").toString(), QStringLiteral("motor1.speed"));
        QCOMPARE(lines.at(1).value(u"key").toString(), QStringLiteral("motor1.pitch"));
        QCOMPARE(lines.at(1).value(u"value").toDouble(), 12.34);
    }

    // What was answered and acknowledged is the heard state; the answer times per device.
    void heardStateAndAnswerTimes()
    {
        ListenDecoder decoder(&RegisterMap::builtin(), 38400);
        decodeAll(decoder, {{"01 03 00 00 00 02", 0},
                            {"01 03 04 00 B4 00 08", 20},
                            {"01 06 00 05 03 09", 100},
                            {"01 06 00 05 03 09", 110},
                            {"01 06 00 06 00 01", 200}}); // never acknowledged
        const QHash<QString, qint64> values =
            decoder.state().devices.value(1).values(RegisterMap::builtin());
        QCOMPARE(values.value(QStringLiteral("motor1.step_angle")), 180);
        QCOMPARE(values.value(QStringLiteral("motor1.speed")), 777);
        QVERIFY(!values.contains(QStringLiteral("motor1.pitch"))); // its other half unheard
        const ListenDecoder::DeviceStats s = decoder.deviceStats().value(1);
        QCOMPARE(s.requests, 3);
        QCOMPARE(s.answered, 2);
        QCOMPARE(s.unanswered, 1);
        QCOMPARE(decoder.pairs(), 2);
        QVERIFY(qAbs(s.answerMsMin - 7.9) < 0.1);
        QVERIFY(qAbs(s.answerMsMax - 17.7) < 0.1);
    }

    // A request waits for its answer no longer than the timeout when the line goes quiet.
    void aLongSilenceEndsTheWait()
    {
        ListenDecoder decoder(&RegisterMap::builtin(), 38400);
        decoder.setAnswerTimeoutMs(500);
        QVERIFY(decoder.frame(HeardFrame{rtu("01 03 00 00 00 02"), 100}).isEmpty());
        QVERIFY(decoder.idle(599).isEmpty());
        const QList<HeardEvent> out = decoder.idle(600);
        QCOMPARE(out.size(), 1);
        QCOMPARE(out.first().kind, HeardEvent::Kind::NoAnswer);
        QVERIFY(decoder.finish().isEmpty());
    }

    // Frames found in 16-byte packets with a stray 0x00 and a bad CRC decode to the same events.
    void fromTheByteStream()
    {
        const QByteArray stream = rtu("01 06 00 05 03 09") + QByteArray(1, '\0') +
                                  rtu("01 06 00 05 03 09") + badCrc("01 03 00 00 00 02") +
                                  rtu("01 03 00 00 00 02") + rtu("01 03 04 00 B4 00 08");
        FrameFinder finder(38400);
        ListenDecoder decoder(&RegisterMap::builtin(), 38400);
        QList<HeardEvent> events;
        for (int i = 0; i < stream.size(); i += 16)
            for (const HeardFrame &f : finder.feed(stream.mid(i, 16), i))
                events << decoder.frame(f);
        // A damaged frame may leave bytes waiting for a long frame: the silence ends them.
        for (const HeardFrame &f : finder.idle(stream.size() + 1000))
            events << decoder.frame(f);
        events << decoder.finish();
        QStringList texts;
        for (const HeardEvent &e : events)
            texts << e.text();
        QVERIFY2(events.size() == 2, qPrintable(texts.join(u'\n')));
        QCOMPARE(events.at(0).kind, HeardEvent::Kind::Write);
        QCOMPARE(events.at(1).kind, HeardEvent::Kind::Read);
        QCOMPARE(finder.stats().damaged, 1);
        QCOMPARE(finder.stats().strayBytes, 1);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestListenDecoder, Guiless)
#include "tst_listendecoder.moc"
