// Frames found in the bytes of a line heard from the side: packets split anywhere, a stray
// 0x00, a bad CRC, a lost byte, every function code StepCom knows and its exceptions; whatever
// is damaged costs its one frame and the stream finds the next one.
#include "listen/framefinder.h"
#include "listenframes.h"

#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

const QByteArray kRead = rtu("01 03 00 00 00 02");
const QByteArray kReadAnswer = rtu("01 03 04 00 B4 00 08");
const QByteArray kWrite = rtu("01 06 00 05 03 09");
const QByteArray kWriteMany = rtu("02 10 00 06 00 02 04 00 64 00 00");
const QByteArray kWriteManyAnswer = rtu("02 10 00 06 00 02");
const QByteArray kCoil = rtu("01 05 00 29 FF 00");
const QByteArray kInputs = rtu("01 04 00 10 00 01");
const QByteArray kInputsAnswer = rtu("01 04 02 12 34");
const QByteArray kException = rtu("01 83 02");
const QByteArray kCoils = rtu("01 0F 00 00 00 0A 02 FF 03");
const QByteArray kCoilsAnswer = rtu("01 0F 00 00 00 0A");

QList<QByteArray> cut(const QByteArray &bytes, int size)
{
    QList<QByteArray> out;
    for (int i = 0; i < bytes.size(); i += size)
        out << bytes.mid(i, size);
    return out;
}

struct Run
{
    QList<QByteArray> frames;
    FrameFinder::Stats stats;
};

// Each chunk 1 ms after the last (no silence), or `gapMs` before the chunks in `gapsBefore`.
Run feed(const QList<QByteArray> &chunks, const QList<int> &gapsBefore = {}, int gapMs = 100)
{
    FrameFinder finder(38400);
    Run run;
    qint64 ms = 0;
    for (int i = 0; i < chunks.size(); ++i) {
        ms += gapsBefore.contains(i) ? gapMs : 1;
        for (const HeardFrame &f : finder.feed(chunks.at(i), ms))
            run.frames << f.bytes;
    }
    for (const HeardFrame &f : finder.idle(ms + 1000))
        run.frames << f.bytes;
    finder.finish();
    run.stats = finder.stats();
    return run;
}

} // namespace

