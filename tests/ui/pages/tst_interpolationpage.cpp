#include "base/language.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "pages/interpolationpage.h"
#include "pages/modespage.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"
#include "widgets/motion/patheditor.h"
#include "widgets/plots/interpolationpreview.h"
#include "widgets/plots/xyplot.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include "darkpalette.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QWidget>

#include <memory>

using namespace stepcom;

// The Interpolation and Special modes pages against the built-in simulator, offscreen.
class TestInterpolationPage : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    qint64 simValue(const QString &key) const { return sim()->value(key).value_or(-99999); }
    void connectSim() { test::connectToSimulator(*session); }
    static void enter(PathEditor *e, const QString &key, const QString &text)
    {
        ParameterField *f = e->form()->field(key);
        QVERIFY2(f, qPrintable(key));
        f->enterText(text);
    }
    // Writes the editor's edits through its write dialog, as a user does.
    void writeThroughDialog(PathEditor *e)
    {
        QTRY_VERIFY(e->writeButton()->isEnabled());
        QVERIFY(!e->startButton()->isEnabled());
        QVERIFY(e->startReason()->text().contains(QStringLiteral("not written")));
        e->writeButton()->click();
        QVERIFY(e->writeDialog());
        QVERIFY(!e->writeDialog()->writes().isEmpty());
        for (const ParameterWrite &w : e->writeDialog()->writes())
            QVERIFY(e->keys().contains(w.parameter->key)); // only this editor's values
        e->writeDialog()->accept();
        QTRY_VERIFY_WITH_TIMEOUT(!session->parameters()->store()->hasEdits(), 10000);
    }
    // Non-background pixels inside the plot area of the preview.
    static int drawnPixels(InterpolationPreview *preview)
    {
        preview->plot()->flush();
        const QImage image = preview->plot()->grab().toImage();
        const QRect area = preview->plot()->chart()->plotArea().toRect().adjusted(2, 2, -2, -2);
        const QRgb background = preview->plot()->palette().color(QPalette::Base).rgb();
        int count = 0;
        for (int y = area.top(); y <= area.bottom(); ++y) {
            for (int x = area.left(); x <= area.right(); ++x) {
                const QColor c = image.pixelColor(x, y);
                const QColor b(background);
                if (std::abs(c.red() - b.red()) + std::abs(c.green() - b.green()) +
                        std::abs(c.blue() - b.blue()) >
                    60)
                    ++count;
            }
        }
        return count;
    }
    void runToEnd(PathEditor *e, InterpolationPreview *preview, qint64 endX, qint64 endY)
    {
        QTRY_VERIFY_WITH_TIMEOUT(e->startButton()->isEnabled(), 10000);
        QVERIFY2(e->startReason()->text().startsWith(QStringLiteral("Ready")),
                 qPrintable(e->startReason()->text()));
        e->startButton()->click();
        QVERIFY(!e->startButton()->isEnabled()); // no second start before the poll sees it
        QTRY_VERIFY_WITH_TIMEOUT(sim()->running(1) || sim()->running(2), 5000);
        QTRY_VERIFY(!e->startButton()->isEnabled()); // a motor moves
        QVERIFY(e->stopButton()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!sim()->running(1) && !sim()->running(2), 30000);
        QCOMPARE(sim()->position(1), endX);
        QCOMPARE(sim()->position(2), endY);
        // The live run was traced over the preview, up to the end point.
        QTRY_VERIFY_WITH_TIMEOUT(preview->plot()->marker() &&
                                     std::abs(preview->plot()->marker()->x() - endX / 100.0) <
                                         1e-6 &&
                                     std::abs(preview->plot()->marker()->y() - endY / 100.0) < 1e-6,
                                 10000);
        // (How many points lie before it depends on how often the poll came round while it
        // ran: on a busy computer the whole run may fall between two polls.)
        QVERIFY2(preview->plot()->traceCount() >= 1,
                 qPrintable(QString::number(preview->plot()->traceCount())));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
    }
    void init() { session = std::make_unique<DeviceSession>(); }
    void cleanup() { session.reset(); }

    void arcRunsToItsEnd_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("direction");
        QTest::newRow("centre, counter-clockwise") << 0 << 1;
        QTest::newRow("three points, clockwise") << 1 << 0;
    }
    void arcRunsToItsEnd()
    {
        QFETCH(int, mode);
        QFETCH(int, direction);
        InterpolationPage page(session.get());
        page.resize(1400, 900);
        page.show();
        PathEditor *arc = page.arcEditor();
        QVERIFY(!arc->startButton()->isEnabled());
        QVERIFY(!arc->stopButton()->isEnabled());
        QCOMPARE(arc->startReason()->text(), QStringLiteral("Not connected."));
        connectSim();
        QVERIFY(arc->stopButton()->isEnabled());

        enter(arc, QStringLiteral("arc.enabled"), QStringLiteral("1"));
        enter(arc, QStringLiteral("arc.mode"), QString::number(mode));
        enter(arc, QStringLiteral("arc.start_x"), QStringLiteral("10"));
        enter(arc, QStringLiteral("arc.start_y"), QStringLiteral("0"));
        // Centre mode: a quarter round (0,0) counter-clockwise. Three points: clockwise from
        // (10,0) over the bottom, through the middle point (0,-10), to (-10,0).
        enter(arc, QStringLiteral("arc.end_x"),
              mode == 0 ? QStringLiteral("0") : QStringLiteral("-10"));
        enter(arc, QStringLiteral("arc.end_y"),
              mode == 0 ? QStringLiteral("10") : QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_y"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.middle_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.middle_y"), QStringLiteral("-10"));
        enter(arc, QStringLiteral("arc.direction"), QString::number(direction));
        enter(arc, QStringLiteral("arc.speed"),
              mode == 0 ? QStringLiteral("300") : QStringLiteral("120"));
        const interpolation::Geometry g = arc->geometry();
        QVERIFY2(g.valid, qPrintable(g.error));
        QVERIFY(g.notes.isEmpty());
        QVERIFY(std::abs(g.radius() - 10) < 1e-9);
        QVERIFY(std::abs(std::abs(g.sweepDegrees) - (mode == 0 ? 90 : 180)) < 1e-9);
        QVERIFY(sim()->value(QStringLiteral("arc.start_x")) != 1000); // nothing written yet
        writeThroughDialog(arc);
        QCOMPARE(simValue(QStringLiteral("arc.start_x")), 1000);
        QCOMPARE(simValue(QStringLiteral("arc.mode")), mode);
        runToEnd(arc, page.preview(), mode == 0 ? 0 : -1000, mode == 0 ? 1000 : 0);
        if (mode == 1) {
            // Went over the bottom, through the middle point (the other way round stays at
            // y >= 0); the polled trace has points there at any poll rate (a second or more).
            const QList<QPointF> &trace = page.preview()->plot()->trace();
            QVERIFY(std::any_of(trace.cbegin(), trace.cend(),
                                [](const QPointF &p) { return p.y() < -7; }));
        }
    }

    void lineRunsToItsEnd()
    {
        InterpolationPage page(session.get());
        page.resize(1400, 900);
        page.show();
        page.tabs()->setCurrentIndex(1);
        QCOMPARE(page.currentEditor(), page.lineEditor());
        connectSim();
        PathEditor *line = page.lineEditor();
        enter(line, QStringLiteral("line.enabled"), QStringLiteral("1"));
        enter(line, QStringLiteral("line.start_x"), QStringLiteral("-5"));
        enter(line, QStringLiteral("line.start_y"), QStringLiteral("2.5"));
        enter(line, QStringLiteral("line.end_x"), QStringLiteral("7.25"));
        enter(line, QStringLiteral("line.end_y"), QStringLiteral("-4"));
        enter(line, QStringLiteral("line.speed"), QStringLiteral("240"));
        QVERIFY(line->geometry().valid);
        writeThroughDialog(line);
        runToEnd(line, page.preview(), 725, -400);
    }

    // Motor 2 sat on its negative limit, only the approach ran, and the arc was
    // reported "done". Now: warned before Start, and the outcome says where it stopped and why.
    void anArcAgainstAnActiveLimitIsWarnedAndNotDone()
    {
        InterpolationPage page(session.get());
        page.resize(1400, 900);
        page.show();
        PathEditor *arc = page.arcEditor();
        connectSim();
        QVERIFY(sim()->setValue(QStringLiteral("motor2.limit_positive"), 3));
        QVERIFY(sim()->setValue(QStringLiteral("motor2.limit_negative"), 4));
        QVERIFY(sim()->setValue(QStringLiteral("motor2.home_input"), 4));
        sim()->setInput(4, SimDevice::InputForce::On);
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE(read.size(), 1);
        // From (10, -5) counter-clockwise round (0, -5) to (0, 5): the approach drives motor 2
        // from 0 in reverse, into its negative limit.
        enter(arc, QStringLiteral("arc.enabled"), QStringLiteral("1"));
        enter(arc, QStringLiteral("arc.mode"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.start_x"), QStringLiteral("10"));
        enter(arc, QStringLiteral("arc.start_y"), QStringLiteral("-5"));
        enter(arc, QStringLiteral("arc.end_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.end_y"), QStringLiteral("5"));
        enter(arc, QStringLiteral("arc.center_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_y"), QStringLiteral("-5"));
        enter(arc, QStringLiteral("arc.direction"), QStringLiteral("1"));
        enter(arc, QStringLiteral("arc.speed"), QStringLiteral("300"));
        QVERIFY2(arc->geometry().valid, qPrintable(arc->geometry().error));
        writeThroughDialog(arc);
        QTRY_VERIFY_WITH_TIMEOUT(arc->startButton()->isEnabled(), 10000);
        QTRY_VERIFY2(arc->startReason()->text().contains(
                         QLatin1String("Motor 2's negative limit (IN4) is already ON")),
                     qPrintable(arc->startReason()->text()));
        QVERIFY(arc->startReason()->text().contains(QLatin1String("approach")));
        arc->startButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(arc->outcomeLabel()->text().startsWith(QLatin1String("Last run")),
                                 20000);
        const QString outcome = arc->outcomeLabel()->text();
        QVERIFY2(outcome.contains(QLatin1String("Arc: stopped at (")) &&
                     outcome.contains(QLatin1String("not at the end point (0.00, 5.00) mm")) &&
                     outcome.contains(QLatin1String("motor 2's negative limit (IN4) is ON")),
                 qPrintable(outcome));
        QVERIFY(!outcome.contains(QLatin1String("done")));
        QCOMPARE(sim()->position(2), 0);
    }

    void startNeedsWrittenValidGeometry()
    {
        InterpolationPage page(session.get());
        page.resize(1400, 900);
        page.show();
        connectSim();
        PathEditor *arc = page.arcEditor();
        // Valid and written, but interpolation switched off.
        enter(arc, QStringLiteral("arc.mode"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.start_x"), QStringLiteral("10"));
        enter(arc, QStringLiteral("arc.start_y"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.end_x"), QStringLiteral("-10"));
        enter(arc, QStringLiteral("arc.end_y"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_y"), QStringLiteral("0"));
        if (session->parameters()->store()->hasEdits())
            writeThroughDialog(arc);
        if (simValue(QStringLiteral("arc.enabled")) != 1) {
            QTRY_VERIFY(arc->startReason()->text().contains(QStringLiteral("is off")));
            QVERIFY(!arc->startButton()->isEnabled());
            enter(arc, QStringLiteral("arc.enabled"), QStringLiteral("1"));
            writeThroughDialog(arc);
        }
        QTRY_VERIFY(arc->startButton()->isEnabled());

        // Typing (not yet held) updates the preview and blocks Start.
        auto *endY =
            qobject_cast<QLineEdit *>(arc->form()->field(QStringLiteral("arc.end_y"))->editor());
        QVERIFY(endY);
        endY->setFocus();
        endY->selectAll();
        QTest::keyClicks(endY, QStringLiteral("3"));
        QVERIFY(!arc->startButton()->isEnabled());
        QVERIFY(arc->startReason()->text().contains(QStringLiteral("being typed")));
        page.updatePreview();
        // end (-10, 3) is not 10 from the centre: invalid, with both radii in the message.
        QVERIFY(!arc->geometry().valid);
        QVERIFY(page.preview()->message().startsWith(QStringLiteral("Invalid")));
        QVERIFY(page.preview()->message().contains(QStringLiteral("end radius 10.44")));
        QVERIFY(page.preview()->plot()->pathIds().contains(QStringLiteral("invalid")));
        page.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-invalid.png")));
        QTest::keyClick(endY, Qt::Key_Return);
        QVERIFY(session->parameters()->store()->entry(QStringLiteral("arc.end_y")).edited);
        QVERIFY(!arc->startButton()->isEnabled());
        QVERIFY(arc->startReason()->text().contains(QStringLiteral("not written")));
        // Three points on one line: invalid, Start off with the reason; Stop stays.
        enter(arc, QStringLiteral("arc.end_y"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.mode"), QStringLiteral("1"));
        enter(arc, QStringLiteral("arc.middle_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.middle_y"), QStringLiteral("0"));
        writeThroughDialog(arc);
        QTRY_VERIFY(arc->startReason()->text().contains(QStringLiteral("one straight line")));
        QVERIFY(!arc->startButton()->isEnabled());
        QVERIFY(arc->stopButton()->isEnabled());
        arc->startButton()->click();                  // disabled: nothing is sent
        QVERIFY(test::waitForStatusCycles(*session)); // a start would have gone out by then
        QVERIFY(!sim()->running(1) && !sim()->running(2));
    }

    void previewRendersOffscreen()
    {
        InterpolationPage page(session.get());
        page.resize(1400, 900);
        page.show();
        QVERIFY(QTest::qWaitForWindowExposed(&page));
        PathEditor *arc = page.arcEditor();
        page.updatePreview();
        const int empty = drawnPixels(page.preview());
        // Full circle around (0,0) from (5,0): path, arrows and markers are drawn.
        enter(arc, QStringLiteral("arc.mode"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.start_x"), QStringLiteral("5"));
        enter(arc, QStringLiteral("arc.start_y"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.end_x"), QStringLiteral("5"));
        enter(arc, QStringLiteral("arc.end_y"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_x"), QStringLiteral("0"));
        enter(arc, QStringLiteral("arc.center_y"), QStringLiteral("0"));
        page.updatePreview();
        QVERIFY(arc->geometry().fullCircle);
        QVERIFY(page.preview()->message().contains(QStringLiteral("full circle")));
        QVERIFY(page.preview()->plot()->pathIds().contains(QStringLiteral("path")));
        QVERIFY(page.preview()->plot()->pathIds().contains(QStringLiteral("arrow0")));
        const int drawn = drawnPixels(page.preview());
        QVERIFY2(drawn > empty + 500, qPrintable(QStringLiteral("%1 vs %2").arg(drawn).arg(empty)));
        const QString file = QDir::temp().filePath(QStringLiteral("stepcom-i6-preview.png"));
        QString error;
        QVERIFY2(page.preview()->exportPng(file, &error), qPrintable(error));
        QVERIFY(!QImage(file).isNull());
        page.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-page.png")));
    }

    // Both pages are in the window; an arc run there, pictured in both languages (the pictures
    // land in the temporary directory for a look).
    void inTheWindow()
    {
        MainWindow window(session.get());
        window.resize(1500, 950);
        window.show();
        InterpolationPage *page = nullptr;
        int index = -1;
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i) {
            if (auto *p = qobject_cast<InterpolationPage *>(WindowProbe(window).pages().at(i))) {
                page = p;
                index = i;
            }
        }
        QVERIFY(page);
        QVERIFY(std::any_of(WindowProbe(window).pages().cbegin(),
                            WindowProbe(window).pages().cend(),
                            [](Page *p) { return qobject_cast<ModesPage *>(p) != nullptr; }));
        WindowProbe(window).showPage(index);
        connectSim();
        PathEditor *arc = page->arcEditor();
        const QList<QPair<const char *, const char *>> values = {
            {"arc.enabled", "1"},  {"arc.mode", "1"},     {"arc.start_x", "20"},
            {"arc.start_y", "5"},  {"arc.end_x", "5"},    {"arc.end_y", "20"},
            {"arc.middle_x", "9"}, {"arc.middle_y", "9"}, {"arc.direction", "0"},
            {"arc.speed", "600"}};
        for (const auto &[key, value] : values)
            enter(arc, QLatin1String(key), QLatin1String(value));
        QVERIFY2(arc->geometry().valid, qPrintable(arc->geometry().error));
        writeThroughDialog(arc);
        page->updatePreview();
        window.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-before.png")));
        runToEnd(arc, page->preview(), 500, 2000);
        page->updatePreview();
        window.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-after.png")));
        const QPalette light = QApplication::palette();
        QApplication::setPalette(test::darkPalette());
        QCoreApplication::sendPostedEvents(); // the layouts settle before the picture
        window.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-dark.png")));
        QApplication::setPalette(light);
        const QString english = page->title();
        Language::instance().setLanguage(QStringLiteral("zh_CN"));
        QTRY_VERIFY(page->title() != english); // retranslated without a crash
        QCoreApplication::sendPostedEvents();
        window.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-zh.png")));
        WindowProbe(window).showPage(index + 1);
        QTRY_VERIFY(WindowProbe(window).pages().at(index + 1)->isVisible());
        QCoreApplication::sendPostedEvents();
        window.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-modes-zh.png")));
        Language::instance().setLanguage(QStringLiteral("en"));
        QTRY_COMPARE(page->title(), english);
        QCoreApplication::sendPostedEvents();
        window.grab().save(QDir::temp().filePath(QStringLiteral("stepcom-i6-modes.png")));
    }

    void modeChangeAsksFirst()
    {
        QWidget owner; // the write flow's dialogs open over it, as over the window
        WriteFlow writes(session.get(), &owner);
        QSignalSpy confirmed(&writes, &WriteFlow::confirmed);
        ModesPage page(session.get(), &writes);
        page.resize(1200, 900);
        page.show();
        QVERIFY(!page.modeBox()->isEnabled()); // not connected
        connectSim();
        QTRY_VERIFY(page.modeBox()->isEnabled());
        QCOMPARE(page.modeBox()->currentData().toInt(), 0);
        QCOMPARE(page.table()->rowCount(), 6);
        QVERIFY(page.warning()->text().contains(QStringLiteral("ignore the limit settings")));

        // Cancel: nothing written, the list shows the controller's mode again.
        page.chooseMode(3);
        QVERIFY(page.confirmation());
        QVERIFY(page.confirmation()->text().contains(QStringLiteral("IN1-IN4")));
        QVERIFY(
            page.confirmation()->informativeText().contains(QStringLiteral("IN3: positive limit")));
        // The review stepcomctl prints before the same write, word for word.
        QVERIFY2(page.confirmation()->informativeText().contains(
                     QStringLiteral("System mode 3 “Forward/reverse trigger” changes what the "
                                    "inputs IN1-IN4 do, at once, and ignores the limit settings")),
                 qPrintable(page.confirmation()->informativeText()));
        QVERIFY(page.explanation()->text().contains(QStringLiteral("IN1")));
        page.confirmation()->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY(!page.confirmation());
        QVERIFY(test::waitForStatusCycles(*session)); // a write would have gone out by then
        QCOMPARE(simValue(QStringLiteral("mode.system")), 0);
        QCOMPARE(page.modeBox()->currentData().toInt(), 0);
        QVERIFY(!session->parameters()->store()->hasEdits()); // never held as an edit
        QVERIFY(confirmed.isEmpty());

        // Yes: written at once and read back.
        page.chooseMode(3);
        QVERIFY(page.confirmation());
        QCOMPARE(simValue(QStringLiteral("mode.system")), 0);
        page.confirmation()->button(QMessageBox::Yes)->click();
        QVERIFY(!page.writeDialog()); // one question: the flow asks nothing more
        QCOMPARE(confirmed.size(), 1);
        QCOMPARE(confirmed.first().first().toString(), QStringLiteral("mode.system = 3"));
        QTRY_COMPARE_WITH_TIMEOUT(simValue(QStringLiteral("mode.system")), 3, 10000);
        QTRY_COMPARE(
            session->parameters()->store()->deviceValue(QStringLiteral("mode.system")).value_or(-1),
            3);
        QCOMPARE(page.modeBox()->currentData().toInt(), 3);

        // Round trips: edited, then written through the write dialog.
        page.form()->field(QStringLiteral("mode.round_trips"))->enterText(QStringLiteral("7"));
        QVERIFY(page.writeButton()->isEnabled());
        page.writeButton()->click();
        QVERIFY(page.writeDialog());
        QCOMPARE(page.writeDialog()->writes().size(), 1);
        page.writeDialog()->accept();
        QTRY_COMPARE_WITH_TIMEOUT(simValue(QStringLiteral("mode.round_trips")), 7, 10000);
        // Back to normal for the other tests' simulator (each test has its own anyway).
        page.chooseMode(0);
        page.confirmation()->button(QMessageBox::Yes)->click();
        QTRY_COMPARE_WITH_TIMEOUT(simValue(QStringLiteral("mode.system")), 0, 10000);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestInterpolationPage, Gui)
#include "tst_interpolationpage.moc"
