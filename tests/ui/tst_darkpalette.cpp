// Issue 25, one visual language: the state colours (statetone.h) stay readable on the style's
// light palette and on a dark one (tests/support/darkpalette.h): the machine strip's words
// and lamps, and the sidebar's marks, keep a WCAG contrast of at least 3:1 against what they
// are drawn on -- disconnected (the unknown grey) and connected (idle, referenced, answering),
// and the status bar's link state.
#include "darkpalette.h"
#include "language.h"
#include "mainwindow.h"
#include "pages/checklistpage.h"
#include "session/devicesession.h"
#include "simsession.h"
#include "widgets/docks/linkstatus.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/pagesidebar.h"
#include "widgets/fields/led.h"
#include "widgets/fields/statetone.h"

#include <QApplication>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QStyle>
#include <QTest>

using namespace stepcom;

class TestDarkPalette : public QObject
{
    Q_OBJECT
    QStringList m_problems;

    void check(const QString &what, const QColor &colour, const QColor &background)
    {
        const double ratio = contrastRatio(colour, background);
        if (ratio < kMinContrast)
            m_problems << QStringLiteral("%1: %2 on %3, contrast %4")
                              .arg(what, colour.name(), background.name())
                              .arg(ratio, 0, 'f', 2);
    }

    void checkStrip(MachineStrip *strip, const QString &context, bool lamps)
    {
        for (QLabel *label : strip->findChildren<QLabel *>()) {
            if (!label->isVisible() || label->text().isEmpty())
                continue;
            const QWidget *under = label->parentWidget();
            check(QStringLiteral("%1 strip \"%2\"").arg(context, label->text()),
                  label->palette().color(QPalette::WindowText),
                  under->palette().color(under->backgroundRole()));
        }
        // The lamps keep their bright green on a light window (a lit lamp, framed); on a dark one
        // they must stand out from the window and from an unlit lamp.
        for (Led *led : lamps ? strip->findChildren<Led *>() : QList<Led *>()) {
            const QWidget *under = led->parentWidget();
            const QColor back = under->palette().color(under->backgroundRole());
            check(context + QStringLiteral(" lamp frame"),
                  led->palette().color(QPalette::WindowText), back);
            check(context + QStringLiteral(" lamp on"), led->onColor(), back);
            // On and off told apart by more than the hue.
            check(context + QStringLiteral(" lamp on against off"), led->onColor(),
                  led->palette().color(QPalette::Mid));
        }
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QSettings().clear();
        Language::instance().setLanguage(QStringLiteral("en"));
    }
    void cleanup()
    {
        QApplication::setPalette(QApplication::style()->standardPalette());
        m_problems.clear();
    }

    void stateColoursKeepContrast_data()
    {
        QTest::addColumn<bool>("dark");
        QTest::newRow("light") << false;
        QTest::newRow("dark") << true;
    }
    void stateColoursKeepContrast()
    {
        QFETCH(bool, dark);
        const QPalette palette =
            dark ? test::darkPalette() : QApplication::style()->standardPalette();
        QApplication::setPalette(palette);
        // Every tone, on a window and on a list's base.
        for (const auto role : {QPalette::Window, QPalette::Base}) {
            for (const StateTone tone : {StateTone::Normal, StateTone::Good, StateTone::Running,
                                         StateTone::Warning, StateTone::Fault, StateTone::Unknown})
                check(QStringLiteral("tone %1 on role %2").arg(int(tone)).arg(int(role)),
                      stateColour(tone, palette, role), palette.color(role));
        }
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        checkStrip(window.machineStrip(), QStringLiteral("disconnected"), dark);
        PageSidebar *sidebar = window.sidebar();
        const QColor base = sidebar->viewport()->palette().color(QPalette::Base);
        check(QStringLiteral("sidebar edits"), sidebar->editColour(), base);
        check(QStringLiteral("sidebar page waiting for a controller"), sidebar->offlineColour(),
              base);
        check(QStringLiteral("sidebar checklist"),
              sidebar->progressColour(int(window.pages().indexOf(window.checklistPage()))), base);
        test::connectToSimulator(session);
        QTRY_VERIFY(session.linkStats().answers > 0);
        QTRY_VERIFY(window.machineStrip()->motion(1) != MachineStrip::Motion::Unknown);
        checkStrip(window.machineStrip(), QStringLiteral("connected"), dark);
        // The status bar says the link's state in the same colours.
        auto *link = window.findChild<LinkStatus *>();
        QVERIFY(link);
        for (QLabel *label : link->findChildren<QLabel *>()) {
            if (label->isVisible() && label->text() == link->stateText())
                check(QStringLiteral("status bar \"%1\"").arg(label->text()),
                      label->palette().color(QPalette::WindowText),
                      link->palette().color(link->backgroundRole()));
        }
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QLatin1Char('\n') + m_problems.join(QLatin1Char('\n'))));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDarkPalette, Gui)
#include "tst_darkpalette.moc"
