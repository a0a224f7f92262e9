#include "pendant/pendantgate.h"
#include "pendant/pendantpage.h"
#include "pendant/pendantserver.h"
#include "testregistry.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTest>

using namespace stepcom;

// Pairing by token and the refusal of an address that guesses; the pendant's address option.
class TestPendantGate : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void tokenIs128RandomBitsNewEachTime()
    {
        PendantGate gate;
        const QString first = gate.token();
        QCOMPARE(first.size(), 32);
        QVERIFY(QRegularExpression(QStringLiteral("^[0-9a-f]{32}$")).match(first).hasMatch());
        gate.renew();
        QVERIFY(gate.token() != first);
        QVERIFY(gate.admit(QStringLiteral("10.0.0.2"), gate.token()));
        QVERIFY(!gate.admit(QStringLiteral("10.0.0.2"), first));
        QVERIFY(!gate.admit(QStringLiteral("10.0.0.2"), QString()));
        QVERIFY(!gate.admit(QStringLiteral("10.0.0.2"), gate.token().left(31)));
    }

    void tenWrongTokensInAMinuteRefuseTheAddressForAMinute()
    {
        qint64 now = 1'000'000;
        PendantGate gate([&now] { return now; });
        const QString bad = QStringLiteral("192.168.1.50");
        const QString good = QStringLiteral("192.168.1.23");
        for (int i = 0; i < 9; ++i) {
            QVERIFY(!gate.admit(bad, QStringLiteral("guess%1").arg(i)));
            now += 1000;
        }
        QVERIFY(!gate.isRefused(bad));
        QVERIFY(gate.admit(bad, gate.token())); // nine wrong: still let in with the token
        QVERIFY(!gate.admit(bad, QStringLiteral("guess9")));
        QVERIFY(gate.isRefused(bad));
        QVERIFY(!gate.admit(bad, gate.token())); // refused, right token or not
        QVERIFY(gate.admit(good, gate.token())); // another address is not
        now += PendantGate::kRefusedMs - 1;
        QVERIFY(!gate.admit(bad, gate.token()));
        now += 1;
        QVERIFY(gate.admit(bad, gate.token()));
    }

    void wrongTokensOlderThanAMinuteAreForgotten()
    {
        qint64 now = 0;
        PendantGate gate([&now] { return now; });
        const QString a = QStringLiteral("10.1.1.1");
        for (int i = 0; i < 20; ++i) {
            QVERIFY(!gate.admit(a, QStringLiteral("x")));
            now += 7000; // 9 in any minute, never 10
        }
        QVERIFY(!gate.isRefused(a));
    }

    void listenOption_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("address");
        QTest::addColumn<int>("port");
        QTest::addColumn<QString>("error");
        QTest::newRow("port") << "8470" << true << "0.0.0.0" << 8470 << "";
        QTest::newRow("loopback any port") << "127.0.0.1:0" << true << "127.0.0.1" << 0 << "";
        QTest::newRow("ipv6") << "[::1]:9000" << true << "::1" << 9000 << "";
        QTest::newRow("no port") << "127.0.0.1:" << false << "" << 0 << "port must be a number";
        QTest::newRow("too big") << "70000" << false << "" << 0 << "port must be a number";
        QTest::newRow("bad host") << "phone:80" << false << "" << 0 << "'phone' is not an IP";
    }
    void listenOption()
    {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(QString, address);
        QFETCH(int, port);
        QFETCH(QString, error);
        QHostAddress parsed;
        quint16 parsedPort = 1;
        QString said;
        QCOMPARE(PendantServer::parseListen(text, &parsed, &parsedPort, &said), ok);
        if (ok) {
            QCOMPARE(parsed.toString(),
                     parsed == QHostAddress(QHostAddress::Any)
                         ? (address == QLatin1String("0.0.0.0") ? parsed.toString() : address)
                         : address);
            QCOMPARE(int(parsedPort), port);
            QVERIFY(said.isEmpty());
        } else {
            QVERIFY2(said.contains(error), qPrintable(said));
            QVERIFY2(said.contains(text), qPrintable(said)); // it names what was typed
        }
    }

    void pageWordsFollowTheBrowsersLanguage()
    {
        QCOMPARE(PendantPage::languageOf("zh-CN,zh;q=0.9,en;q=0.8"), QStringLiteral("zh_CN"));
        QCOMPARE(PendantPage::languageOf("en-US,en;q=0.9,zh;q=0.8"), QStringLiteral("en"));
        QCOMPARE(PendantPage::languageOf(""), QStringLiteral("en"));
        const auto zh =
            QJsonDocument::fromJson(PendantPage::strings(QStringLiteral("zh_CN"))).object();
        const auto en =
            QJsonDocument::fromJson(PendantPage::strings(QStringLiteral("en"))).object();
        QCOMPARE(en.value(QStringLiteral("estop")).toString(), QStringLiteral("E-STOP"));
        QCOMPARE(en.value(QStringLiteral("m1fwd")).toString(), QStringLiteral("Motor 1 forward"));
        // Every word has its Chinese (from the .ts files, as the window's).
        for (auto it = en.begin(); it != en.end(); ++it) {
            if (it.key() == QLatin1String("lang"))
                continue;
            QVERIFY2(zh.value(it.key()).toString() != it.value().toString(), qPrintable(it.key()));
        }
    }
};

STEPCOM_TEST(TestPendantGate, Guiless)
#include "tst_pendantgate.moc"
