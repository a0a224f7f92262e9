// The window's views in a replay, offscreen, on a log of three minutes of two
// controllers made for the purpose: at a late moment the plots and the XY trace hold what the
// live window held (the path back to the start, not only the last minute), the traffic view
// ends at the moment's frame and goes back over the earlier ones, the device list shows each
// device's own state (names from the log, running, not answering, restarted, errors); playing
// on feeds the views instead of building them again.
#include "device/statusrecorder.h"
#include "logbuilder.h"
#include "pages/plotpage.h"
#include "replay/replaybar.h"
#include "replay/replayviews.h"
#include "replayfixture.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionstatus.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/docks/trafficmodel.h"
#include "widgets/docks/trafficview.h"
#include "widgets/plots/xyplot.h"
#include "window/windowprobe.h"

#include <QDockWidget>
#include <QPushButton>
#include <QScrollBar>
#include <QTableView>
#include <QTableWidget>
#include <QTest>

using namespace stepcom;

namespace {

constexpr int kCycles = 900;      // 180 s
constexpr int kCycleMs = 200;     // a cycle: three reads of id 1, one of id 2
constexpr int kSilentFrom = 450;  // id 2 answers no more from here (90 s)
constexpr int kRunningFrom = 600; // motor 1 of id 1 runs from here (120 s)
constexpr int kRestartAt = 500;   // the session saw id 2 restart (100 s)

} // namespace

class TestReplayViews : public test::ReplayFixture
{
    Q_OBJECT
    QString logPath;

    const Parameter *param(const char *role, int motor = 1) const
    {
        return session->map().blockParameter(QStringLiteral("motor"), motor, QLatin1String(role));
    }
    // Where the tool was in cycle i: motor 1 at 10 i, motor 2 at 5 i (raw).
    QPointF positionAt(int i) const
    {
        return QPointF(10.0 * i / param("position", 1)->scale,
                       5.0 * i / param("position", 2)->scale);
    }
    TrafficModel *traffic() const { return WindowProbe(*window).trafficView()->model(); }
    const TrafficEntry &lastRow() const
    {
        traffic()->flush();
        return traffic()->entryAt(traffic()->rowCount() - 1);
    }
    static QString clock(const TrafficEntry &e)
    {
        return e.time.toString(QStringLiteral("HH:mm:ss.zzz"));
    }
    void seek(qint64 ms)
    {
        replay()->seek(ms);
        QCoreApplication::processEvents();
    }

private Q_SLOTS:
    void initTestCase()
    {
        openWindow();
        test::LogBuilder b;
        b.header();
        b.text += QStringLiteral("# names: {\"1\":\"X gantry\",\"2\":\"Lift\"}\n");
        const quint16 speed = param("speed")->address;
        for (int i = 0; i < kCycles; ++i) {
            const QDateTime start = b.time;
            if (i == kRestartAt)
                b.mark("restart", QStringLiteral("id 2: motor1.speed 300 → 120 rpm"), 0);
            b.read(1, param("position", 1)->address, param("position", 1)->encode(10 * i));
            b.read(1, param("position", 2)->address, param("position", 2)->encode(5 * i));
            b.read(1, param("running")->address, {quint16(i >= kRunningFrom ? 1 : 0)});
            if (i < kSilentFrom)
                b.read(2, speed, {300});
            else
                b.frame(true, test::LogBuilder::readRequest(2, speed, 1)); // no answer
            if (i == kRunningFrom - 1) // what sets motor 1 running, acknowledged
                b.coil(1, param("forward")->address);
            b.time = start.addMSecs(kCycleMs);
        }
        logPath = b.save(dir, QStringLiteral("two-devices.log"));
        QVERIFY(!logPath.isEmpty());
    }
    void cleanupTestCase() { closeWindow(); }
    void cleanup() { closeReplay(); }

    // Late in the log the plots hold the samples of the minutes before, as the live recorder
    // kept them, and the XY trace the whole path from the start.
    void thePlotsGoBackToTheStart()
    {
        QVERIFY(openReplay(logPath));
        const int cycle = 850;
        const qint64 moment = qint64(cycle) * kCycleMs + 50; // the running flag's answer
        seek(moment);
        const StatusRecorder *recorder = session->status()->recorder();
        QVERIFY(!recorder->isEmpty());
        QVERIFY2(recorder->at(0).elapsedMs < moment - 60000,
                 qPrintable(QString::number(recorder->at(0).elapsedMs)));
        QCOMPARE(recorder->at(0).elapsedMs, 10); // the first answer
        QCOMPARE(recorder->last().elapsedMs, moment);
        QCOMPARE(recorder->last().positions.value(0), positionAt(cycle).x());
        QCOMPARE(recorder->last().positions.value(1), positionAt(cycle).y());
        QCOMPARE(recorder->last().running.value(0), qint8(1));
        const XYPlot *xy = WindowProbe(*window).plotPage()->xyPlot();
        QVERIFY(xy->traceCount() > 1000);
        QCOMPARE(xy->trace().first(), positionAt(0));
        QCOMPARE(xy->trace().last(), positionAt(cycle));
        QCOMPARE(*xy->marker(), positionAt(cycle));
        // Earlier: the trace ends earlier.
        seek(30 * 1000 + 50);
        QCOMPARE(xy->trace().last(), positionAt(150));
        QCOMPARE(recorder->last().positions.value(0), positionAt(150).x());
    }

