#pragma once

#include "language.h"
#include "mainwindow.h"
#include "replaymode.h"
#include "session/devicesession.h"
#include "simsession.h"

#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <memory>

namespace stepcom::test {

// What the window's replay suites (issue 26) share: a window on a session with the built-in
// simulator, a scratch folder, and the replay opened as a user opens it (openPath, then the
// opening on its thread).
class ReplayFixture : public QObject
{
protected:
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<MainWindow> window;
    QTemporaryDir dir;

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
    ParameterStore *store() const { return session->parameters(); }
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
