// Help in the window: every F1 target is a heading of BOTH guides, each page's F1 opens the guide
// in the window's language at that page's section, links between sections work, and "What's
// this" on a parameter gives the register map's help.
#include "base/language.h"
#include "base/page.h"
#include "help/guidewindow.h"
#include "help/userguide.h"
#include "session/devicesession.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QFile>
#include <QLabel>
#include <QStandardPaths>
#include <QTest>
#include <QTextBrowser>
#include <QTextDocument>

using namespace stepcom;

namespace {

QString sourceGuide(const QString &language)
{
    return QStringLiteral(STEPCOM_SOURCE_DIR "/docs/") + UserGuide::fileName(language);
}

std::unique_ptr<QTextDocument> loadMarkdown(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return nullptr;
    auto doc = std::make_unique<QTextDocument>();
    doc->setMarkdown(QString::fromUtf8(f.readAll()));
    return doc;
}

} // namespace

class TestUserGuide : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
    }
    void cleanup() { Language::instance().setLanguage(QStringLiteral("en")); }

    void everyTargetIsAHeadingOfBothGuides_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void everyTargetIsAHeadingOfBothGuides()
    {
        QFETCH(QString, language);
        const auto doc = loadMarkdown(sourceGuide(language));
        QVERIFY2(doc, qPrintable(sourceGuide(language)));
        QVERIFY(UserGuide::findHeading(*doc, UserGuide::title(language)).isValid());
        for (const QString &topic : UserGuide::topics()) {
            const QString heading = UserGuide::heading(topic, language);
            QVERIFY2(UserGuide::findHeading(*doc, heading).isValid(),
                     qPrintable(topic + QStringLiteral(": no heading '") + heading +
                                QStringLiteral("' in ") + sourceGuide(language)));
        }
    }

    // Run from the build, the window shows the source tree's guide; the guide's own
    // "#anchor" links resolve to its headings.
    void findsTheGuideOfEachLanguage()
    {
        QCOMPARE(UserGuide::file(QStringLiteral("en")), sourceGuide(QStringLiteral("en")));
        QCOMPARE(UserGuide::file(QStringLiteral("zh_CN")), sourceGuide(QStringLiteral("zh_CN")));
        QCOMPARE(UserGuide::anchor(QStringLiteral("The serial port permission trap (Linux)")),
                 QStringLiteral("the-serial-port-permission-trap-linux"));
        QCOMPARE(UserGuide::anchor(QStringLiteral("Linux 串口权限问题")),
                 QStringLiteral("linux-串口权限问题"));
    }

    // F1 on every page opens the guide at the page's own section, in the window's language.
    void f1OnEveryPage_data() { everyTargetIsAHeadingOfBothGuides_data(); }
    void f1OnEveryPage()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QAction *help = WindowProbe(window).action(QStringLiteral("userGuide"));
        QVERIFY(help);
        QCOMPARE(help->shortcut(), QKeySequence(QKeySequence::HelpContents));
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i) {
            WindowProbe(window).showPage(i);
            const QString topic =
                QString::fromLatin1(WindowProbe(window).pages().at(i)->metaObject()->className());
            QVERIFY2(UserGuide::topics().contains(topic), qPrintable(topic + " has no section"));
            help->trigger();
            auto *guide = window.findChild<GuideWindow *>();
            QVERIFY(guide);
            QVERIFY(guide->isVisible());
            QCOMPARE(guide->file(), sourceGuide(language));
            QCOMPARE(guide->currentHeading(), UserGuide::heading(topic, language));
            // The window's title is the page and nothing else (the platform adds the program).
            QCOMPARE(window.windowTitle(), WindowProbe(window).pages().at(i)->title());
        }
        // Pictures are found beside the guide.
        auto *guide = window.findChild<GuideWindow *>();
        const QVariant picture = guide->browser()->document()->resource(
            QTextDocument::ImageResource,
            QUrl(language == QLatin1String("en")
                     ? QStringLiteral("images/en/01-connectionPage.png")
                     : QStringLiteral("images/zh_CN/01-connectionPage.png")));
        QVERIFY(picture.isValid());
    }

    void linksBetweenSections()
    {
        DeviceSession session;
        MainWindow window(&session);
        GuideWindow *guide = WindowProbe(window).openGuide();
        QCOMPARE(guide->currentHeading(), QStringLiteral("The Connection page"));
        Q_EMIT guide->browser()->anchorClicked(
            QUrl(QStringLiteral("#the-serial-port-permission-trap-linux")));
        QCOMPARE(guide->currentHeading(),
                 QStringLiteral("The serial port permission trap (Linux)"));
    }

    void unknownTopicOpensAtTheTitle()
    {
        GuideWindow guide;
        QVERIFY(guide.showTopic(QStringLiteral("no such page"), QStringLiteral("zh_CN")));
        QCOMPARE(guide.currentHeading(), QStringLiteral("StepCom 使用手册"));
    }

    // "What's this" on a parameter's name or field: the map's help, in the window's language.
    void whatsThisOnParameters()
    {
        DeviceSession session;
        MainWindow window(&session);
        QVERIFY(WindowProbe(window).action(QStringLiteral("whatsThis")));
        const auto fields = window.findChildren<ParameterField *>();
        QVERIFY(!fields.isEmpty());
        int withForm = 0;
        for (ParameterField *f : fields) {
            if (!qobject_cast<ParameterForm *>(f->parentWidget()))
                continue;
            ++withForm;
            const QString help = f->parameter().help.text(QStringLiteral("en")).toHtmlEscaped();
            QVERIFY2(f->whatsThis().contains(help), qPrintable(f->parameter().key));
        }
        QVERIFY(withForm > 10);
        Language::instance().setLanguage(QStringLiteral("zh_CN"));
        for (ParameterField *f : fields) {
            if (qobject_cast<ParameterForm *>(f->parentWidget()))
                QVERIFY2(f->whatsThis().contains(
                             f->parameter().help.text(QStringLiteral("zh_CN")).toHtmlEscaped()),
                         qPrintable(f->parameter().key));
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestUserGuide, Gui)
#include "tst_userguide.moc"
