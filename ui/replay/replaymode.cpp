#include "replay/replaymode.h"

#include "base/page.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "device/statusrecorder.h"
#include "pages/checklistpage.h"
#include "replay/replaybar.h"
#include "replay/replayviews.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/reconnector.h"
#include "session/sessionlog.h"
#include "support/supportbundle.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/pagesidebar.h"
#include "widgets/docks/trafficview.h"

#include <QAction>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
#include <QVBoxLayout>

#include <atomic>

namespace stepcom {

// A log being opened on a thread of its own; the window asks it how far it got.
struct ReplayMode::Opening
{
    ReplayLog log;
    QString path;
    QString name;
    std::unique_ptr<QTemporaryDir> unpacked;
    std::atomic<bool> cancel{false};
    std::atomic<qint64> done{0};
    std::atomic<qint64> total{0};
    bool ok = false;
    QThread *thread = nullptr;
    QTimer poll;
};

namespace {

constexpr int kProgressSteps = 1000;
constexpr int kProgressPollMs = 100;
constexpr qint64 kFirstBackSpanMs = 1000;

bool isZip(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) && f.read(4) == QByteArrayLiteral("PK\x03\x04");
}

} // namespace

ReplayMode::ReplayMode(DeviceSession *session, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_window(window)
    , m_open(new QAction(this))
    , m_close(new QAction(this))
    , m_banner(new QFrame(window))
    , m_bannerText(new QLabel(m_banner))
    , m_bannerState(new QLabel(m_banner))
    , m_bar(new ReplayBar(window))
    , m_views(new ReplayViews(session, this))
    , m_log(session->map())
{
    m_open->setObjectName(QStringLiteral("openSessionLog"));
    m_open->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    m_close->setObjectName(QStringLiteral("closeReplay"));
    m_close->setEnabled(false);
    connect(m_open, &QAction::triggered, this, &ReplayMode::choose);
    connect(m_close, &QAction::triggered, this, &ReplayMode::close);
    // Marked as offline editing is, in its own colour: a recording, not a machine.
    m_banner->setObjectName(QStringLiteral("replayBanner"));
    m_banner->setStyleSheet(
        QStringLiteral("QFrame#replayBanner { background: #fff0c8; border: 1px solid #b8860b; } "
                       "QFrame#replayBanner QLabel { color: black; }"));
    m_bannerText->setObjectName(QStringLiteral("replayBannerTitle"));
    m_bannerText->setWordWrap(true);
    m_bannerText->setTextFormat(Qt::PlainText);
    QFont bold = m_bannerText->font();
    bold.setBold(true);
    m_bannerText->setFont(bold);
    m_bannerState->setObjectName(QStringLiteral("replayBannerState"));
    m_bannerState->setWordWrap(true);
    m_bannerState->setTextFormat(Qt::PlainText);
    auto *bannerLayout = new QVBoxLayout(m_banner);
    bannerLayout->addWidget(m_bannerText);
    bannerLayout->addWidget(m_bannerState);
    m_banner->hide();
    m_bar->hide();
    connect(m_bar, &ReplayBar::seekRequested, this, &ReplayMode::seek);
    connect(m_bar, &ReplayBar::stepFrame, this, &ReplayMode::stepFrame);
    connect(m_bar, &ReplayBar::deviceChosen, this, &ReplayMode::showDevice);
    connect(m_bar, &ReplayBar::closeRequested, this, &ReplayMode::close);
    // Connecting or opening a profile file is the way out too.
    connect(session->connection(), &SessionConnection::linkStateChanged, this, [this] {
        if (m_active &&
            m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
            close();
    });
    connect(session->parameters()->store(), &ParameterStore::originChanged, this, [this] {
        if (m_active && m_session->parameters()->store()->isFile())
            close();
    });
    retranslate();
}

ReplayMode::~ReplayMode()
{
    if (m_opening) {
        m_opening->cancel = true;
        m_opening->thread->wait();
    }
}

void ReplayMode::recordActions(SessionLog *log, PageSidebar *sidebar, const QList<Page *> &pages,
                               WriteFlow *writes, ChecklistPage *checklist, DeviceListDock *devices)
{
    log->setDeviceNames(devices->names());
    connect(devices, &DeviceListDock::namesChanged, log,
            [log, devices] { log->setDeviceNames(devices->names()); });
    // Only while a connection is logged (SessionLog writes nothing before the first one), in
    // the words the technician saw.
    connect(sidebar, &PageSidebar::pageChosen, log, [log, pages](int index) {
        if (index >= 0 && index < pages.size())
            log->noteUserAction(
                QStringLiteral("page %1: %2").arg(index + 1).arg(pages.at(index)->title()));
    });
    connect(writes, &WriteFlow::confirmed, log, [log](const QString &what) {
        log->noteUserAction(QStringLiteral("write changes: ") + what);
    });
    connect(checklist, &ChecklistPage::resultRecorded, log, &SessionLog::noteUserAction);
}

void ReplayMode::setViews(const Views &views)
{
    m_views->setTrafficView(views.traffic);
    m_views->setDeviceList(views.devices);
    m_views->setPlots(views.plots);
    m_strip = views.strip;
}

QMessageBox *ReplayMode::errorBox() const
{
    return m_errorBox;
}

QProgressDialog *ReplayMode::progress() const
{
    return m_progress;
}

QInputDialog *ReplayMode::entryChooser() const
{
    return m_chooser;
}

QString ReplayMode::bannerText() const
{
    return tr("Replay of %1 — nothing is written or moved. The pages show what the log says the "
              "controller held at the moment chosen below; connect or close the replay to work "
              "with a controller.")
        .arg(m_name);
}

QString ReplayMode::stateText(const ReplayState &state) const
{
    const ReplayDevice device = state.devices.value(m_device);
    // Whole sentences, so each language words them its own way.
    QString text =
        (state.linkUp ? tr("At this moment the link is up.")
                      : tr("At this moment the link is down.")) +
        QLatin1Char(' ') +
        (device.answering ? tr("Id %1 answers.") : tr("Id %1 does not answer.")).arg(m_device);
    if (!device.lastError.isEmpty())
        text += QLatin1Char(' ') + tr("Its last error, at %1: %2.")
                                       .arg(m_log.momentText(device.lastErrorMs), device.lastError);
    return text;
}

void ReplayMode::retranslate()
{
    m_open->setText(tr("Open session &log…"));
    m_open->setToolTip(tr("Replay a session log or a support bundle: see what the window showed "
                          "then, without a controller (%1)")
                           .arg(m_open->shortcut().toString(QKeySequence::NativeText)));
    m_close->setText(tr("Close re&play"));
    m_bannerText->setText(bannerText());
    if (m_active) // the words of the new language
        m_stateText = stateText(m_log.stateAt(m_moment));
    m_bannerState->setText(m_stateText);
}

bool ReplayMode::refused(QString *why) const
{
    if (m_opening)
        *why = tr("A session log is being opened already.");
    else if (m_session->connection()->reconnector()->isActive())
        *why = tr("StepCom is trying to reconnect to the controller: cancel that before "
                  "replaying a log.");
    else if (m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
        *why = tr("Disconnect from the controller before replaying a log: a replay shows the "
                  "log's values where the controller's are.");
    else if (m_session->parameters()->store()->isFile())
        *why = tr("Close the profile file before replaying a log.");
    return !why->isEmpty();
}

void ReplayMode::choose()
{
    auto *dialog =
        new QFileDialog(m_window, tr("Open session log"), SessionLog::defaultDirectory(),
                        tr("Session logs and support bundles (*.log *.txt *.zip);;All files (*)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, &ReplayMode::openPath);
    dialog->open();
}

bool ReplayMode::openPath(const QString &path)
{
    QString why;
    if (refused(&why)) {
        fail(why);
        return false;
    }
    if (!isZip(path))
        return startOpening(path, QFileInfo(path).fileName(), nullptr);
    QString error;
    const QStringList logs = SupportBundle::logs(path, &error);
    if (logs.isEmpty()) {
        fail(tr("%1 cannot be replayed: %2").arg(QFileInfo(path).fileName(), error));
        return false;
    }
    if (logs.size() == 1)
        return openBundleEntry(path, logs.first());
    chooseEntry(path, logs);
    return true;
}

void ReplayMode::chooseEntry(const QString &zipPath, const QStringList &logs)
{
    QStringList newestFirst(logs.crbegin(), logs.crend());
    m_chooser = new QInputDialog(m_window);
    m_chooser->setAttribute(Qt::WA_DeleteOnClose);
    m_chooser->setWindowTitle(tr("Open session log"));
    m_chooser->setLabelText(
        tr("%1 holds %n session log(s). Which one to replay?", nullptr, int(logs.size()))
            .arg(QFileInfo(zipPath).fileName()));
    m_chooser->setComboBoxItems(newestFirst);
    m_chooser->setTextValue(newestFirst.first());
    connect(m_chooser, &QInputDialog::textValueSelected, this,
            [this, zipPath](const QString &entry) { openBundleEntry(zipPath, entry); });
    m_chooser->open();
}

bool ReplayMode::openBundleEntry(const QString &zipPath, const QString &entry)
{
    QString why;
    if (refused(&why)) {
        fail(why);
        return false;
    }
    auto unpacked = std::make_unique<QTemporaryDir>();
    QString error;
    const QString path = SupportBundle::extract(zipPath, entry, unpacked->path(), &error);
    if (path.isEmpty()) {
        fail(tr("%1 cannot be replayed: %2").arg(QFileInfo(zipPath).fileName(), error));
        return false;
    }
    return startOpening(path, QStringLiteral("%1: %2").arg(QFileInfo(zipPath).fileName(), entry),
                        std::move(unpacked));
}

bool ReplayMode::startOpening(const QString &path, const QString &name,
                              std::unique_ptr<QTemporaryDir> unpacked)
{
    auto opening = std::make_shared<Opening>();
    opening->log = ReplayLog(m_session->map());
    opening->path = path;
    opening->name = name;
    opening->unpacked = std::move(unpacked);
    Opening *o = opening.get();
    // ReplayLog streams the file once; a big one takes a while, so not on the GUI thread.
    o->thread = QThread::create([o] {
        ReplayLog::Callbacks callbacks;
        callbacks.progress = [o](qint64 done, qint64 total) {
            o->done = done;
            o->total = total;
        };
        callbacks.cancelled = [o] { return o->cancel.load(); };
        o->ok = o->log.open(o->path, callbacks);
    });
    m_opening = opening;
    m_progress =
        new QProgressDialog(tr("Reading %1…").arg(name), tr("Cancel"), 0, kProgressSteps, m_window);
    m_progress->setWindowTitle(tr("Open session log"));
    m_progress->setMinimumDuration(500);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    connect(m_progress, &QProgressDialog::canceled, this, [o] { o->cancel = true; });
    o->poll.setInterval(kProgressPollMs);
    connect(&o->poll, &QTimer::timeout, this, [this, o] {
        if (m_progress && o->total > 0)
            m_progress->setValue(int(o->done * kProgressSteps / o->total));
    });
    o->poll.start();
    connect(o->thread, &QThread::finished, this, &ReplayMode::openingDone);
    connect(o->thread, &QThread::finished, o->thread, &QObject::deleteLater);
    o->thread->start();
    return true;
}

void ReplayMode::openingDone()
{
    const std::shared_ptr<Opening> o = std::move(m_opening);
    o->poll.stop();
    if (m_progress)
        m_progress->deleteLater();
    // Cancel pressed after the last chunk was read still means: do not open it.
    if (!o->ok || o->cancel) {
        fail(o->cancel || o->log.problem() == ReplayLog::Problem::Cancelled
                 ? tr("Opening %1 was cancelled.").arg(o->name)
                 : tr("%1 cannot be replayed: %2").arg(o->name, o->log.errorString()));
        return;
    }
    if (m_active)
        close();
    // The plots show the log now; a CSV recording of the live status ends here.
    if (m_session->status()->recorder()->isRecording())
        m_session->status()->recorder()->stopRecording();
    m_log = o->log;
    m_unpacked = std::move(o->unpacked);
    m_name = o->name;
    m_devices = m_log.stateAt(m_log.durationMs()).devices.keys();
    m_device = m_devices.value(0, 0);
    m_moment = 0;
    m_active = true;
    m_views->start(&m_log, [this](int id) { showDevice(id); });
    const ReplayLog *log = &m_log;
    m_bar->setLog(m_log.durationMs(), m_log.events(), m_devices,
                  [log](qint64 ms) { return log->momentText(ms); });
    m_bar->setDevice(m_device);
    m_close->setEnabled(true);
    retranslate();
    m_banner->show();
    m_bar->show();
    showMoment();
    Q_EMIT activeChanged(true);
    Q_EMIT opened();
    QString said = tr("Replaying %1: %2 s, %n event(s).", nullptr, int(m_log.events().size()))
                       .arg(m_name)
                       .arg(double(m_log.durationMs()) / 1000.0, 0, 'f', 1);
    for (const QString &w : m_log.warnings())
        said += QLatin1Char(' ') + tr("Warning: %1.").arg(w);
    Q_EMIT finished(true, said);
}

void ReplayMode::fail(const QString &reason)
{
    if (m_errorBox)
        m_errorBox->deleteLater();
    m_errorBox = new QMessageBox(QMessageBox::Warning, tr("Open session log"), reason,
                                 QMessageBox::Ok, m_window);
    m_errorBox->setAttribute(Qt::WA_DeleteOnClose);
    m_errorBox->open();
    Q_EMIT failed(reason);
    Q_EMIT finished(false, reason);
}

void ReplayMode::seek(qint64 ms)
{
    if (!m_active)
        return;
    m_moment = std::clamp<qint64>(ms, 0, m_log.durationMs());
    showMoment();
}

void ReplayMode::showDevice(int id)
{
    if (!m_active || !m_devices.contains(id))
        return;
    m_device = id;
    m_bar->setDevice(id);
    showMoment();
}

void ReplayMode::showMoment()
{
    const ReplayState state = m_log.stateAt(m_moment);
    m_session->parameters()->store()->showReplay(m_name,
                                                 state.devices.value(m_device).values(m_log.map()));
    m_views->show(m_moment, m_device, m_devices, state);
    m_bar->setMoment(m_moment);
    if (m_strip) { // the line as the log's header names it (an older log: not known)
        const QString line = m_log.header().value(QStringLiteral("line"));
        m_strip->showReplayLink(state.linkUp, state.devices.value(m_device).answering,
                                line.isEmpty() ? QString() : tr("replay: %1").arg(line));
    }
    m_stateText = stateText(state);
    m_bannerState->setText(m_stateText);
    Q_EMIT momentChanged(m_moment);
}

void ReplayMode::stepFrame(int direction)
{
    if (!m_active)
        return;
    std::optional<qint64> to;
    if (direction > 0) {
        m_log.walk(m_moment + 1, m_log.durationMs(),
                   [&](QByteArrayView, const LogLine &line, qint64 ms, const ReplayState &) {
                       if (line.type != LogLine::Type::Frame || ms <= m_moment)
                           return true;
                       to = ms;
                       return false;
                   });
    } else {
        // Back through ever longer spans until a frame before the moment is found.
        for (qint64 span = kFirstBackSpanMs; !to && m_moment > 0; span *= 4) {
            const qint64 from = std::max<qint64>(0, m_moment - span);
            m_log.walk(from, m_moment - 1,
                       [&](QByteArrayView, const LogLine &line, qint64 ms, const ReplayState &) {
                           if (line.type == LogLine::Type::Frame && ms < m_moment)
                               to = ms;
                           return true;
                       });
            if (from == 0)
                break;
        }
    }
    if (to)
        seek(*to);
}

void ReplayMode::close()
{
    if (!m_active)
        return;
    m_bar->setPlaying(false);
    m_active = false;
    if (m_session->parameters()->store()->isReplay())
        m_session->parameters()->store()->closeReplay();
    m_views->stop();
    if (m_strip)
        m_strip->endReplay();
    m_banner->hide();
    m_bar->hide();
    m_close->setEnabled(false);
    m_log = ReplayLog(m_session->map());
    m_unpacked.reset();
    const QString name = m_name;
    m_name.clear();
    m_stateText.clear();
    m_devices.clear();
    Q_EMIT activeChanged(false);
    Q_EMIT finished(true, tr("Replay of %1 closed.").arg(name));
}

} // namespace stepcom
