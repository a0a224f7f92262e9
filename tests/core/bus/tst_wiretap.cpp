#include "bus/wiretap.h"

#include <QTest>

using namespace stepcom;

// The exact lines QtSerialBus 6.4.2 logs; if a Qt update changes them, this fails first.
class TestWireTap : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_data()
    {
        QTest::addColumn<QString>("message");
        QTest::addColumn<bool>("isFrame");
        QTest::addColumn<int>("frame");
        QTest::addColumn<QByteArray>("raw");
        QTest::newRow("rtu sent") << "(RTU client) Sent Serial ADU: 0x010300000002c40b" << true
                                  << int(WireTap::Frame::RtuSent)
                                  << QByteArray::fromHex("010300000002c40b");
        QTest::newRow("rtu received")
            << "(RTU client) Received ADU: \"01030400b40008bbd3\"" << true
            << int(WireTap::Frame::RtuReceived) << QByteArray::fromHex("01030400b40008bbd3");
        QTest::newRow("rtu partial buffer")
            << "(RTU client) Response buffer: \"0103\"" << false << 0 << QByteArray();
        QTest::newRow("tcp sent") << "(TCP client) Sent TCP ADU: \"000000000006010300000001\""
                                  << true << int(WireTap::Frame::TcpSent)
                                  << QByteArray::fromHex("000000000006010300000001");
        QTest::newRow("tcp received")
            << "(TCP client) Response buffer: \"00000000000501030200b4\"" << true
            << int(WireTap::Frame::TcpReceived) << QByteArray::fromHex("00000000000501030200b4");
        QTest::newRow("pdu line") << "(TCP client) Sent TCP PDU: 0x0300000001 with tId: 0" << false
                                  << 0 << QByteArray();
        QTest::newRow("other") << "(RTU client) Receive timeout: 0x0300000001" << false << 0
                               << QByteArray();
    }
    void parse()
    {
        QFETCH(QString, message);
        QFETCH(bool, isFrame);
        QFETCH(int, frame);
        QFETCH(QByteArray, raw);
        WireTap::Frame f{};
        QByteArray bytes;
        QCOMPARE(WireTap::parse(message, &f, &bytes), isFrame);
        if (isFrame) {
            QCOMPARE(int(f), frame);
            QCOMPARE(bytes, raw);
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestWireTap, Guiless)
#include "tst_wiretap.moc"
