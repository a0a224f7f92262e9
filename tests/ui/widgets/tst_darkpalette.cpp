// One visual language: the state colours (statetone.h) stay readable on the style's
// light palette and on a dark one (tests/fixtures/darkpalette.h): the machine strip's words
// and lamps, and the sidebar's marks, keep a WCAG contrast of at least 3:1 against what they
// are drawn on -- disconnected (the unknown grey) and connected (idle, referenced, answering),
// and the status bar's link state.
#include "base/language.h"
#include "darkpalette.h"
#include "pages/checklistpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "simsession.h"
#include "widgets/docks/linkstatus.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/pagesidebar.h"
#include "widgets/fields/led.h"
#include "widgets/fields/statetone.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

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
    QList<QColor> m_backgrounds; // what the checked colours were drawn on

    void check(const QString &what, const QColor &colour, const QColor &background)
    {
        if (!m_backgrounds.contains(background))
            m_backgrounds << background;
        const double ratio = contrastRatio(colour, background);
        if (ratio < kMinContrast)
            m_problems << QStringLiteral("%1: %2 on %3, contrast %4")
                              .arg(what, colour.name(), background.name())
                              .arg(ratio, 0, 'f', 2);
    }

    void checkStrip(MachineStrip *strip, const QString &context)
    {
        for (QLabel *label : strip->findChildren<QLabel *>()) {
            if (!label->isVisible() || label->text().isEmpty())
                continue;
            const QWidget *under = label->parentWidget();
            check(QStringLiteral("%1 strip \"%2\"").arg(context, label->text()),
                  label->palette().color(QPalette::WindowText),
                  under->palette().color(under->backgroundRole()));
        }
        for (Led *led : strip->findChildren<Led *>())
            checkLamp(led, context);
    }

    // A lamp as it is drawn, in each state: lit, filled in a colour that stands out from the
    // window; off and unknown hollow (the window shows through their middle), off inside a ring
    // that stands out: lit and unlit told apart by more than the colour.
    void checkLamp(Led *led, const QString &context)
    {
        if (!led->isVisible())
            return;
        const QWidget *under = led->parentWidget();
        const QColor back = under->palette().color(under->backgroundRole());
        const QString what = QStringLiteral("%1 lamp %2").arg(context, led->objectName());
        const Led::State was = led->state();
        for (const Led::State state : {Led::State::On, Led::State::Off, Led::State::Unknown}) {
            led->setState(state);
            const QImage image = led->grab().toImage();
            const QColor middle = image.pixelColor(image.rect().center());
            double ring = 1.0; // the ring: the strongest contrast across the middle row
            for (int x = 0; x < image.width(); ++x)
                ring = std::max(ring, contrastRatio(image.pixelColor(x, image.height() / 2), back));
            if (state == Led::State::On) {
                check(what + QStringLiteral(" lit"), middle, back);
                check(what + QStringLiteral(" lit, as it says"), led->litColor(), back);
            } else if (contrastRatio(middle, back) > 1.1) {
                m_problems << QStringLiteral("%1 %2: not hollow, its middle is %3 on %4")
                                  .arg(what,
                                       state == Led::State::Off ? QStringLiteral("off")
                                                                : QStringLiteral("unknown"),
                                       middle.name(), back.name());
            }
            if (state == Led::State::Off && ring < kMinContrast)
                m_problems << QStringLiteral("%1 off: its ring has a contrast of %2")
                                  .arg(what)
                                  .arg(ring, 0, 'f', 2);
        }
        led->setState(was);
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
        m_backgrounds.clear();
    }

    // The widgets really are drawn on the palette under test: a check of colours on a palette
    // that never reached them would pass on any palette.
    void requireDrawnOn(const QPalette &palette, const QString &what, const QWidget *widget)
    {
        const QColor seen = widget->palette().color(widget->backgroundRole());
        QVERIFY2(seen == palette.color(QPalette::Window) || seen == palette.color(QPalette::Base),
                 qPrintable(QStringLiteral("%1 is drawn on %2, not on the palette's window %3 or "
                                           "base %4")
                                .arg(what, seen.name(), palette.color(QPalette::Window).name(),
                                     palette.color(QPalette::Base).name())));
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
        requireDrawnOn(palette, QStringLiteral("the window"), &window);
        requireDrawnOn(palette, QStringLiteral("the machine strip"),
                       WindowProbe(window).machineStrip());
        checkStrip(WindowProbe(window).machineStrip(), QStringLiteral("disconnected"));
        PageSidebar *sidebar = WindowProbe(window).sidebar();
        const QColor base = sidebar->viewport()->palette().color(QPalette::Base);
        check(QStringLiteral("sidebar edits"), sidebar->editColour(), base);
        check(QStringLiteral("sidebar page waiting for a controller"), sidebar->offlineColour(),
              base);
        check(QStringLiteral("sidebar checklist"),
              sidebar->progressColour(
                  int(WindowProbe(window).pages().indexOf(WindowProbe(window).checklistPage()))),
              base);
        test::connectToSimulator(session);
        QTRY_VERIFY(session.connection()->linkStats().answers > 0);
        QTRY_VERIFY(WindowProbe(window).machineStrip()->motion(1) != MachineStrip::Motion::Unknown);
        checkStrip(WindowProbe(window).machineStrip(), QStringLiteral("connected"));
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
        // The strip's words were checked on the palette under test's own window colour.
        QVERIFY(m_backgrounds.contains(palette.color(QPalette::Window)));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestDarkPalette, Gui)
#include "tst_darkpalette.moc"