class TestFrameFinder : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void findsFrames_data()
    {
        QTest::addColumn<QList<QByteArray>>("chunks");
        QTest::addColumn<QList<int>>("gapsBefore");
        QTest::addColumn<QList<QByteArray>>("frames");
        QTest::addColumn<int>("damaged");
        QTest::addColumn<int>("stray");

        const QByteArray all = kRead + kReadAnswer + kWrite + kWrite + kWriteMany +
                               kWriteManyAnswer + kCoil + kCoil + kInputs + kInputsAnswer + kRead +
                               kException + kCoils + kCoilsAnswer;
        const QList<QByteArray> allFrames = {
            kRead, kReadAnswer, kWrite,        kWrite, kWriteMany, kWriteManyAnswer, kCoil,
            kCoil, kInputs,     kInputsAnswer, kRead,  kException, kCoils,           kCoilsAnswer};
        QTest::newRow("every function code in one packet")
            << QList<QByteArray>{all} << QList<int>{} << allFrames << 0 << 0;
        for (const int size : {1, 2, 3, 5, 7, 16, 64})
            QTest::addRow("in %d-byte packets", size)
                << cut(all, size) << QList<int>{} << allFrames << 0 << 0;
        QTest::newRow("a stray 0x00 before the answer")
            << QList<QByteArray>{kRead, QByteArray(1, '\0') + kReadAnswer} << QList<int>{}
            << QList<QByteArray>{kRead, kReadAnswer} << 0 << 1;
        QTest::newRow("a stray 0x00 after a silence")
            << QList<QByteArray>{kRead, QByteArray(1, '\0'), kReadAnswer} << QList<int>{1}
            << QList<QByteArray>{kRead, kReadAnswer} << 0 << 1;
        QTest::newRow("a bad CRC is skipped, the next frame decodes")
            << cut(badCrc("01 03 00 00 00 02") + kWrite + kWrite, 16) << QList<int>{}
            << QList<QByteArray>{kWrite, kWrite} << 1 << 0;
        QTest::newRow("a bad CRC in an answer")
            << QList<QByteArray>{kRead + badCrc("01 03 04 00 B4 00 08") + kRead + kReadAnswer}
            << QList<int>{} << QList<QByteArray>{kRead, kRead, kReadAnswer} << 1 << 0;
        QByteArray lost = kRead;
        lost.remove(3, 1);
        QTest::newRow("a lost byte costs one frame")
            << cut(lost + kReadAnswer + kWrite + kWrite, 16) << QList<int>{}
            << QList<QByteArray>{kReadAnswer, kWrite, kWrite} << 1 << 0;
        QByteArray lostAnswer = kReadAnswer;
        lostAnswer.remove(4, 1);
        QTest::newRow("a lost byte in an answer, then a silence")
            << QList<QByteArray>{kRead, lostAnswer, kRead, kReadAnswer} << QList<int>{2}
            << QList<QByteArray>{kRead, kRead, kReadAnswer} << 1 << 0;
        QTest::newRow("a frame cut short by a silence")
            << QList<QByteArray>{kWriteMany.left(6), kWrite} << QList<int>{1}
            << QList<QByteArray>{kWrite} << 1 << 0;
        QTest::newRow("an unknown function code is no frame")
            << QList<QByteArray>{rtu("01 2B 0E 01 00") + kWrite} << QList<int>{}
            << QList<QByteArray>{kWrite} << 1 << 0;
        QTest::newRow("a request whose answer never comes")
            << QList<QByteArray>{kRead, kRead} << QList<int>{1} << QList<QByteArray>{kRead, kRead}
            << 0 << 0;
    }

    void findsFrames()
    {
        QFETCH(QList<QByteArray>, chunks);
        QFETCH(QList<int>, gapsBefore);
        QFETCH(QList<QByteArray>, frames);
        QFETCH(int, damaged);
        QFETCH(int, stray);
        const Run run = feed(chunks, gapsBefore);
        QCOMPARE(run.frames, frames);
        QCOMPARE(run.stats.frames, qint64(frames.size()));
        QCOMPARE(run.stats.damaged, qint64(damaged));
        QCOMPARE(run.stats.strayBytes, qint64(stray));
    }

    // A frame is handed on when its last byte is in, not at the next silence.
    void aFrameIsFoundAtItsLastByte()
    {
        FrameFinder finder(9600);
        QVERIFY(finder.feed(kWriteMany.left(kWriteMany.size() - 1), 10).isEmpty());
        const QList<HeardFrame> out = finder.feed(kWriteMany.right(1), 11);
        QCOMPARE(out.size(), 1);
        QCOMPARE(out.first().bytes, kWriteMany);
        QCOMPARE(out.first().ms, 11);
        QCOMPARE(finder.held(), 0);
    }

    void candidateLengths_data()
    {
        QTest::addColumn<QByteArray>("start");
        QTest::addColumn<QList<int>>("lengths");
        QTest::newRow("nothing yet") << QByteArray() << QList<int>{0};
        QTest::newRow("unit past 247") << QByteArray::fromHex("F8") << QList<int>{};
        QTest::newRow("FC03 without its count") << QByteArray::fromHex("0103") << QList<int>{0, 8};
        QTest::newRow("FC03 answer of 2 registers")
            << QByteArray::fromHex("010304") << QList<int>{8, 9};
        QTest::newRow("FC03 odd byte count is a request only")
            << QByteArray::fromHex("010303") << QList<int>{8};
        QTest::newRow("FC06") << QByteArray::fromHex("0106") << QList<int>{8};
        QTest::newRow("FC05 with a value no coil takes")
            << QByteArray::fromHex("010500291234") << QList<int>{};
        QTest::newRow("FC10 request of 2 registers")
            << QByteArray::fromHex("01100006000204") << QList<int>{8, 13};
        QTest::newRow("FC10 with a byte count that does not fit")
            << QByteArray::fromHex("01100006000205") << QList<int>{8};
        QTest::newRow("exception") << QByteArray::fromHex("0183") << QList<int>{5};
        QTest::newRow("exception of an unknown code")
            << QByteArray::fromHex("01AB") << QList<int>{};
        QTest::newRow("function 0") << QByteArray::fromHex("0100") << QList<int>{};
    }

    void candidateLengths()
    {
        QFETCH(QByteArray, start);
        QFETCH(QList<int>, lengths);
        QCOMPARE(FrameFinder::candidateLengths(start), lengths);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestFrameFinder, Guiless)
#include "tst_framefinder.moc"
