#pragma once

#include "base/language.h"
#include "device/statusrecorder.h"
#include "programrun.h"
#include "replay/replaybar.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "simsession.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/trafficmodel.h"
#include "widgets/docks/trafficview.h"
#include "window/mainwindow.h"

#include <QApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMessageBox>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <memory>
#include <optional>

namespace stepcom::test {

// What the window's replay suites share: a window on a session with the built-in
// simulator, a scratch folder, and the replay opened as a user opens it (openPath, then the
// opening on its thread); for a session the window records itself, the moments it held and
// the checks that the replay (and `stepcomctl replay --at`) shows the same at each.
class ReplayFixture : public QObject
{
protected:
    // What the session held at a moment, and that moment's clock time in the log.
    struct Moment
    {
        QString what;
        QString clock;
        QHash<QString, qint64> values;
        QString position1;                           // the strip's text, when it had settled
        std::optional<MachineStrip::Motion> motion1; // the strip's, when it had settled
    };

    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<MainWindow> window;
    QTemporaryDir dir;
    QString logPath; // where the window records its session
    QList<Moment> moments;

    void openWindow()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
        session = std::make_unique<DeviceSession>();
        useBuiltinSimulator(*session);
        window = std::make_unique<MainWindow>(session.get());
        window->show();
    }
    void closeWindow()
    {
        window.reset();
        session.reset();
    }
    // Between tests: no replay, no message left open.
    void closeReplay()
    {
        replay()->close();
        if (replay()->errorBox())
            replay()->errorBox()->close();
    }
    // What the session holds at the end of the next status cycle that satisfies `when`, taken
    // in the cycle's own signal: the poller puts a cycle's values into the store at its end, so
    // between its reads the log is ahead of the window.
    void captureAtCycleEnd(const QString &what, bool withStrip,
                           const std::function<bool()> &when = {})
    {
        std::optional<Moment> taken;
        const auto c = connect(
            session->status(), &SessionStatus::statusCycleFinished, this, [&](bool ok, qint64) {
                if (taken || !ok || (when && !when()))
                    return;
                QFile f(logPath);
                if (!f.open(QIODevice::ReadOnly))
                    return;
                const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
                Moment m;
                m.what = what;
                m.clock = QString::fromLatin1(lines.last().mid(11, 12));
                m.values = deviceValues();
                if (withStrip) { // settled: the strip shows these values
                    m.position1 = window->machineStrip()->positionLabel(1)->text();
                    m.motion1 = window->machineStrip()->motion(1);
                }
                taken = m;
            });
        const auto stop = qScopeGuard([&] { disconnect(c); }); // also when the wait fails
        QTRY_VERIFY2_WITH_TIMEOUT(taken.has_value(), qPrintable(what), 20000);
        moments << *taken;
    }
    // The same once motor 1 stands still: the same position two cycles running, so the strip
    // shows it already.
    void captureSettled(const QString &what)
    {
        std::optional<qint64> last;
        captureAtCycleEnd(what, true, [this, &last] {
            const auto now = store()->deviceValue(key("position"));
            const bool same = now.has_value() && now == last &&
                              store()->deviceValue(key("running")).value_or(1) == 0;
            last = now;
            return same;
        });
    }
    // The replay at `m`: the store, the strip, the bar and the plots show what the session
    // held then. A failure is recorded for the running test (QTest::currentTestFailed()).
    void checkReplayAt(const Moment &m)
    {
        QString error;
        const auto ms = replay()->log().parseTime(m.clock, &error);
        QVERIFY2(ms, qPrintable(error));
        replay()->seek(*ms);
        QCoreApplication::processEvents();
        QCOMPARE(replay()->moment(), *ms);
        const QHash<QString, qint64> shown = deviceValues();
        for (auto it = m.values.cbegin(); it != m.values.cend(); ++it)
            QVERIFY2(shown.value(it.key(), -1) == it.value(),
                     qPrintable(QStringLiteral("%1 at %2: %3, held %4")
                                    .arg(it.key(), m.what)
                                    .arg(shown.value(it.key(), -1))
                                    .arg(it.value())));
        QVERIFY2(shown.size() == m.values.size(),
                 qPrintable(QStringLiteral("at %1: %2 values shown, %3 held")
                                .arg(m.what)
                                .arg(shown.size())
                                .arg(m.values.size())));
        if (!m.position1.isEmpty())
            QVERIFY2(window->machineStrip()->positionLabel(1)->text() == m.position1,
                     qPrintable(QStringLiteral("at %1: the strip shows %2, it showed %3")
                                    .arg(m.what, window->machineStrip()->positionLabel(1)->text(),
                                         m.position1)));
        // Settled, as the live strip showed it (at a limit, say); else as the running flag says.
        QCOMPARE(window->machineStrip()->motion(1),
                 m.motion1.value_or(m.values.value(key("running")) == 1
                                        ? MachineStrip::Motion::Running
                                        : MachineStrip::Motion::Idle));
        QCOMPARE(replay()->bar()->momentLabel()->text(), replay()->log().momentText(*ms));
        // The plots end at the moment too, with the same position.
        const StatusRecorder *plots = session->status()->recorder();
        QVERIFY(!plots->isEmpty());
        QVERIFY(plots->last().elapsedMs <= *ms);
        QCOMPARE(
            plots->last().positions.value(0),
            session->map().find(key("position"))->toEngineering(m.values.value(key("position"))));
        QCOMPARE(plots->last().running.value(0), qint8(m.values.value(key("running"))));
        TrafficModel *traffic = window->trafficView()->model();
        traffic->flush();
        QVERIFY(traffic->storedCount() > 0);
    }
    // `stepcomctl replay --at` at `m` says what the session held then (in engineering units).
    void checkCommandLineAt(const Moment &m)
    {
        const ProgramRun r = runProgram(QStringLiteral("stepcomctl"),
                                        {"replay", logPath, "--at", m.clock, "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject cli = QJsonDocument::fromJson(r.out.toUtf8())
                                    .object()
                                    .value(QStringLiteral("devices"))
                                    .toObject()
                                    .value(QStringLiteral("1"))
                                    .toObject()
                                    .value(QStringLiteral("values"))
                                    .toObject();
        QVERIFY2(cli.size() == m.values.size(),
                 qPrintable(QStringLiteral("at %1: stepcomctl %2 values, the window held %3")
                                .arg(m.what)
                                .arg(cli.size())
                                .arg(m.values.size())));
        for (auto it = m.values.cbegin(); it != m.values.cend(); ++it)
            QVERIFY2(cli.value(it.key()).toDouble() ==
                         session->map().find(it.key())->toEngineering(it.value()),
                     qPrintable(QStringLiteral("%1 at %2: window %3, stepcomctl %4")
                                    .arg(it.key(), m.what)
                                    .arg(it.value())
                                    .arg(cli.value(it.key()).toDouble())));
    }

    ParameterStore *store() const { return session->parameters()->store(); }
    ReplayMode *replay() const { return window->replayMode(); }
    QString key(const char *role) const
    {
        return session->map().blockParameter(QStringLiteral("motor"), 1, QLatin1String(role))->key;
    }
    QHash<QString, qint64> deviceValues() const
    {
        QHash<QString, qint64> out;
        for (const Parameter *p : session->map().holdings()) {
            if (const auto v = store()->deviceValue(p->key))
                out.insert(p->key, *v);
        }
        return out;
    }
    bool openReplay(const QString &path)
    {
        QSignalSpy opened(replay(), &ReplayMode::opened);
        if (!replay()->openPath(path))
            return false;
        return opened.wait(15000) || !opened.isEmpty();
    }
    QString failure(const QString &path)
    {
        QSignalSpy failed(replay(), &ReplayMode::failed);
        if (replay()->openPath(path) && failed.isEmpty() && !failed.wait(15000))
            return QString();
        return failed.value(0).value(0).toString();
    }
    QString writeFile(const QString &name, const QByteArray &bytes) const
    {
        const QString path = dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            return {};
        return path;
    }
};

} // namespace stepcom::test
