// Help on demand: a page shows values and actions; explanations live in tooltips,
// What's This (Shift+F1), the guide (F1) and the "About this page" boxes, which start closed.
// Walks every page of the window, disconnected and connected to the simulator, in English and
// Chinese, and fails on any label shown by default that holds a paragraph of more than
// kMaxWords words. Words are counted as docs/ui-style.md says: a run of letters or digits
// between spaces is one word; Chinese, Japanese and Korean characters count one half each.
#include "base/language.h"
#include "base/page.h"
#include "help/guidewindow.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "simsession.h"
#include "widgets/fields/aboutbox.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QTextDocument>
#include <QToolButton>

using namespace stepcom;

namespace {

constexpr double kMaxWords = 40;

bool isCjk(QChar c)
{
    const char16_t u = c.unicode();
    return (u >= 0x3400 && u <= 0x9fff) || (u >= 0x3040 && u <= 0x30ff) ||
           (u >= 0xac00 && u <= 0xd7af) || (u >= 0xf900 && u <= 0xfaff);
}

// The rule (docs/ui-style.md).
double paragraphWords(const QString &text)
{
    double words = 0;
    bool inWord = false;
    for (const QChar c : text) {
        if (isCjk(c)) {
            words += 0.5;
            inWord = false;
        } else if (c.isLetterOrNumber()) {
            words += inWord ? 0 : 1;
            inWord = true;
        } else if (c.isSpace()) {
            inWord = false;
        }
    }
    return words;
}

} // namespace

class TestHelpOnDemand : public QObject
{
    Q_OBJECT

    static QString plain(const QLabel *label)
    {
        QString text = label->text();
        if (Qt::mightBeRichText(text)) {
            QTextDocument doc;
            doc.setHtml(text);
            text = doc.toPlainText();
        }
        return text;
    }

    static void settle()
    {
        for (int round = 0; round < 5; ++round) {
            QCoreApplication::sendPostedEvents();
            QCoreApplication::processEvents();
        }
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QSettings().clear();
    }

    void wordsAreCounted_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<double>("words");
        QTest::newRow("empty") << QString() << 0.0;
        QTest::newRow("english") << QStringLiteral("Jog the motor, then home it.") << 6.0;
        QTest::newRow("numbers and units") << QStringLiteral("Speed 1200 steps/s") << 3.0;
        QTest::newRow("chinese") << QStringLiteral("点动电机，然后回零。") << 4.0;
        QTest::newRow("mixed") << QStringLiteral("写入 IN1 的设置") << 3.5;
    }
    void wordsAreCounted()
    {
        QFETCH(QString, text);
        QFETCH(double, words);
        QCOMPARE(paragraphWords(text), words);
    }

    void noLongParagraphShown_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<bool>("connected");
        for (const char *lang : {"en", "zh_CN"}) {
            for (const bool connected : {false, true})
                QTest::addRow("%s %s", lang, connected ? "connected" : "disconnected")
                    << QString::fromLatin1(lang) << connected;
        }
    }
    void noLongParagraphShown()
    {
        QFETCH(QString, language);
        QFETCH(bool, connected);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        if (connected) {
            test::connectToSimulator(session);
            QTRY_VERIFY(session.connection()->linkStats().answers > 0);
        }
        QStringList problems;
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i) {
            WindowProbe(window).showPage(i);
            settle();
            for (QLabel *label : window.findChildren<QLabel *>()) {
                if (!label->isVisible())
                    continue;
                const QString text = plain(label);
                if (const double words = paragraphWords(text); words > kMaxWords)
                    problems << QStringLiteral("%1: %2 words: %3…")
                                    .arg(WindowProbe(window).pages().at(i)->title())
                                    .arg(words)
                                    .arg(text.left(70));
            }
        }
        problems.removeDuplicates();
        QVERIFY2(problems.isEmpty(),
                 qPrintable(QLatin1Char('\n') + problems.join(QLatin1Char('\n'))));
    }

    // Every "About this page" starts closed, and opens and closes again from its button.
    void aboutBoxesStartClosed()
    {
        Language::instance().setLanguage(QStringLiteral("en"));
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QList<AboutBox *> boxes = window.findChildren<AboutBox *>();
        QVERIFY(!boxes.isEmpty());
        for (AboutBox *box : boxes) {
            QVERIFY2(!box->isOpen(), qPrintable(box->text()));
            QVERIFY(!box->text().isEmpty());
            QVERIFY(!box->whatsThis().isEmpty());
            QCOMPARE(box->button()->accessibleName(), QStringLiteral("About this page"));
        }
        AboutBox *box = boxes.first();
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i) {
            if (WindowProbe(window).pages().at(i)->isAncestorOf(box))
                WindowProbe(window).showPage(i);
        }
        QVERIFY(box->isVisible());
        QVERIFY(!box->guideButton()->isVisible());
        box->button()->click();
        QVERIFY(box->isOpen());
        // More than the box says: the guide, at the page.
        QVERIFY(box->guideButton()->isVisible());
        box->guideButton()->click();
        GuideWindow *guide = window.findChild<GuideWindow *>();
        QVERIFY(guide);
        QTRY_VERIFY(guide->isVisible());
        guide->close();
        box->button()->click();
        QVERIFY(!box->isOpen());
        QVERIFY(!box->guideButton()->isVisible());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestHelpOnDemand, Gui)
#include "tst_helpondemand.moc"