    // The traffic view ends at the moment's frame and goes back over the earlier ones.
    void theTrafficViewEndsAtTheMoment()
    {
        QVERIFY(openReplay(logPath));
        const qint64 moment = 850 * kCycleMs + 50;
        seek(moment);
        const TrafficEntry &last = lastRow();
        QCOMPARE(clock(last), QStringLiteral("22:12:50.050"));
        QCOMPARE(last.direction, TrafficEntry::Direction::Received);
        QCOMPARE(last.bytes, test::LogBuilder::withCrc(QByteArray::fromHex("01030200") + '\x01'));
        // Everything before it is there to scroll back to (a short log: from its start).
        QCOMPARE(clock(traffic()->entryAt(0)), QStringLiteral("22:10:00.000"));
        QVERIFY(traffic()->rowCount() > 5000);
        QVERIFY(traffic()->rowCount() <= ReplayViews::kTrafficLines);
        // At another moment, its own last frame: id 2's request that got no answer.
        seek(600 * kCycleMs + 60);
        QCOMPARE(clock(lastRow()), QStringLiteral("22:12:00.060"));
        QCOMPARE(lastRow().direction, TrafficEntry::Direction::Sent);
        QCOMPARE(lastRow().bytes, test::LogBuilder::readRequest(2, param("speed")->address, 1));
    }

    // Beyond its rows the traffic view goes back on: scrolled to the top, or with "Earlier
    // lines", to the start of the log.
    void theTrafficViewScrollsBackToTheStart()
    {
        test::LogBuilder b;
        b.header();
        const quint16 speed = param("speed")->address;
        static_assert(3 * ReplayViews::kTrafficLines < 32000);
        for (int i = 0; i < 16000; ++i) // 32 000 lines: three times what the view takes at once
            b.read(1, speed, {quint16(i)});
        QVERIFY(openReplay(b.save(dir, QStringLiteral("long.log"))));
        for (QWidget *w = WindowProbe(*window).trafficView(); w; w = w->parentWidget()) {
            if (auto *dock = qobject_cast<QDockWidget *>(w))
                dock->show();
        }
        seek(replay()->log().durationMs());
        TrafficView *view = WindowProbe(*window).trafficView();
        QVERIFY(view->earlierButton()->isVisibleTo(window.get()));
        QCOMPARE(clock(lastRow()), QStringLiteral("22:15:19.990"));
        QCOMPARE(traffic()->rowCount(), ReplayViews::kTrafficLines);
        const QString firstBefore = clock(traffic()->entryAt(0));
        QVERIFY(firstBefore > QStringLiteral("22:10:00.000"));
        // Scrolled to the top: the lines before come, the rows in sight stay in sight; again
        // and again, to the start of the log.
        QScrollBar *bar = view->table()->verticalScrollBar();
        QTRY_VERIFY(bar->maximum() > 0);
        bar->setValue(bar->minimum());
        QTRY_COMPARE(traffic()->rowCount(), 2 * ReplayViews::kTrafficLines);
        QCOMPARE(clock(traffic()->entryAt(ReplayViews::kTrafficLines)), firstBefore);
        QCOMPARE(clock(lastRow()), QStringLiteral("22:15:19.990")); // it still ends there
        QVERIFY(bar->value() > bar->minimum());
        for (int rows : {3 * ReplayViews::kTrafficLines, 32000}) {
            bar->setValue(bar->minimum());
            QTRY_COMPARE(traffic()->rowCount(), rows);
        }
        QCOMPARE(clock(traffic()->entryAt(0)), QStringLiteral("22:10:00.000"));
        // None left: the button says so.
        QCOMPARE(view->showEarlier(), 0);
        QVERIFY(!view->earlierButton()->isEnabled());
        // Another moment: its own last rows, and the button again.
        seek(50000);
        QVERIFY(view->earlierButton()->isEnabled());
        QCOMPARE(clock(lastRow()), QStringLiteral("22:10:50.000"));
        QCOMPARE(traffic()->rowCount(), 5001);
        replay()->close();
        QVERIFY(!view->earlierButton()->isVisibleTo(window.get()));
    }

