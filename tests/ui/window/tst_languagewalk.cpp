#include "base/language.h"
#include "base/page.h"
#include "pages/motionpage.h"
#include "session/devicesession.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/messageview.h"
#include "widgets/docks/trafficview.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/jogpanel.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTest>

#include <memory>

using namespace stepcom;

// After a live language switch every text shown is in the new language -- states,
// outcomes, reasons, banners -- on every page, back and forth. Logs (messages, traffic) are
// history and keep the language they were written in.
class TestLanguageWalk : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<MainWindow> window;

    bool insideLog(const QWidget *w) const
    {
        for (const QWidget *p = w; p; p = p->parentWidget()) {
            if (qobject_cast<const MessageView *>(p) || qobject_cast<const TrafficView *>(p))
                return true;
        }
        return false;
    }

    // Every text a person can see on the current page, the docks and the status bar.
    QStringList visibleTexts() const
    {
        QStringList texts;
        for (QWidget *w : window->findChildren<QWidget *>()) {
            if (!w->isVisible() || insideLog(w))
                continue;
            if (auto *l = qobject_cast<QLabel *>(w))
                texts << l->text();
            else if (auto *b = qobject_cast<QAbstractButton *>(w))
                texts << b->text();
            else if (auto *g = qobject_cast<QGroupBox *>(w))
                texts << g->title();
            else if (auto *c = qobject_cast<QComboBox *>(w))
                texts << c->currentText();
            else if (auto *t = qobject_cast<QTabWidget *>(w)) {
                for (int i = 0; i < t->count(); ++i)
                    texts << t->tabText(i);
            } else if (auto *d = qobject_cast<QDockWidget *>(w))
                texts << d->windowTitle();
        }
        texts << window->statusBar()->currentMessage() << window->windowTitle();
        texts.removeAll(QString());
        return texts;
    }

    // Chinese text while the window speaks English.
    static QStringList chineseIn(const QStringList &texts)
    {
        static const QRegularExpression han(QStringLiteral("[\\x{4e00}-\\x{9fff}]"));
        QStringList found;
        for (const QString &t : texts) {
            if (han.match(t).hasMatch())
                found << t;
        }
        return found;
    }

    // English sentences while the window speaks Chinese: two English words in a row, once the
    // names that stay English in Chinese (protocols, units, keys, paths) are taken out.
    static QStringList englishIn(const QStringList &texts)
    {
        static const QRegularExpression keep(QStringLiteral(
            "Modbus|RTU|TCP|RS-485|RS-232|E-STOP|StepCom|stepcomctl|CSV|PDF|HTML|USB|"
            "/dev/\\S*|\\b[a-z0-9_]+\\.[a-z0-9_.]+\\b|\\brpm\\b|\\bmm\\b|\\bHz\\b|\\bbaud\\b|"
            "\\bIN\\d\\b|\\bOUT\\d\\b|<[^>]*>|&[a-z]+;|English|localhost|\\bms\\b"));
        static const QRegularExpression sentence(QStringLiteral("[A-Za-z]{3,}[ ,]+[A-Za-z]{3,}"));
        QStringList found;
        for (QString t : texts) {
            t.remove(keep);
            if (sentence.match(t).hasMatch())
                found << t;
        }
        return found;
    }

    QStringList walk(bool english)
    {
        QStringList problems;
        for (int i = 0; i < WindowProbe(*window).pages().size(); ++i) {
            WindowProbe(*window).showPage(i);
            QCoreApplication::processEvents();
            const QStringList bad = english ? chineseIn(visibleTexts()) : englishIn(visibleTexts());
            for (const QString &b : bad)
                problems << QStringLiteral("%1: %2").arg(
                    WindowProbe(*window).pages().at(i)->title(), b);
        }
        problems.removeDuplicates();
        return problems;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
        session = std::make_unique<DeviceSession>();
        window = std::make_unique<MainWindow>(session.get());
        window->resize(1366, 900);
        window->show();
        test::connectToSimulator(*session);
    }
    void cleanupTestCase()
    {
        Language::instance().setLanguage(QStringLiteral("en"));
        window.reset();
        session.reset();
    }

    void everyPageInBothLanguages()
    {
        // State worth translating: a judged homing, a refused value, an edit.
        JogPanel *panel = WindowProbe(*window).motionPage()->panel(1);
        WindowProbe(*window).showPage(
            WindowProbe(*window).pages().indexOf(WindowProbe(*window).motionPage()));
        QTRY_VERIFY(panel->homeButton()->isEnabled());
        panel->homeButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(panel->statusText().contains(QLatin1String("referenced")), 10000);
        for (ParameterField *f : window->findChildren<ParameterField *>()) {
            if (f->parameter().key == QLatin1String("motor1.speed"))
                f->enterText(QStringLiteral("99999"));
            if (f->parameter().key == QLatin1String("motor2.speed"))
                f->enterText(QStringLiteral("450"));
        }
        QStringList english = walk(true);
        QVERIFY2(english.isEmpty(), qPrintable(english.join(QLatin1Char('\n'))));

        for (int round = 0; round < 2; ++round) {
            QVERIFY(Language::instance().setLanguage(QStringLiteral("zh_CN")));
            const QStringList chinese = walk(false);
            QVERIFY2(chinese.isEmpty(), qPrintable(chinese.join(QLatin1Char('\n'))));
            QVERIFY(Language::instance().setLanguage(QStringLiteral("en")));
            english = walk(true);
            QVERIFY2(english.isEmpty(), qPrintable(english.join(QLatin1Char('\n'))));
        }
        // The judged outcome was made again in each language, not kept as text.
        QVERIFY(panel->statusText().contains(QLatin1String("Homing motor 1: referenced")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestLanguageWalk, Gui)
#include "tst_languagewalk.moc"
