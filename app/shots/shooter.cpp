#include "shooter.h"

#include "base/language.h"
#include "base/page.h"
#include "scenes.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "sim/host/builtinsimulator.h"
#include "sim/host/simhost.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QHash>
#include <QImage>
#include <QPainter>
#include <QPixmap>
#include <QScreen>
#include <QTextStream>
#include <QWindow>

#include <memory>

namespace stepcom {

namespace {

// Enough status cycles after the first read-all that every lamp and position is known.
constexpr int kPollCycles = 3;
// Long enough for a page's deferred refreshes (coalescing timers of 100-200 ms) to land.
constexpr int kSettleMs = 400;

} // namespace

Shooter::Shooter(const Options &options, QObject *parent)
    : QObject(parent)
    , m_options(options)
{
    connect(&m_script, &Script::finished, this, [this](bool ok, const QString &error) {
        closeWindow();
        m_done = true;
        Q_EMIT finished(ok, error);
    });
}

Shooter::~Shooter()
{
    closeWindow();
}

QString Shooter::pageFileName(const QList<Page *> &pages, int index)
{
    const auto baseName = [](const Page *page) {
        QString name = QString::fromLatin1(page->metaObject()->className());
        name = name.mid(name.lastIndexOf(QLatin1Char(':')) + 1);
        if (!name.isEmpty())
            name[0] = name.at(0).toLower();
        return name;
    };
    const Page *page = pages.at(index);
    QString name = page->objectName();
    if (name.isEmpty()) {
        name = baseName(page);
        int same = 0;
        int number = 0;
        for (int i = 0; i < pages.size(); ++i) {
            if (pages.at(i)->objectName().isEmpty() && baseName(pages.at(i)) == name) {
                ++same;
                if (i == index)
                    number = same;
            }
        }
        if (same > 1)
            name += QString::number(number);
    }
    return QStringLiteral("%1-%2.png").arg(index + 1, 2, 10, QLatin1Char('0')).arg(name);
}

void Shooter::start()
{
    for (const QString &language : std::as_const(m_options.languages))
        planLanguage(language);
    m_script.start();
}

void Shooter::planLanguage(const QString &language)
{
    m_script.then([this, language] { openWindow(language); });
    m_script.waitFor(QStringLiteral("the first read-all"), [this] { return m_readOk; });
    m_script.then([this] {
        // A few status cycles on top, so the dock's lamps and positions are all known.
        auto cycles = std::make_shared<int>(0);
        connect(m_session->status(), &SessionStatus::statusCycleFinished, this,
                [cycles](bool ok) { *cycles += ok ? 1 : 0; });
        m_script.waitFor(QStringLiteral("%1 status poll cycles").arg(kPollCycles),
                         [cycles] { return *cycles >= kPollCycles; });
    });
    m_script.then([this] { planPages(); });
    m_script.then([this] { closeWindow(); });
}

void Shooter::openWindow(const QString &language)
{
    m_language = language;
    if (!Language::instance().setLanguage(language)) {
        m_script.fail(QStringLiteral("no translation for language %1").arg(language));
        return;
    }
    QDir dir(m_options.outDir.filePath(language));
    if (!dir.mkpath(QStringLiteral("."))) {
        m_script.fail(QStringLiteral("cannot create %1").arg(dir.path()));
        return;
    }
    // Pictures of pages and scenes that no longer exist must not linger (a run of chosen
    // scenes only replaces what it takes).
    if (m_options.onlyScenes.isEmpty()) {
        for (const QString &old : dir.entryList({QStringLiteral("*.png")}, QDir::Files))
            dir.remove(old);
    }

    m_session = std::make_unique<DeviceSession>();
    auto sim = std::make_unique<BuiltinSimulator>();
    sim->setIds({1, 2, 3}); // the device list's scene shows a line of three controllers
    m_sim = sim->host();
    m_session->setSimulator(std::move(sim));
    m_readOk = false;
    connect(m_session->parameters(), &SessionParameters::readFinished, this, [this](bool ok) {
        if (ok)
            m_readOk = true;
    });
    m_window = std::make_unique<MainWindow>(m_session.get());
    m_window->resize(m_options.size);
    m_window->show();
    m_window->activateWindow();
    m_session->connection()->connectSimulator();
    m_script.waitFor(QStringLiteral("the window to become active"),
                     [this] { return m_window->isActiveWindow(); });
}

void Shooter::planPages()
{
    const auto wanted = [this](const Scene &scene) {
        return m_options.onlyScenes.isEmpty() || m_options.onlyScenes.contains(scene.name);
    };
    for (const Scene &scene : scenes()) {
        if (scene.when == Scene::When::BeforePages)
            scene.plan(*this);
    }
    const QList<Page *> &pages = WindowProbe(*m_window).pages();
    for (int i = 0; i < pages.size(); ++i)
        shoot(pageFileName(pages, i), i);
    for (const Scene &scene : scenes()) {
        if (scene.when == Scene::When::AfterPages && wanted(scene))
            scene.plan(*this);
    }
}

void Shooter::closeWindow()
{
    m_window.reset();
    m_session.reset();
    m_sim = nullptr;
    m_extraSim.reset();
}

SimHost *Shooter::extraSimulator(int deviceId)
{
    m_extraSim = std::make_unique<SimHost>();
    SimOptions options;
    options.rtu = true;
    options.deviceId = deviceId;
    QString error;
    if (!m_extraSim->start(options, &error)) {
        m_extraSim.reset();
        m_script.fail(QStringLiteral("the second simulator did not start: %1").arg(error));
        return nullptr;
    }
    return m_extraSim.get();
}

void Shooter::shoot(const QString &fileName, int page, std::function<QWidget *()> dialog)
{
    m_script.then([this, page] {
        if (page >= 0)
            WindowProbe(*m_window).showPage(page);
    });
    m_script.sleep(kSettleMs);
    m_script.then([this, fileName, dialog] {
        QWidget *over = dialog ? dialog() : nullptr;
        if (dialog && !over) {
            m_script.fail(QStringLiteral("%1: the dialog is not open").arg(fileName));
            return;
        }
        save(composite(m_window.get(), over), fileName);
    });
}

void Shooter::shootOnScreen(const QString &fileName, int page, const QString &screenName)
{
    QScreen *target = nullptr;
    for (QScreen *screen : QGuiApplication::screens()) {
        if (screen->name() == screenName)
            target = screen;
    }
    if (!target) {
        m_script.then([this, screenName] {
            m_script.fail(QStringLiteral("no screen %1 (run offscreen, as scripts/screenshots.sh "
                                         "does)")
                              .arg(screenName));
        });
        return;
    }
    // What a first start on that screen does (app/stepcom/main.cpp: the constructor's
    // restoreLayout with nothing saved, then showOnScreen), on this window.
    auto saved = std::make_shared<QByteArray>();
    m_script.then([this, target, saved] {
        *saved = m_window->saveState();
        m_window->hide();
        // The picture is the window's inside: without a frame, maximized fills the screen
        // (the offscreen platform keeps a frame's margins from a maximized window).
        m_window->setWindowFlag(Qt::FramelessWindowHint, true);
        m_window->setScreen(target);
        m_window->move(target->availableGeometry().topLeft());
        WindowProbe(*m_window).useDefaultLayout();
        m_window->showOnScreen();
    });
    m_script.waitFor(QStringLiteral("the window to fill %1").arg(screenName), [this, target] {
        return m_window->isVisible() && m_window->screen() == target &&
               m_window->size() == target->availableGeometry().size();
    });
    m_script.then([this, page] {
        if (page >= 0)
            WindowProbe(*m_window).showPage(page);
    });
    m_script.sleep(kSettleMs);
    m_script.then([this, fileName, saved] {
        save(composite(m_window.get(), nullptr), fileName);
        m_window->hide();
        m_window->setWindowFlag(Qt::FramelessWindowHint, false);
        m_window->setWindowState(Qt::WindowNoState);
        m_window->setScreen(QGuiApplication::primaryScreen());
        m_window->setGeometry(
            QRect(QGuiApplication::primaryScreen()->availableGeometry().topLeft(), m_options.size));
        m_window->restoreState(*saved);
        m_window->show();
        m_window->activateWindow();
    });
    m_script.waitFor(QStringLiteral("the window back on the first screen"), [this] {
        return m_window->screen() == QGuiApplication::primaryScreen() &&
               m_window->size() == m_options.size;
    });
}

QImage Shooter::composite(QWidget *window, QWidget *dialog)
{
    QImage image = window->grab().toImage().convertToFormat(QImage::Format_RGB32);
    if (!dialog)
        return image;
    // The dialog as it floats over the window: dimmed window, a shadow, a frame.
    const QImage top = dialog->grab().toImage();
    QPainter p(&image);
    p.fillRect(image.rect(), QColor(0, 0, 0, 60));
    QRect where(QPoint(0, 0), top.size());
    where.moveCenter(image.rect().center());
    where.moveTop(std::max(0, where.top()));
    where.moveLeft(std::max(0, where.left()));
    p.fillRect(where.translated(6, 6), QColor(0, 0, 0, 70));
    p.drawImage(where.topLeft(), top);
    p.setPen(dialog->palette().color(QPalette::Shadow));
    p.drawRect(where.adjusted(-1, -1, 0, 0));
    return image;
}

bool Shooter::save(const QImage &image, const QString &fileName)
{
    const QString path = m_options.outDir.filePath(m_language + QLatin1Char('/') + fileName);
    // Quality 0 is PNG's strongest compression: the pictures live in git.
    if (image.isNull() || !image.save(path, "PNG", 0)) {
        m_script.fail(QStringLiteral("cannot write %1").arg(path));
        return false;
    }
    m_written << path;
    QTextStream(stdout) << path << Qt::endl;
    return true;
}

} // namespace stepcom
