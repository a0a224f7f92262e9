// The window's replay of a session log, offscreen: a session recorded by the window
// itself against the built-in simulator (connect and read-all, a write, a move, a move stopped by
// E-STOP) opens in replay mode, and at each chosen moment the store and the machine strip hold
// exactly what the session held then (and what `stepcomctl replay --at` says); nothing writes;
// the markers are the log's events; bundles replay; the support bundle dialog writes one.
#include "base/language.h"
#include "base/page.h"
#include "base/writechangesdialog.h"
#include "device/statusrecorder.h"
#include "dialogs/supportbundledialog.h"
#include "enabledcontrols.h"
#include "logbuilder.h"
#include "map/factoryvalues.h"
#include "pages/checklistpage.h"
#include "profile/profiledocument.h"
#include "profile/profilefile.h"
#include "programrun.h"
#include "replay/replaybar.h"
#include "replay/replaymode.h"
#include "replay/replayslider.h"
#include "replayfixture.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/sessionlog.h"
#include "session/stepmove.h"
#include "simsession.h"
#include "support/supportbundle.h"
#include "widgets/checklist/checkliststepwidget.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/pagesidebar.h"
#include "widgets/docks/trafficmodel.h"
#include "widgets/docks/trafficview.h"
#include "widgets/fields/elidedlabel.h"
#include "window/mainwindow.h"
#include "window/offlineactions.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QInputDialog>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <memory>

using namespace stepcom;

