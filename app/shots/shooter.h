#pragma once

#include "base/page.h"
#include "script.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QDir>
#include <QSize>
#include <QStringList>
#include <QTemporaryDir>

#include <memory>

class QWidget;

namespace stepcom {

class DeviceSession;
class SimHost;

// Takes the guide's screenshots from the real window on the built-in simulator: one picture of
// every page in the window's sidebar (whatever pages the window has) and the scenes of
// scenes.cpp, for each language, into <out>/<language>/.
class Shooter : public QObject
{
    Q_OBJECT
public:
    struct Options
    {
        QDir outDir;
        QStringList languages;
        QSize size{1280, 800};
        QStringList onlyScenes; // empty: every scene
    };

    explicit Shooter(const Options &options, QObject *parent = nullptr);
    ~Shooter() override;

    void start();

    // "<NN>-<name>.png" for the page at `index` (NN from 01): the page's object name, else its
    // class name (without namespace, first letter lower case) with a 1-based number when the
    // window has more than one page of that class (motorPage1, motorPage2).
    static QString pageFileName(const QList<Page *> &pages, int index);
    static QString sceneFileName(const QString &scene)
    {
        return QStringLiteral("scene-%1.png").arg(scene);
    }

    // For the scenes: what they work with, and how they take their picture.
    Script &script() { return m_script; }
    MainWindow *window() const { return m_window.get(); }
    DeviceSession *session() const { return m_session.get(); }
    // The built-in simulator the session runs on, to set the machine up for a scene.
    SimHost *simulator() const { return m_sim; }
    const QString &language() const { return m_language; }
    // Index of the first page of class T in the sidebar, -1 if the window has none.
    template<typename T>
    int pageIndex() const;
    // Plans: show the page (when >= 0), let it settle, grab the window (with `dialog` drawn
    // over it, centred, when given) and save it as `fileName`.
    void shoot(const QString &fileName, int page = -1, std::function<QWidget *()> dialog = {});
    // As shoot(), with the window as the program first starts on the screen `screenName`
    // (MainWindow::useDefaultLayout and showOnScreen there: maximized on a laptop's screen, the
    // docks arranged and sized for it); it goes back to the first screen, its usual size and
    // its docks as they were afterwards.
    void shootOnScreen(const QString &fileName, int page, const QString &screenName);
    // A second simulated controller on a pty, for the scan scene; null when it cannot start
    // (the reason goes to the script).
    SimHost *extraSimulator(int deviceId);
    // A path for a scratch file (profiles the scenes save and open), removed at the end.
    QString scratchPath(const QString &fileName) const { return m_scratch.filePath(fileName); }

    QStringList written() const { return m_written; }
    // The script ran to its end (successfully or not).
    bool isDone() const { return m_done; }

Q_SIGNALS:
    void finished(bool ok, const QString &error);

private:
    void planLanguage(const QString &language);
    void openWindow(const QString &language);
    void planPages();
    void closeWindow();
    bool save(const QImage &image, const QString &fileName);
    static QImage composite(QWidget *window, QWidget *dialog);

    Options m_options;
    Script m_script;
    QString m_language;
    std::unique_ptr<DeviceSession> m_session;
    std::unique_ptr<MainWindow> m_window;
    SimHost *m_sim = nullptr; // owned by the session
    std::unique_ptr<SimHost> m_extraSim;
    QTemporaryDir m_scratch;
    QStringList m_written;
    bool m_readOk = false;
    bool m_done = false;
};

template<typename T>
int Shooter::pageIndex() const
{
    if (!m_window)
        return -1;
    const QList<Page *> &pages = WindowProbe(*m_window).pages();
    for (int i = 0; i < pages.size(); ++i) {
        if (qobject_cast<T *>(pages.at(i)))
            return i;
    }
    return -1;
}

} // namespace stepcom