    // Playing on adds what came since to the views; it does not build them again.
    void playingFeedsTheViews()
    {
        QVERIFY(openReplay(logPath));
        seek(850 * kCycleMs + 50);
        const StatusRecorder *recorder = session->status()->recorder();
        const int samples = recorder->size();
        const int rows = (traffic()->flush(), traffic()->rowCount());
        QSignalSpy cleared(recorder, &StatusRecorder::cleared);
        QSignalSpy reset(traffic(), &QAbstractItemModel::modelReset);
        ReplayBar *bar = replay()->bar();
        bar->setSpeed(4);
        bar->tick(); // 400 ms on: two cycles
        QCoreApplication::processEvents();
        QCOMPARE(replay()->moment(), 850 * kCycleMs + 50 + 4 * ReplayBar::kTickMs);
        QCOMPARE(cleared.size(), 0);
        QCOMPARE(reset.size(), 0);
        QCOMPARE(clock(lastRow()), QStringLiteral("22:12:50.450")); // cycle 852's third answer
        QCOMPARE(traffic()->rowCount(), rows + 1 + 7 + 6); // the rest of 850, 851, most of 852
        QVERIFY(recorder->size() > samples);
        QCOMPARE(recorder->last().positions.value(0), positionAt(852).x());
        // The XY trace follows (the plot page feeds it from the recorder, as when live).
        const XYPlot *xy = WindowProbe(*window).plotPage()->xyPlot();
        QTRY_COMPARE(xy->trace().last(), positionAt(852));
        QCOMPARE(xy->trace().first(), positionAt(0));
        // A jump back is shown afresh.
        seek(10000);
        QCOMPARE(cleared.size(), 1);
        QCOMPARE(xy->trace().last(), positionAt(49));
    }

    // Each device of the line its own row: its name from the log, running or not answering,
    // its restart, its errors; the one in view marked.
    void theDeviceListShowsEachDevicesState()
    {
        QVERIFY(openReplay(logPath));
        DeviceListDock *list = WindowProbe(*window).deviceListDock();
        seek(30 * 1000 + 50);
        QVERIFY(list->isReplay());
        QCOMPARE(list->table()->rowCount(), 2);
        QCOMPARE(list->rowTexts(0),
                 (QStringList{"1", "X gantry", "answering (in view)", "unknown", "0"}));
        QCOMPARE(list->rowTexts(1), (QStringList{"2", "Lift", "answering", "unknown", "0"}));
        // Late: id 1 runs (the motion command it acknowledged, in the list's words), id 2
        // answers no more and was seen to restart.
        seek(850 * kCycleMs + 50);
        const QString forward = param("forward")->label.text(QStringLiteral("en"));
        QCOMPARE(forward, QStringLiteral("Forward"));
        QCOMPARE(list->rowTexts(0),
                 (QStringList{"1", "X gantry", "running: " + forward, "unknown", "0"}));
        const QStringList second = list->rowTexts(1);
        QCOMPARE(second.value(0), QStringLiteral("2"));
        QCOMPARE(second.value(1), QStringLiteral("Lift"));
        QVERIFY2(second.value(2).startsWith(QLatin1String("not answering; restarted +100.000 s "
                                                          "(22:11:40.000)")),
                 qPrintable(second.value(2)));
        QCOMPARE(second.value(4), QString::number(850 - kSilentFrom)); // each cycle's read
        QVERIFY2(list->table()->item(1, 4)->toolTip().contains(QLatin1String("no answer")),
                 qPrintable(list->table()->item(1, 4)->toolTip()));
        QCOMPARE(list->table()->item(1, 2)->toolTip(),
                 QStringLiteral("id 2: motor1.speed 300 → 120 rpm"));
        // In view: id 2, at the same moment.
        Q_EMIT list->table()->cellClicked(1, 0);
        QCOMPARE(replay()->device(), 2);
        QVERIFY2(list->rowTexts(1).value(2).startsWith(QLatin1String("not answering (in view)")),
                 qPrintable(list->rowTexts(1).value(2)));
        QCOMPARE(list->rowTexts(0).value(2), "running: " + forward);
        // At the start nothing has answered yet: the line is not known to be up.
        seek(0);
        QCOMPARE(list->rowTexts(0).value(2), QStringLiteral("not connected"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReplayViews, Gui)
#include "tst_replayviews.moc"
