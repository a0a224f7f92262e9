#include "i18n/translators.h"

#include <QCoreApplication>
#include <QTest>

using namespace stepcom;

// The one place every program picks its language: what --lang asks for, what is installed, and
// that the installed catalogue really translates (a message of the core, a list's separator).
class TestTranslators : public QObject
{
    Q_OBJECT

    static QString unknownMessage()
    {
        return Translators::unknownLanguageMessage(QStringLiteral("xx"));
    }

private Q_SLOTS:
    void languageFromArguments_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("language");
        const QString program = QStringLiteral("stepcomctl");
        QTest::newRow("separate value")
            << QStringList{program, QStringLiteral("--lang"), QStringLiteral("zh_CN")}
            << QStringLiteral("zh_CN");
        QTest::newRow("joined value")
            << QStringList{program, QStringLiteral("--lang=en")} << QStringLiteral("en");
        QTest::newRow("among the program's own options")
            << QStringList{program,
                           QStringLiteral("--json"),
                           QStringLiteral("read"),
                           QStringLiteral("--lang"),
                           QStringLiteral("zh_CN"),
                           QStringLiteral("motor1.speed")}
            << QStringLiteral("zh_CN");
        // Passed on as given: the program refuses it with unknownLanguageMessage().
        QTest::newRow("unknown kept as asked")
            << QStringList{program, QStringLiteral("--lang"), QStringLiteral("de")}
            << QStringLiteral("de");
        QTest::newRow("none: the system's")
            << QStringList{program, QStringLiteral("read")} << Translators::systemLanguage();
    }
    void languageFromArguments()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, language);
        QCOMPARE(Translators::languageFromArguments(arguments), language);
    }

    void systemLanguageIsOneStepComSpeaks()
    {
        QVERIFY(Translators::available().contains(Translators::systemLanguage()));
    }

    void unknownLanguageIsRefusedAndChangesNothing()
    {
        Translators translators;
        QVERIFY(translators.install(QStringLiteral("zh_CN")));
        const QString chinese = unknownMessage();
        QVERIFY(!translators.install(QStringLiteral("xx")));
        QVERIFY(!translators.install(QString()));
        QCOMPARE(Translators::current(), QStringLiteral("zh_CN"));
        QCOMPARE(unknownMessage(), chinese);
    }

    void chineseTranslatesAndUninstallBringsEnglishBack()
    {
        const QString english = unknownMessage();
        QCOMPARE(english, QStringLiteral("unknown language 'xx' (known: en, zh_CN)"));
        QCOMPARE(Translators::joinList({QStringLiteral("a"), QStringLiteral("b")}),
                 QStringLiteral("a, b"));
        {
            Translators translators;
            QVERIFY(translators.install(QStringLiteral("zh_CN")));
            QCOMPARE(Translators::current(), QStringLiteral("zh_CN"));
            const QString chinese = unknownMessage();
            QVERIFY2(chinese != english, qPrintable(chinese));
            QVERIFY2(chinese.contains(QStringLiteral("xx")), qPrintable(chinese));
            QCOMPARE(Translators::joinList({QStringLiteral("a"), QStringLiteral("b")}),
                     QStringLiteral("a、b"));
            // A second install replaces the first instead of stacking on it.
            QVERIFY(translators.install(QStringLiteral("en")));
            QCOMPARE(Translators::current(), QStringLiteral("en"));
            QCOMPARE(unknownMessage(), english);
            QVERIFY(translators.install(QStringLiteral("zh_CN")));
        }
        // The translators went with their object.
        QCOMPARE(Translators::current(), QStringLiteral("en"));
        QCOMPARE(unknownMessage(), english);
    }

    void languageOptionIsLang()
    {
        const QCommandLineOption option = Translators::languageOption();
        QCOMPARE(option.names(), QStringList{QStringLiteral("lang")});
        QCOMPARE(option.valueName().isEmpty(), false);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestTranslators, Guiless)
#include "tst_translators.moc"
