#include "base/language.h"
#include "base/page.h"
#include "bus/modbuslink.h"
#include "device/parameterstore.h"
#include "device/poller.h"
#include "device/statusrecorder.h"
#include "pages/plotpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/statusdock.h"
#include "widgets/fields/led.h"
#include "widgets/fields/statuspollrow.h"
#include "widgets/plots/positionplot.h"
#include "widgets/plots/xyplot.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include "testmaps.h"

#include "darkpalette.h"
#include "screenshots.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineSeries>
#include <QPushButton>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace stepcom;

// The status dock and the Plots page against the built-in simulator, offscreen.
class TstMonitoring : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    void connectSim() { test::connectToSimulator(*session); }
    QString simPositionText(int motor) const
    {
        const Parameter *p = session->map().find(QStringLiteral("motor%1.position").arg(motor));
        return p->displayRaw(sim()->position(motor));
    }
    static QStringList csvLines(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
            return {};
        QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
        lines.removeAll(QString());
        return lines;
    }
    // Header plus rows whose ms column only grows.
    static void checkCsv(const QString &path, int minRows)
    {
        const QStringList lines = csvLines(path);
        QVERIFY2(lines.size() >= minRows + 1, qPrintable(lines.join(QLatin1Char('\n'))));
        QVERIFY(lines.at(0).startsWith(QLatin1String("time,ms,motor1.position [mm]")));
        const int columns = int(lines.at(0).split(QLatin1Char(',')).size());
        qint64 previous = -1;
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList cols = lines.at(i).split(QLatin1Char(','));
            QCOMPARE(cols.size(), columns);
            QVERIFY(QDateTime::fromString(cols.at(0), Qt::ISODateWithMs).isValid());
            bool ok = false;
            const qint64 ms = cols.at(1).toLongLong(&ok);
            QVERIFY(ok);
            QVERIFY2(ms > previous, qPrintable(lines.at(i)));
            previous = ms;
            cols.at(2).toDouble(&ok);
            QVERIFY(ok);
        }
    }
    static int colourCount(const QString &path)
    {
        QImage image(path);
        QSet<QRgb> colours;
        for (int y = 0; y < image.height() && colours.size() < 3; y += 3) {
            for (int x = 0; x < image.width(); x += 3)
                colours.insert(image.pixel(x, y));
        }
        return int(colours.size());
    }
    std::unique_ptr<PlotPage> shownPlotPage()
    {
        auto page = std::make_unique<PlotPage>(session.get());
        page->resize(1000, 500);
        page->show();
        return page;
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

    void dockShowsPositionsAndFollowsAMove()
    {
        StatusDock dock(session.get());
        QCOMPARE(dock.motorCount(), 2);
        QCOMPARE(dock.positionText(1), QStringLiteral("unknown"));
        QCOMPARE(dock.runningLed(1)->state(), Led::State::Unknown);
        connectSim();
        sim()->setMachinePosition(2, 7.5);
        QTRY_COMPARE(dock.positionText(1), simPositionText(1));
        QTRY_COMPARE(dock.positionText(2), simPositionText(2));
        QVERIFY(dock.positionText(2).endsWith(QLatin1String(" mm")));
        QCOMPARE(dock.runningText(1), QStringLiteral("Stopped"));
        QCOMPARE(dock.runningLed(1)->state(), Led::State::Off);

        const QString before = dock.positionText(1);
        session->command(QStringLiteral("motor1.forward"));
        QTRY_COMPARE(dock.runningLed(1)->state(), Led::State::On);
        QCOMPARE(dock.runningText(1), QStringLiteral("Running"));
        QTRY_VERIFY(dock.positionText(1) != before);
        session->command(QStringLiteral("motor1.stop"));
        QTRY_VERIFY_WITH_TIMEOUT(!sim()->running(1), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(dock.runningLed(1)->state(), Led::State::Off, 5000);
        QTRY_COMPARE(dock.positionText(1), simPositionText(1));
        QCOMPARE(dock.runningLed(2)->state(), Led::State::Off); // the other motor never moved

        session->connection()->disconnectFrom();
        QTRY_COMPARE(dock.positionText(1), QStringLiteral("unknown"));
        QCOMPARE(dock.runningLed(1)->state(), Led::State::Unknown);
        QCOMPARE(dock.inputLed(1)->state(), Led::State::Unknown);
    }

    void dockLampsFollowTheInputsAndOutputs()
    {
        connectSim();
        StatusDock dock(session.get());
        QCOMPARE(dock.inputCount(), 4);
        QCOMPARE(dock.outputCount(), 3);
        QTRY_COMPARE(dock.inputLed(2)->state(), Led::State::Off);
        sim()->setInput(2, SimDevice::InputForce::On);
        QTRY_COMPARE(dock.inputLed(2)->state(), Led::State::On);
        QCOMPARE(dock.inputLed(1)->state(), Led::State::Off);
        QVERIFY2(dock.inputLed(2)->toolTip().contains(QLatin1String("IN2")),
                 qPrintable(dock.inputLed(2)->toolTip()));
        sim()->setInput(2, SimDevice::InputForce::Off);
        QTRY_COMPARE(dock.inputLed(2)->state(), Led::State::Off);
        QVERIFY(sim()->command(QStringLiteral("output1_on")));
        QTRY_COMPARE(dock.outputLed(1)->state(), Led::State::On);
        QCOMPARE(dock.outputLed(2)->state(), Led::State::Off);
    }

    // Where the link is described (the Connection page's Link box): the rate achieved.
    void linkShowsTheAchievedRate()
    {
        StatusPollRow row(session.get());
        QCOMPARE(row.rateText(), QStringLiteral("unknown"));
        connectSim();
        const auto rate = [&row] {
            QString t = row.rateText();
            t.remove(QLatin1String(" Hz"));
            return t.toDouble();
        };
        QTRY_VERIFY_WITH_TIMEOUT(rate() > 0.5, 4000);
        QVERIFY2(row.rateText().endsWith(QLatin1String(" Hz")), qPrintable(row.rateText()));
        session->connection()->disconnectFrom();
        QTRY_COMPARE(row.rateText(), QStringLiteral("unknown"));
    }

    void pollIntervalIsChosenAndRemembered()
    {
        connectSim();
        auto dock = std::make_unique<StatusPollRow>(session.get());
        QComboBox *box = dock->intervalBox();
        const int slow = box->findData(500);
        QVERIFY(slow >= 0);
        box->setCurrentIndex(slow);
        Q_EMIT box->activated(slow);
        QCOMPARE(session->status()->intervalMs(), 500);
        // about two cycles a second now
        const quint64 before = session->connection()->linkStats().requests;
        QTest::qWait(1100);
        QVERIFY2(session->connection()->linkStats().requests - before <= 8,
                 qPrintable(QString::number(session->connection()->linkStats().requests - before)));
        // a new dock (the next start) applies the remembered choice
        session->status()->setIntervalMs(100);
        dock = std::make_unique<StatusPollRow>(session.get());
        QCOMPARE(session->status()->intervalMs(), 500);
        QCOMPARE(dock->intervalBox()->currentData().toInt(), 500);
        QSettings().remove(QStringLiteral("monitor/pollIntervalMs"));
    }

    void dockFollowsTheMapsCounts()
    {
        QStringList errors;
        const auto map = stepcom::test::builtinMapWithMotors(3, &errors);
        QVERIFY2(map, qPrintable(errors.join(QLatin1Char('\n'))));
        DeviceSession three(*map);
        StatusDock dock(&three);
        QCOMPARE(dock.motorCount(), 3);
        QCOMPARE(dock.positionText(3), QStringLiteral("unknown"));
        PlotPage page(&three);
        QCOMPARE(page.positionPlot()->seriesCount(), 3);
    }

    void positionPlotFillsAndPauseFreezesIt()
    {
        connectSim();
        auto page = shownPlotPage();
        PositionPlot *plot = page->positionPlot();
        QCOMPARE(plot->seriesCount(), 2);
        QVERIFY(!page->isPaused()); // setting the chart up is not the user zooming
        QTRY_VERIFY_WITH_TIMEOUT(plot->pointCount(1) >= 3, 5000);
        QCOMPARE(plot->series(1)->name(), QStringLiteral("Motor 1"));

        page->pauseButton()->click();
        QVERIFY(page->isPaused());
        const int shown = plot->pointCount(1);
        const int recorded = page->recorder()->size();
        QTRY_VERIFY_WITH_TIMEOUT(page->recorder()->size() >= recorded + 3, 5000);
        QTest::qWait(300);                    // past the redraw interval
        QCOMPARE(plot->pointCount(1), shown); // frozen, while the recorder went on

        page->pauseButton()->click();
        QVERIFY(!page->isPaused());
        QTRY_VERIFY(plot->pointCount(1) > shown);

        // Zooming in on a live view holds it still; fit keeps it paused, resume goes live.
        plot->zoom(2.0);
        QVERIFY(page->isPaused());
        QVERIFY(page->pauseButton()->isChecked());
        page->fit();
        QVERIFY(page->isPaused());
        page->setPaused(false);
        QVERIFY(!page->pauseButton()->isChecked());
    }

    void xyPlotTracesThePath()
    {
        connectSim();
        auto page = shownPlotPage();
        XYPlot *xy = page->xyPlot();
        QTRY_VERIFY_WITH_TIMEOUT(xy->marker().has_value(), 5000);
        QCOMPARE(xy->traceCount(), 1); // at rest: one point, however many samples
        session->command(QStringLiteral("motor1.forward"));
        QTRY_VERIFY_WITH_TIMEOUT(xy->traceCount() >= 3, 5000);
        session->command(QStringLiteral("motor1.stop"));
        session->command(QStringLiteral("motor2.forward"));
        QTRY_VERIFY_WITH_TIMEOUT(xy->trace().last().y() > xy->trace().first().y(), 5000);
        session->command(QStringLiteral("motor2.stop"));
        QTRY_VERIFY_WITH_TIMEOUT(!sim()->running(1) && !sim()->running(2), 5000);
        const QList<QPointF> trace = xy->trace();
        QVERIFY(trace.last().x() > trace.first().x());
        QTRY_COMPARE(*xy->marker(),
                     QPointF(sim()->position(1) / 100.0, sim()->position(2) / 100.0));
        // The whole path is in view (autofit), with both axes at the same scale.
        const QRectF view = xy->visibleRect();
        for (const QPointF &p : trace)
            QVERIFY(view.contains(p));
        page->clearTrace();
        QCOMPARE(xy->traceCount(), 0);
    }

    void xyPlotIsAGeneralWidget()
    {
        XYPlot xy;
        xy.resize(400, 300);
        xy.show();
        QList<QPointF> arc;
        for (int i = 0; i <= 16; ++i)
            arc << QPointF(10 * std::cos(i * M_PI / 16), 10 * std::sin(i * M_PI / 16));
        xy.setPath(QStringLiteral("arc"), arc, QStringLiteral("Arc"));
        xy.setPoints(QStringLiteral("ends"), {arc.first(), arc.last()});
        xy.appendTrace({QPointF(0, 0), QPointF(0, 0), QPointF(1, 1)});
        QCOMPARE(xy.traceCount(), 2);
        xy.flush();
        QTRY_VERIFY(xy.visibleRect().contains(QRectF(-10, 0, 20, 10)));
        xy.zoom(4.0);
        QVERIFY(!xy.autoFit());
        QVERIFY(xy.visibleRect().width() < 10);
        xy.fit();
        QVERIFY(xy.autoFit());
        QCOMPARE(xy.path(QStringLiteral("arc")).size(), 17);
        xy.removePath(QStringLiteral("arc"));
        QCOMPARE(xy.pathIds(), QStringList{QStringLiteral("ends")});
        xy.setTraceLimit(1);
        QCOMPARE(xy.traceCount(), 2); // at least two points make a line
    }

    void pngExportIsNotBlank()
    {
        connectSim();
        auto page = shownPlotPage();
        QTRY_VERIFY_WITH_TIMEOUT(page->positionPlot()->pointCount(1) >= 2, 5000);
        QTemporaryDir dir;
        QString error;
        const QString both = dir.filePath(QStringLiteral("plots.png"));
        QVERIFY2(page->exportPng(both, &error), qPrintable(error));
        QVERIFY(colourCount(both) > 1);
        const QString xy = dir.filePath(QStringLiteral("xy.png"));
        QVERIFY2(page->xyPlot()->exportPng(xy, &error), qPrintable(error));
        QVERIFY(colourCount(xy) > 1);
        QVERIFY(!page->exportPng(QStringLiteral("/nonexistent-stepcom/x.png"), &error));
        QVERIFY2(error.contains(QLatin1String("/nonexistent-stepcom/x.png")), qPrintable(error));
    }

    void csvExportAndRecordingAreParseable()
    {
        connectSim();
        auto page = shownPlotPage();
        QTemporaryDir dir;
        QString error;
        const QString recording = dir.filePath(QStringLiteral("recording.csv"));
        QVERIFY2(page->startRecording(recording, &error), qPrintable(error));
        QVERIFY(page->recordButton()->isChecked());
        QVERIFY(page->recordingStatus().contains(QLatin1String("recording.csv")));
        session->command(QStringLiteral("motor1.forward"));
        QTRY_VERIFY_WITH_TIMEOUT(page->recorder()->recordedRows() >= 5, 5000);
        session->command(QStringLiteral("motor1.stop"));
        page->stopRecording();
        QVERIFY(!page->recordButton()->isChecked());
        checkCsv(recording, 5);

        const QString visible = dir.filePath(QStringLiteral("visible.csv"));
        QVERIFY2(page->exportCsv(visible, &error), qPrintable(error));
        checkCsv(visible, 3);

        QVERIFY(!page->startRecording(QStringLiteral("/nonexistent-stepcom/r.csv"), &error));
        QVERIFY2(error.contains(QLatin1String("/nonexistent-stepcom/r.csv")), qPrintable(error));
        QVERIFY(!page->recordButton()->isChecked());
    }

    void exportGoesThroughANonModalDialog()
    {
        connectSim();
        auto page = shownPlotPage();
        QTRY_VERIFY_WITH_TIMEOUT(page->recorder()->size() >= 2, 5000);
        page->findChild<QPushButton *>(QStringLiteral("exportCsvButton"))->click();
        QFileDialog *dialog = page->fileDialog();
        QVERIFY(dialog); // click() returned: nothing waited for the dialog
        QTRY_VERIFY(dialog->isVisible());
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("chosen.csv"));
        dialog->selectFile(path);
        static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept is protected
        QTRY_VERIFY(QFile::exists(path));
        checkCsv(path, 1);
        QVERIFY2(page->recordingStatus().contains(QLatin1String("chosen.csv")),
                 qPrintable(page->recordingStatus()));
    }

    void windowHasTheDockAndThePage()
    {
        MainWindow window(session.get());
        window.show();
        QVERIFY(WindowProbe(window).statusDock());
        // Off at first: the machine strip shows the same; the View menu brings it back.
        QVERIFY(!WindowProbe(window).statusDock()->isVisible());
        WindowProbe(window).statusDock()->toggleViewAction()->trigger();
        QVERIFY(WindowProbe(window).statusDock()->isVisible());
        // Beside the page on a wide screen; on a narrow one (the offscreen default is 800 px
        // wide) in the bottom tabs, so the page keeps its width.
        const bool wide = window.screen()->availableGeometry().width() >=
                          window.centralWidget()->minimumSizeHint().width() +
                              WindowProbe(window).statusDock()->minimumSizeHint().width() + 20;
        QCOMPARE(window.dockWidgetArea(WindowProbe(window).statusDock()),
                 wide ? Qt::RightDockWidgetArea : Qt::BottomDockWidgetArea);
        bool found = false;
        for (Page *p : WindowProbe(window).pages())
            found = found || qobject_cast<PlotPage *>(p);
        QVERIFY(found);
        WindowProbe(window).statusDock()->toggleViewAction()->trigger();
        QVERIFY(!WindowProbe(window).statusDock()->isVisible());
    }

    void languageSwitchRetranslates()
    {
        StatusDock dock(session.get());
        dock.show();
        auto page = shownPlotPage();
        QVERIFY(Language::instance().setLanguage(QStringLiteral("zh_CN")));
        QTRY_COMPARE(dock.windowTitle(), QStringLiteral("状态"));
        QCOMPARE(dock.positionText(1), QStringLiteral("未知"));
        QTRY_COMPARE(page->title(), QStringLiteral("曲线图"));
        QCOMPARE(page->pauseButton()->text(), QStringLiteral("暂停(&P)"));
        QCOMPARE(page->positionPlot()->series(2)->name(), QStringLiteral("电机 2"));
        QVERIFY(Language::instance().setLanguage(QStringLiteral("en")));
        QTRY_COMPARE(dock.windowTitle(), QStringLiteral("Status"));
        QTRY_COMPARE(page->pauseButton()->text(), QStringLiteral("&Pause"));
        QCOMPARE(page->positionPlot()->series(2)->name(), QStringLiteral("Motor 2"));
    }

    // The plots, the status dock and the window after an L-shaped path, light and dark: each
    // picture is checked. STEPCOM_SCREENSHOTS=/tmp/shots tests_ui tst_monitoring screenshots
    // keeps them to look at.
    void screenshots()
    {
        const test::ScreenshotDir dir;
        QVERIFY(dir.isValid());
        connectSim();
        sim()->setInput(4, SimDevice::InputForce::On); // IN3 would be motor 2's limit
        QVERIFY(sim()->command(QStringLiteral("output1_on")));
        const QPalette dark = stepcom::test::darkPalette();
        const QPalette light = QApplication::palette();
        auto page = shownPlotPage();
        StatusDock dock(session.get());
        dock.resize(dock.sizeHint().expandedTo(QSize(300, 500)));
        dock.show();
        MainWindow window(session.get());
        window.resize(1400, 800);
        window.show();
        for (int i = 0; i < WindowProbe(window).pages().size(); ++i) {
            if (qobject_cast<PlotPage *>(WindowProbe(window).pages().at(i)))
                WindowProbe(window).showPage(i);
        }
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        // One motor at a time (the controller runs one jog at a time): an L-shaped path, each leg
        // 5 mm as the status poll saw it.
        const ParameterStore *store = session->parameters()->store();
        for (const char *key : {"motor1.forward", "motor2.forward", "motor1.reverse"}) {
            const QString motor = QLatin1String(key).left(6);
            const QString position = motor + QLatin1String(".position");
            const qint64 from = store->deviceValue(position).value_or(0);
            session->command(QLatin1String(key));
            QTRY_VERIFY_WITH_TIMEOUT(
                std::abs(store->deviceValue(position).value_or(from) - from) >= 500, 20000);
            session->command(motor + QLatin1String(".stop"));
            QTRY_VERIFY(!sim()->running(1) && !sim()->running(2));
        }
        QTRY_VERIFY(page->positionPlot()->pointCount(1) >= 3);
        for (const bool isDark : {false, true}) {
            QApplication::setPalette(isDark ? dark : light);
            QCoreApplication::sendPostedEvents(); // the layouts settle before the pictures
            const QString suffix = isDark ? QStringLiteral("-dark") : QString();
            for (auto [widget, name] : {std::pair<QWidget *, const char *>{page.get(), "plots"},
                                        {&dock, "status"},
                                        {&window, "window"}}) {
                const QString problem = test::saveAndCheckGrab(
                    widget,
                    dir.filePath(QStringLiteral("%1%2.png").arg(QLatin1String(name), suffix)));
                QVERIFY2(problem.isEmpty(), qPrintable(problem));
            }
        }
        QApplication::setPalette(light);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstMonitoring, Gui)
#include "tst_monitoring.moc"