class TestReplayWindow : public test::ReplayFixture
{
    Q_OBJECT
    QByteArray recorded() const
    {
        QFile f(logPath);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

private Q_SLOTS:
    void initTestCase()
    {
        // The window records its session into one file, as `stepcomctl --log` does.
        logPath = dir.filePath(QStringLiteral("logs/session.log"));
        QDir().mkpath(dir.filePath(QStringLiteral("logs")));
        openWindow();
        WindowProbe(*window).sessionLog()->setFile(logPath);

        // 1. connect and read everything
        test::connectToSimulator(*session);
        QTRY_VERIFY_WITH_TIMEOUT(store()->deviceValue(key("position")).has_value(), 10000);
        captureAtCycleEnd(QStringLiteral("read-all"), true);
        // 2. a write
        const qint64 speed = *store()->deviceValue(key("speed"));
        QVERIFY(store()->edit(key("speed"), speed + 17).isEmpty());
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        WindowProbe(*window)
            .writeChanges(); // the window's dialog, confirmed: a user line of the log
        QTRY_VERIFY(WindowProbe(*window).writeDialog());
        WindowProbe(*window).writeDialog()->accept();
        QVERIFY(written.wait(10000));
        QCOMPARE(store()->deviceValue(key("speed")), speed + 17);
        captureAtCycleEnd(QStringLiteral("written"), true);
        // 3. a move, done
        QSignalSpy stepped(session->stepMove(), &StepMove::finished);
        QCOMPARE(session->stepMove()->start({StepMoveRequest::Kind::By, 1, 2.0, 0}), QString());
        QVERIFY(stepped.wait(20000));
        QVERIFY2(stepped.at(0).at(0).value<StepMoveResult>().ok(),
                 qPrintable(stepped.at(0).at(0).value<StepMoveResult>().text));
        QTRY_COMPARE(WindowProbe(*window).machineStrip()->motion(1), MachineStrip::Motion::Idle);
        captureAtCycleEnd(QStringLiteral("moved"), true);
        // 4. a long move, seen running, then E-STOP
        QCOMPARE(session->stepMove()->start({StepMoveRequest::Kind::By, 1, 500.0, 0}), QString());
        captureAtCycleEnd(QStringLiteral("running"), false,
                          [this] { return store()->deviceValue(key("running")).value_or(0) == 1; });
        QSignalSpy stopped(session.get(), &DeviceSession::commandFinished);
        session->emergencyStop();
        QTRY_VERIFY_WITH_TIMEOUT(!stopped.isEmpty(), 10000);
        QCOMPARE(stopped.at(0).at(0).toString(), QStringLiteral("estop"));
        QVERIFY(stopped.at(0).at(1).toBool());
        QTRY_VERIFY_WITH_TIMEOUT(store()->deviceValue(key("running")) == 0, 10000);
        QTRY_COMPARE(WindowProbe(*window).machineStrip()->motion(1), MachineStrip::Motion::Idle);
        captureSettled(QStringLiteral("stopped"));
        // 5. a page chosen and a checklist result (skipped), user lines of the log
        WindowProbe(*window).sidebar()->setCurrentPage(2);
        auto *step =
            WindowProbe(*window).checklistPage()->stepWidget(QStringLiteral("motor1.direction"));
        QVERIFY(step);
        step->skipButton()->click();
        session->connection()->disconnectFrom();
        QTRY_VERIFY(!session->connection()->isConnected());
        QVERIFY(!store()->deviceValue(key("position")).has_value());
        WindowProbe(*window).sessionLog()->setFile(QString());
        if (qEnvironmentVariableIsSet("REPLAY_KEEP_LOG"))
            QFile::copy(logPath, qEnvironmentVariable("REPLAY_KEEP_LOG"));
    }
    void cleanupTestCase() { closeWindow(); }
    void cleanup() { closeReplay(); }

    // At each chosen moment the store and the strip hold what the session held then, and the
    // traffic view ends at that moment.
    void replayShowsWhatTheSessionHeld()
    {
        const QString title = window->windowTitle();
        const qsizetype sent =
            session->connection()->traffic()->entries().size(); // the recording's
        QVERIFY(openReplay(logPath));
        QVERIFY(replay()->isActive());
        QVERIFY(window->windowTitle().contains(QStringLiteral("replay")));
        QVERIFY(window->windowTitle() != title);
        QVERIFY(replay()->banner()->isVisibleTo(window.get()));
        QVERIFY(replay()->bannerText().contains(QStringLiteral("session.log")));
        QVERIFY(replay()->bannerText().contains(QStringLiteral("nothing is written or moved")));
        QVERIFY(replay()->bar()->isVisibleTo(window.get()));
        QVERIFY(store()->isReplay());
        for (const Moment &m : std::as_const(moments)) {
            checkReplayAt(m);
            if (QTest::currentTestFailed())
                return;
            QCOMPARE(session->connection()->traffic()->entries().size(),
                     sent); // the session's own: nothing new
        }
        QVERIFY2(
            replay()->momentStateText().contains(QStringLiteral("the link is up. Id 1 answers.")),
            qPrintable(replay()->momentStateText()));
        replay()->seek(replay()->log().durationMs()); // after the disconnect
        QVERIFY2(replay()->momentStateText().contains(QStringLiteral("link is down")),
                 qPrintable(replay()->momentStateText()));
        QCOMPARE(moments.at(3).values.value(key("running")), 1);
        QVERIFY(moments.at(3).values.value(key("position")) !=
                moments.at(4).values.value(key("position")));
        // Back to the start: nothing known yet.
        replay()->seek(0);
        QVERIFY(!store()->deviceValue(key("speed")).has_value());
    }

    // Frame by frame and playing move the moment on; events step to their moments.
    void stepsAndPlay()
    {
        QVERIFY(openReplay(logPath));
        ReplayBar *bar = replay()->bar();
        replay()->stepFrame(+1);
        const qint64 first = replay()->moment();
        QVERIFY(first >= 0);
        replay()->stepFrame(+1);
        QVERIFY(replay()->moment() > first);
        replay()->stepFrame(-1);
        QCOMPARE(replay()->moment(), first);
        bar->setSpeed(4);
        const qint64 before = replay()->moment();
        bar->tick();
        QCOMPARE(replay()->moment(), before + 4 * ReplayBar::kTickMs);
        bar->setPlaying(true);
        QVERIFY(bar->isPlaying());
        bar->setPlaying(false);
        replay()->seek(replay()->log().durationMs() + 1000);
        QCOMPARE(replay()->moment(), replay()->log().durationMs());
    }

    // Every event of the log is a marker and a row of the list, with its text; the write, the
    // move's command and the E-STOP are among them.
    void markersMatchEvents()
    {
        QVERIFY(openReplay(logPath));
        const QList<ReplayEvent> &events = replay()->log().events();
        ReplayBar *bar = replay()->bar();
        QCOMPARE(bar->slider()->markerCount(), int(events.size()));
        QCOMPARE(bar->eventList()->count(), int(events.size()));
        QStringList kinds;
        for (const ReplayEvent &e : events)
            kinds << ReplayEvent::kindName(e.kind);
        QVERIFY2(kinds.contains(QStringLiteral("write")), qPrintable(kinds.join(u' ')));
        QVERIFY2(kinds.contains(QStringLiteral("command")), qPrintable(kinds.join(u' ')));
        QVERIFY2(kinds.contains(QStringLiteral("estop")), qPrintable(kinds.join(u' ')));
        const auto checklist =
            std::find_if(events.cbegin(), events.cend(), [](const ReplayEvent &e) {
                return e.kind == ReplayEvent::Kind::User && e.text.startsWith(u"checklist");
            });
        QVERIFY2(checklist != events.cend(), qPrintable(kinds.join(u' ')));
        QCOMPARE(checklist->text, QStringLiteral("checklist motor1.direction: skipped"));
        // The page chosen and the changes confirmed, as the technician saw them.
        const auto userLine = [&events](QStringView start) {
            for (const ReplayEvent &e : events) {
                if (e.kind == ReplayEvent::Kind::User && e.text.startsWith(start))
                    return e.text;
            }
            return QString();
        };
        QCOMPARE(userLine(u"page 3"),
                 QStringLiteral("page 3: %1").arg(WindowProbe(*window).pages().at(2)->title()));
        QVERIFY2(userLine(u"write changes: ")
                     .startsWith(QStringLiteral("write changes: %1 = ").arg(key("speed"))),
                 qPrintable(userLine(u"write changes")));
        const auto estop = std::find_if(events.cbegin(), events.cend(), [](const ReplayEvent &e) {
            return e.kind == ReplayEvent::Kind::EmergencyStop;
        });
        const QStringList tip = bar->slider()->textsAt(bar->slider()->xOf(estop->ms));
        QVERIFY2(tip.join(u'\n').contains(estop->text), qPrintable(tip.join(u'\n')));
        const auto write = std::find_if(events.cbegin(), events.cend(), [](const ReplayEvent &e) {
            return e.kind == ReplayEvent::Kind::Write;
        });
        QVERIFY2(write->text.contains(key("speed")), qPrintable(write->text));
        // Choosing an event in the list shows its moment.
        const int row = int(estop - events.cbegin());
        bar->eventList()->setCurrentIndex(row);
        Q_EMIT bar->eventList()->activated(row);
        QCOMPARE(replay()->moment(), estop->ms);
    }

    // The machine strip shows the link as the log has it at the moment, and the log's line;
    // the session's own again when the replay ends.
    void theStripShowsTheLogsLink()
    {
        QVERIFY(openReplay(logPath));
        const QList<ReplayEvent> &events = replay()->log().events();
        const auto estop = std::find_if(events.cbegin(), events.cend(), [](const ReplayEvent &e) {
            return e.kind == ReplayEvent::Kind::EmergencyStop;
        });
        QVERIFY(estop != events.cend());
        ReplayBar *bar = replay()->bar();
        const int row = int(estop - events.cbegin());
        bar->eventList()->setCurrentIndex(row);
        Q_EMIT bar->eventList()->activated(row);
        MachineStrip *strip = WindowProbe(*window).machineStrip();
        QCOMPARE(strip->linkLabel()->text(), QStringLiteral("answering"));
        const QString line = static_cast<ElidedLabel *>(strip->lineLabel())->fullText();
        QVERIFY2(line.startsWith(QStringLiteral("replay: ")), qPrintable(line));
        QVERIFY2(line.contains(replay()->log().header().value(QStringLiteral("line"))),
                 qPrintable(line));
        closeReplay();
        QCOMPARE(strip->linkLabel()->text(), QStringLiteral("port closed"));
        QVERIFY(!static_cast<ElidedLabel *>(strip->lineLabel())
                     ->fullText()
                     .startsWith(QStringLiteral("replay: ")));
    }

    // Nothing that writes or moves a controller is enabled in a replay; E-STOP sends nothing.
    void nothingWritesInReplay()
    {
        const qsizetype sent =
            session->connection()->traffic()->entries().size(); // the recording's
        QVERIFY(openReplay(logPath));
        replay()->seek(replay()->log().durationMs() / 2);
        const QStringList enabled = test::enabledControls(
            window.get(),
            {"closeReplay", "openSessionLog", "closeReplayButton", "replayPlay", "replayBackFrame",
             "replayNextFrame", "replayBackEvent", "replayNextEvent"});
        QVERIFY2(enabled.isEmpty(), qPrintable(enabled.join(QLatin1Char('\n'))));
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("writeChanges"))->isEnabled());
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("saveToFlash"))->isEnabled());
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("readAll"))->isEnabled());
        // Nothing to stop: the E-STOP is greyed and says why; F12 still reaches the session,
        // which says that nothing was sent.
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("emergencyStop"))->isEnabled());
        QVERIFY(!WindowProbe(*window).emergencyStopButton()->isEnabled());
        QVERIFY(WindowProbe(*window).emergencyStopButton()->toolTip().contains(
            QStringLiteral("Nothing to stop")));
        QSignalSpy said(session.get(), &DeviceSession::message);
        QTest::keyClick(window.get(), Qt::Key_F12);
        QVERIFY(said.size() >= 1);
        QVERIFY(said.at(0).at(1).toString().contains(QStringLiteral("nothing was sent")));
        QCOMPARE(session->connection()->traffic()->entries().size(), sent);
        QVERIFY(replay()->isActive());
    }

    // Close replay and connecting both end it: the window is empty again.
    void waysOut()
    {
        QVERIFY(openReplay(logPath));
        replay()->seek(replay()->log().durationMs());
        QVERIFY(store()->deviceValue(key("position")).has_value());
        WindowProbe(*window).action(QStringLiteral("closeReplay"))->trigger();
        QVERIFY(!replay()->isActive());
        QVERIFY(!store()->isReplay());
        QVERIFY(!store()->deviceValue(key("position")).has_value());
        QVERIFY(!replay()->banner()->isVisibleTo(window.get()));
        QVERIFY(!window->windowTitle().contains(QStringLiteral("replay")));

        QVERIFY(openReplay(logPath));
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->connection()->connectSimulator();
        QVERIFY(!replay()->isActive());
        QVERIFY(read.wait(10000));
        // While connected a replay is refused, with why.
        QSignalSpy failed(replay(), &ReplayMode::failed);
        QVERIFY(!replay()->openPath(logPath));
        QCOMPARE(failed.size(), 1);
        QVERIFY(failed.at(0).at(0).toString().contains(QStringLiteral("Disconnect")));
        session->connection()->disconnectFrom();
        QTRY_VERIFY(!session->connection()->isConnected());
    }

    // A support bundle replays its log.
    void bundleReplays()
    {
        BundleInput input;
        input.logDirectory = dir.filePath(QStringLiteral("logs"));
        const QString zip = dir.filePath(QStringLiteral("bundle.zip"));
        QString error;
        QVERIFY2(SupportBundle::create(zip, input, nullptr, &error), qPrintable(error));
        QVERIFY(openReplay(zip));
        QVERIFY(replay()->displayName().contains(QStringLiteral("bundle.zip")));
        QCOMPARE(replay()->log().events().size(), replay()->bar()->slider()->markerCount());
    }

    // A log cut short opens with what it has, and says so.
    void truncatedLogOpensWithAWarning()
    {
        QByteArray bytes = recorded();
        bytes.chop(7);
        const QString path = writeFile(QStringLiteral("cut.log"), bytes);
        QSignalSpy said(replay(), &ReplayMode::finished);
        QVERIFY(openReplay(path));
        QVERIFY2(said.last().at(1).toString().contains(QStringLiteral("cut short")),
                 qPrintable(said.last().at(1).toString()));
    }

    // Help → Create support bundle…: the days' logs counted and sized, the bundle written and
    // said, and it replays (the round trip).
    void supportBundleFromTheHelpMenu()
    {
        WindowProbe(*window).action(QStringLiteral("createSupportBundle"))->trigger();
        auto *dialog = window->findChild<SupportBundleDialog *>();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        dialog->setLogDirectory(dir.filePath(QStringLiteral("logs")));
        dialog->setDays(3);
        QVERIFY2(dialog->logsText().startsWith(QStringLiteral("1 session log, ")),
                 qPrintable(dialog->logsText()));
        QCOMPARE(dialog->input().days, 3);
        QSignalSpy written(dialog, &SupportBundleDialog::written);
        const QString zip = dir.filePath(QStringLiteral("from-window.zip"));
        QVERIFY(dialog->createFile(zip));
        QVERIFY(written.wait(30000) || written.size() == 1); // on its own thread
        QCOMPARE(written.size(), 1);
        QVERIFY(written.at(0).at(0).toBool());
        const QString said = written.at(0).at(1).toString();
        QVERIFY2(said.contains(QStringLiteral("logs/session.log")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("README.txt")), qPrintable(said));
        QVERIFY(openReplay(zip));
        QCOMPARE(replay()->log().events().size(), replay()->bar()->slider()->markerCount());
    }

    // A low window (1024×600) gets the bar in one row; the replay never makes the window wider.
    void theBarFitsALaptop()
    {
        const int before = window->minimumSizeHint().width();
        QVERIFY(openReplay(logPath));
        window->resize(1024, 600);
        QCoreApplication::processEvents();
        QVERIFY(replay()->bar()->isCompact());
        QVERIFY2(window->minimumSizeHint().width() <= std::max(1024, before),
                 qPrintable(QStringLiteral("%1 > %2")
                                .arg(window->minimumSizeHint().width())
                                .arg(std::max(1024, before))));
        window->resize(1366, 900);
        QCoreApplication::processEvents();
        QVERIFY(!replay()->bar()->isCompact());
    }

    // A bundle of several logs asks which one, the newest first.
    void aBundleOfSeveralLogsAsks()
    {
        const QString logs = dir.filePath(QStringLiteral("two-logs"));
        QDir().mkpath(logs);
        QVERIFY(QFile::copy(logPath, logs + QStringLiteral("/a-older.log")));
        QVERIFY(QFile::copy(logPath, logs + QStringLiteral("/b-newer.log")));
        BundleInput input;
        input.logDirectory = logs;
        const QString zip = dir.filePath(QStringLiteral("two.zip"));
        QString error;
        QVERIFY2(SupportBundle::create(zip, input, nullptr, &error), qPrintable(error));
        QSignalSpy opened(replay(), &ReplayMode::opened);
        QVERIFY(replay()->openPath(zip));
        QInputDialog *chooser = replay()->entryChooser();
        QVERIFY(chooser);
        QVERIFY(chooser->isVisible());
        QCOMPARE(chooser->comboBoxItems(), (QStringList{"logs/b-newer.log", "logs/a-older.log"}));
        QVERIFY(!replay()->isActive());
        Q_EMIT chooser->textValueSelected(QStringLiteral("logs/a-older.log"));
        chooser->close();
        QVERIFY(opened.wait(15000) || !opened.isEmpty());
        QVERIFY(replay()->displayName().endsWith(QStringLiteral("logs/a-older.log")));
    }

    // A profile file opened during a replay ends it; while a file is edited a replay is refused.
    void aProfileFileAndAReplayTakeTurns()
    {
        const RegisterMap &map = session->map();
        const QString profile = dir.filePath(QStringLiteral("machine.json"));
        QCOMPARE(ProfileFile::save(
                     profile, Profile::fromValues(map, FactoryValues::writable(map), false), map),
                 QString());
        QVERIFY(openReplay(logPath));
        QVERIFY(WindowProbe(*window).offlineActions()->openFile(profile));
        QVERIFY(!replay()->isActive());
        QVERIFY(store()->isFile());
        QVERIFY(!replay()->banner()->isVisibleTo(window.get()));
        QSignalSpy failed(replay(), &ReplayMode::failed);
        QVERIFY(!replay()->openPath(logPath));
        QVERIFY(failed.at(0).at(0).toString().contains(QStringLiteral("profile file")));
        QVERIFY(WindowProbe(*window).offlineActions()->closeFile());
        QVERIFY(openReplay(logPath));
    }

    // `stepcomctl replay --at` agrees with the window at every chosen moment.
    void theCommandLineAgreesWithTheWindow()
    {
        QVERIFY(openReplay(logPath));
        for (const Moment &m : std::as_const(moments)) {
            checkCommandLineAt(m);
            if (QTest::currentTestFailed())
                return;
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReplayWindow, Gui)
#include "tst_replaywindow.moc"
