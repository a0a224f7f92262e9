#include "window/mainwindow.h"

#include "base/backupguard.h"
#include "base/emergencystop.h"
#include "base/language.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "dialogs/supportbundledialog.h"
#include "help/guidewindow.h"
#include "help/userguide.h"
#include "pages/checklistpage.h"
#include "pages/connectionpage.h"
#include "pages/devicepage.h"
#include "pages/inputspage.h"
#include "pages/interpolationpage.h" // interpolation
#include "pages/modespage.h"         // special modes
#include "pages/motionpage.h"        // jogging
#include "pages/motorpage.h"
#include "pages/plotpage.h" // monitoring
#include "pages/sequencepage.h"
#include "pendant/pendantserver.h"
#include "replay/replaybar.h"
#include "replay/replaymode.h" // replaying a session log
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/linkhealth.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/reconnector.h"
#include "session/sessionlog.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/docks/linkstatus.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/messageview.h"
#include "widgets/docks/offlinebanner.h"
#include "widgets/docks/pagesidebar.h"
#include "widgets/docks/statusdock.h" // monitoring
#include "widgets/docks/statusmessage.h"
#include "widgets/docks/trafficview.h"
#include "widgets/fields/verticalscrollarea.h"
#include "widgets/motion/travellimitseditor.h"
#include "window/busactions.h"
#include "window/listenmode.h"
#include "window/machineactions.h"
#include "window/offlineactions.h"
#include "window/pendantactions.h" // working without the machine
#include "window/profileactions.h" // profiles

#include "profile/profiledocument.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWhatsThis>

namespace stepcom {

MainWindow::MainWindow(DeviceSession *session, QWidget *parent)
    : QMainWindow(parent)
    , m_session(session)
    , m_estop(new EmergencyStop(session, this))
    , m_sidebar(new PageSidebar(session, this))
    , m_stack(new QStackedWidget(this))
{
    setObjectName(QStringLiteral("mainWindow"));
    m_writeFlow = new WriteFlow(session, this);
    // --- commissioning: backups before risky operations, saved travel limits ---
    m_backups = new BackupGuard(session, this);
    TravelLimitsEditor::restoreSaved(session);
    auto *splitter = new QSplitter(this);
    splitter->addWidget(m_sidebar);
    splitter->addWidget(m_stack);
    splitter->setStretchFactor(1, 1);
    // Working without the machine: the banner above the pages while a file is edited.
    m_offline = new OfflineActions(session, this);
    m_offlineBanner = new OfflineBanner(m_offline->document(), this);
    auto *central = new QWidget(this);
    auto *centralLayout = new QVBoxLayout(central);
    centralLayout->setContentsMargins(0, 0, 0, 0);
    centralLayout->addWidget(m_offlineBanner);
    m_replay = new ReplayMode(session, this); // Its banner there too, its bar below
    centralLayout->addWidget(m_replay->banner());
    centralLayout->addWidget(splitter, 1);
    setCentralWidget(central);
    connect(m_sidebar, &PageSidebar::pageChosen, m_stack, &QStackedWidget::setCurrentIndex);
    connect(m_stack, &QStackedWidget::currentChanged, this, &MainWindow::updateTitle);

    auto *connectionPage = new ConnectionPage(session, this);
    addPage(connectionPage);
    for (int n = 1; n <= session->map().blockCount(QStringLiteral("motor")); ++n)
        addPage(new MotorPage(session, n, this));
    // In commissioning order: the sidebar groups them by Page::stage().
    addPage(new InputsPage(session, this));
    addPage(m_motion = new MotionPage(session, m_writeFlow, this)); // jogging and homing
    addPage(new ModesPage(session, m_writeFlow, this));             // special modes
    addPage(new InterpolationPage(session, this));                  // interpolation
    addPage(m_plots = new PlotPage(session, this));                 // monitoring
    addPage(m_sequence = new SequencePage(session, this));          // the machine's cycle
    addPage(m_checklist = new ChecklistPage(session, m_writeFlow, this));
    addPage(new DevicePage(session, this)); // its id and baud, save to flash, factory reset
    m_sidebar->setCurrentPage(0);

    createActions();
    m_listen = new ListenMode(session, m_estop, this);
    m_listen->setSettingsSource([connectionPage] { return connectionPage->currentSettings(); });
    connectionPage->addLineAction(m_listen->startAction());
    centralLayout->insertWidget(2, m_listen->banner());
    createMenus();
    createDocks();
    // Under the pages, on every page: positions, states and the E-STOP.
    m_strip = new MachineStrip(session, m_estop, central);
    m_strip->setDeviceNamer([this](int id) { return m_deviceDock->nameOf(id); });
    m_pendant = new PendantActions(m_session, m_strip, m_sessionLog, m_replay, m_offline, this);
    m_pendant->server()->setDeviceNamer([this](int id) { return m_deviceDock->nameOf(id); });
    m_deviceMenu->addAction(m_pendant->pendantAction());
    centralLayout->addWidget(m_replay->bar());
    centralLayout->addWidget(m_strip);
    m_estopButton = m_strip->emergencyStopButton();
    watchProofs();
    watchSequence();
    m_estopAction->setEnabled(m_estop->isAvailable());
    connect(m_estop, &EmergencyStop::availabilityChanged, this, [this](bool available) {
        m_estopAction->setEnabled(available);
        retranslateEmergencyStop();
    });
    m_linkStatus = new LinkStatus(session, this);
    // A cable pulled and plugged back, an adapter that came back: the window tries again.
    session->connection()->reconnector()->setEnabled(true);
    // A page change stops every jog (the session's rule); jog messages go to the dock.
    connect(m_sidebar, &PageSidebar::pageChosen, session,
            [session] { session->stopJogging(DeviceSession::JogStop::PageLeft); });
    connect(session->jog(), &JogController::message, m_messages, &MessageView::add);
    connect(m_sessionLog, &SessionLog::failed, this, [this](const QString &reason) {
        m_messages->add(DeviceSession::Severity::Warning, reason);
    });
    connect(m_profiles, &ProfileActions::finished, this, // profiles
            [this](bool ok, const QString &text) {
                m_status->post(ok ? DeviceSession::Severity::Info : DeviceSession::Severity::Error,
                               text);
            });
    // Passing messages left of the link status, cut short before they reach it.
    m_status = new StatusMessage(m_messages, this);
    statusBar()->addWidget(m_status, 1);
    statusBar()->addPermanentWidget(m_linkStatus);
    // --- working without the machine ---
    m_profiles->setOfflineOpener([this](const QString &path) { return m_offline->openFile(path); });
    connect(m_offline, &OfflineActions::finished, this, [this](bool ok, const QString &text) {
        m_status->post(ok ? DeviceSession::Severity::Info : DeviceSession::Severity::Warning, text);
    });
    connect(m_offline->document(), &ProfileDocument::changed, this, &MainWindow::showOrigin);
    // --- end working without the machine ---
    m_replay->setViews({m_traffic, m_deviceDock, m_plots, m_strip});
    m_listen->setStrip(m_strip);
    // Pages chosen, changes written, checklist results and device names go into the log.
    ReplayMode::recordActions(m_sessionLog, m_sidebar, m_pages, m_writeFlow, m_checklist,
                              m_deviceDock);
    connect(m_replay, &ReplayMode::activeChanged, this, &MainWindow::showOrigin);
    connect(m_replay, &ReplayMode::finished, this, [this](bool ok, const QString &text) {
        m_status->post(ok ? DeviceSession::Severity::Info : DeviceSession::Severity::Warning, text);
    });
    connect(m_listen, &ListenMode::finished, this, [this](bool ok, const QString &text) {
        m_messages->add(ok ? DeviceSession::Severity::Info : DeviceSession::Severity::Warning,
                        text);
    });

    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &MainWindow::updateActions);
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this,
            &MainWindow::updateActions);
    connect(session, &DeviceSession::message, m_status, &StatusMessage::post);
    // On to the first motor once the controller answered, not when the port opened: a port
    // with nobody behind it keeps the Connection page and its "not answering" hints in view.
    connect(session->connection()->health(), &LinkHealth::stateChanged, this,
            [this](LinkHealth::State s) {
                if (s == LinkHealth::State::Answering && !m_answeredOnce && currentPage() &&
                    qobject_cast<ConnectionPage *>(currentPage()))
                    showPage(1);
                m_answeredOnce = m_answeredOnce || s == LinkHealth::State::Answering;
                if (s == LinkHealth::State::Closed)
                    m_answeredOnce = false;
            });
    retranslate();
    // The sidebar as wide as its titles, not as wide as a list's default size hint (256 px):
    // that left a strip of nothing between the sidebar and the page. The page takes the rest.
    splitter->setSizes({m_sidebar->minimumWidth(), width()});
    updateActions();
    restoreLayout();
}

MainWindow::~MainWindow() = default;

void MainWindow::addPage(Page *page)
{
    m_pages << page;
    // Every page scrolls up and down when the screen is low (1024×600), never sideways: the
    // scroll area is at least as wide as the page needs (kept so in eventFilter()).
    auto *scroll = new QScrollArea(m_stack);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(page);
    scroll->setMinimumWidth(page->minimumSizeHint().width() +
                            scroll->verticalScrollBar()->sizeHint().width());
    page->installEventFilter(this);
    m_stack->addWidget(scroll);
    m_sidebar->addPage(page);
}

Page *MainWindow::currentPage() const
{
    const int index = m_stack->currentIndex();
    return index >= 0 && index < m_pages.size() ? m_pages.at(index) : nullptr;
}

void MainWindow::showPage(int index)
{
    m_sidebar->setCurrentPage(index);
}

void MainWindow::createActions()
{
    auto make = [this](const char *name, const QKeySequence &key, auto slot) {
        auto *a = new QAction(this);
        a->setObjectName(QLatin1String(name));
        if (!key.isEmpty())
            a->setShortcut(key);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    m_readAll =
        make("readAll", QKeySequence::Refresh, [this] { m_session->parameters()->readAll(); });
    m_write =
        make("writeChanges", QKeySequence(Qt::CTRL | Qt::Key_Return), [this] { writeChanges(); });
    m_revert = make("revert", QKeySequence(Qt::CTRL | Qt::Key_R),
                    [this] { m_session->parameters()->store()->revertAll(); });
    m_save = make("saveToFlash", QKeySequence::Save, [this] { m_session->saveToFlash(); });
    m_disconnect =
        make("disconnect", QKeySequence(), [this] { m_session->connection()->disconnectFrom(); });
    m_estopAction = make("emergencyStop", QKeySequence(), [this] { m_estop->trigger(); });
    m_quit = make("quit", QKeySequence::Quit, [this] { close(); });
    m_about = make("about", QKeySequence(), [this] {
        auto *box = new QMessageBox(QMessageBox::Information, tr("About StepCom"),
                                    tr("<b>StepCom %1</b><br>Commissioning tool for 2-axis stepper "
                                       "controllers over Modbus RTU/TCP.<br>GPL-3.0-or-later.")
                                        .arg(QStringLiteral(STEPCOM_VERSION)),
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    m_guideAction = make("userGuide", QKeySequence::HelpContents, [this] {
        // F1 in an open dialog explains the dialog; otherwise the page in view.
        const QWidget *active = QApplication::activeWindow();
        const QString topic = active && active != this
                                  ? QString::fromLatin1(active->metaObject()->className())
                                  : QString();
        openGuide(UserGuide::topics().contains(topic) ? topic : QString());
    });
    m_guideAction->setShortcutContext(Qt::ApplicationShortcut);
    // Help from afar: the dialog does the work, with the profile in use.
    m_bundle = make("createSupportBundle", QKeySequence(), [this] {
        const ProfileDocument *file = m_offline->document();
        QString profile = file->isOpen() ? file->path() : m_checklist->profilePath();
        if (profile.isEmpty())
            profile = ProfileActions::recentFiles().value(0);
        auto *dialog = new SupportBundleDialog(profile, m_machine->reportSheets(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(dialog, &SupportBundleDialog::written, this, [this](bool ok, const QString &text) {
            m_status->post(ok ? DeviceSession::Severity::Info : DeviceSession::Severity::Error,
                           text.section(QLatin1Char('\n'), 0, 0));
        });
        dialog->open();
    });
    m_whatsThis = QWhatsThis::createAction(this);
    m_whatsThis->setObjectName(QStringLiteral("whatsThis"));
    m_languages = new QActionGroup(this);
    for (const QString &lang : Language::available()) {
        auto *a = new QAction(Language::nativeName(lang), m_languages);
        a->setObjectName(QStringLiteral("language_") + lang);
        a->setCheckable(true);
        a->setChecked(Language::instance().current() == lang);
        connect(a, &QAction::triggered, this, [lang] { Language::instance().setLanguage(lang); });
    }
    m_toolbar = addToolBar(QString());
    m_toolbar->setObjectName(QStringLiteral("mainToolbar"));
    m_toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_toolbar->setMovable(false);
    m_toolbar->addAction(m_readAll);
    m_toolbar->addAction(m_write);
    m_toolbar->addAction(m_revert);
    m_toolbar->addAction(m_save);
    m_toolbar->addSeparator();
    m_toolbar->addAction(m_disconnect);
    // The E-STOP is the machine strip's, on every page: one button, one place to reach for.
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    // --- profiles: open/compare/apply, save, recent, the commissioning report ---
    m_profiles = new ProfileActions(m_session, this);
    m_fileMenu->addAction(m_offline->newAction());
    m_fileMenu->addAction(m_profiles->openAction());
    m_fileMenu->addMenu(m_profiles->recentMenu());
    m_fileMenu->addAction(m_offline->saveAction());
    m_fileMenu->addAction(m_offline->saveAsAction());
    m_fileMenu->addAction(m_offline->closeAction());
    m_fileMenu->addAction(m_offline->compareAction());
    m_fileMenu->addAction(m_replay->openAction());
    m_fileMenu->addAction(m_replay->closeAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_profiles->saveFromDeviceAction());
    m_fileMenu->addAction(m_profiles->saveFromEditedAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_profiles->reportAction());
    m_fileMenu->addAction(m_offline->reportAction());
    m_fileMenu->addAction(m_profiles->backupsAction());
    m_profiles->setBackupDirectory(m_backups->directory());
    m_profiles->setChecklistSource([this] { return m_checklist->reportChecklist(); });
    m_machine = new MachineActions(m_session, this); // every device of the line
    m_machine->addTo(m_fileMenu, [this] { return m_deviceDock; });
    connect(m_machine, &MachineActions::finished, m_profiles, &ProfileActions::finished);
    m_fileMenu->addSeparator();
    // --- end profiles ---
    m_fileMenu->addAction(m_quit);
    m_deviceMenu = menuBar()->addMenu(QString());
    m_deviceMenu->addActions({m_readAll, m_write, m_revert, m_save});
    m_deviceMenu->addSeparator();
    m_deviceMenu->addAction(m_disconnect);
    m_deviceMenu->addAction(m_listen->startAction());
    m_deviceMenu->addSeparator();
    m_deviceMenu->addAction(m_estopAction);
    m_viewMenu = menuBar()->addMenu(QString());
    m_languageMenu = menuBar()->addMenu(QString());
    m_languageMenu->addActions(m_languages->actions());
    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_guideAction);
    m_helpMenu->addAction(m_whatsThis);
    m_helpMenu->addAction(m_bundle);
    m_helpMenu->addSeparator();
    m_helpMenu->addAction(m_about);
}

void MainWindow::createDocks()
{
    m_traffic = new TrafficView(this);
    m_traffic->setLog(m_session->connection()->traffic());
    m_sessionLog = m_session->log();
    m_traffic->setLogFolder(m_sessionLog->directory());
    m_trafficDock = new QDockWidget(this);
    m_trafficDock->setObjectName(QStringLiteral("trafficDock"));
    m_trafficDock->setWidget(m_traffic);
    m_messages = new MessageView(this);
    m_messageDock = new QDockWidget(this);
    m_messageDock->setObjectName(QStringLiteral("messageDock"));
    m_messageDock->setWidget(m_messages);
    m_viewMenu->addAction(m_trafficDock->toggleViewAction());
    m_viewMenu->addAction(m_messageDock->toggleViewAction());
    // --- monitoring: the live status beside every page ---
    m_statusDock = new StatusDock(m_session, this);
    // Its content scrolls up and down, so the dock fits a low screen beside or below the page;
    // it asks for the width its content needs now (texts change with the state and the
    // language: a width taken once cut "18.17 mm" and "IN4" off in Chinese).
    if (QWidget *content = m_statusDock->widget()) {
        auto *scroll = new VerticalScrollArea(content, m_statusDock);
        scroll->setFrameShape(QFrame::NoFrame);
        m_statusDock->setWidget(scroll);
    }
    m_viewMenu->addAction(m_statusDock->toggleViewAction());
    // --- end monitoring ---
    // Several controllers on one line: opened from the View menu.
    m_deviceDock = new DeviceListDock(m_session, this);
    placeDocks();
    connect(m_deviceDock->toggleViewAction(), &QAction::triggered, m_deviceDock, [this](bool on) {
        if (!on)
            return;
        m_deviceDock->raise();
        // Room for a few devices, not only the two rows a messages-high tab leaves.
        resizeDocks({m_deviceDock}, {fontMetrics().height() * 15}, Qt::Vertical);
    });
    m_viewMenu->addAction(m_deviceDock->toggleViewAction());
    m_deviceMenu->addSeparator();
    auto *bus = new BusActions(m_session, m_deviceDock, this);
    m_deviceMenu->addAction(bus->assignIdsAction());
    m_deviceMenu->addAction(bus->resetSimulatorAction());
    connect(bus, &BusActions::message, this,
            [this](const QString &text) { m_messages->add(DeviceSession::Severity::Info, text); });
}

void MainWindow::showOrigin()
{
    updateTitle();
    const ProfileDocument *file = m_offline->document();
    if (m_replay->isActive()) { // A recording, in its banner's colour
        statusBar()->setStyleSheet(QStringLiteral(
            "QStatusBar { background: #fff0c8; } QStatusBar QLabel { color: black; }"));
        return;
    }
    if (!file->isOpen()) {
        statusBar()->setStyleSheet(QString());
        return;
    }
    // The status area in the banner's colour: a file, not a machine.
    statusBar()->setStyleSheet(
        QStringLiteral("QStatusBar { background: #d6e6ff; } QStatusBar QLabel { color: black; }"));
}

void MainWindow::retranslate()
{
    showOrigin();
    m_guideAction->setText(tr("&User guide"));
    m_guideAction->setToolTip(
        tr("The user guide at the section about this page (%1)")
            .arg(m_guideAction->shortcut().toString(QKeySequence::NativeText)));
    m_whatsThis->setText(tr("What's &this?"));
    m_bundle->setText(tr("Create &support bundle…"));
    m_bundle->setToolTip(tr("One .zip file with the session logs, the profile and the settings, "
                            "to send to support"));
    m_readAll->setText(tr("&Read all"));
    m_readAll->setToolTip(tr("Read every parameter from the controller (%1)")
                              .arg(m_readAll->shortcut().toString(QKeySequence::NativeText)));
    m_write->setText(tr("&Write changes…"));
    m_write->setToolTip(tr("Show the edited values, then write them and verify (%1)")
                            .arg(m_write->shortcut().toString(QKeySequence::NativeText)));
    m_revert->setText(tr("Re&vert"));
    m_revert->setToolTip(tr("Drop every edit and show what the controller holds"));
    m_save->setText(tr("&Save to flash"));
    m_save->setToolTip(
        tr("Save the controller's parameters to its non-volatile memory (coil 00096)"));
    m_disconnect->setText(tr("&Disconnect"));
    retranslateEmergencyStop();
    m_quit->setText(tr("&Quit"));
    m_about->setText(tr("&About StepCom"));
    m_fileMenu->setTitle(tr("&File"));
    m_profiles->retranslate(); // profiles
    m_offline->retranslate();
    m_replay->retranslate();
    m_listen->retranslate();
    m_deviceMenu->setTitle(tr("&Device"));
    m_viewMenu->setTitle(tr("&View"));
    m_languageMenu->setTitle(tr("&Language"));
    m_helpMenu->setTitle(tr("&Help"));
    m_toolbar->setWindowTitle(tr("Main toolbar"));
    m_trafficDock->setWindowTitle(tr("Traffic"));
    m_messageDock->setWindowTitle(tr("Messages"));
    for (QAction *a : m_languages->actions())
        a->setChecked(a->objectName() ==
                      QStringLiteral("language_") + Language::instance().current());
}

void MainWindow::retranslateEmergencyStop()
{
    m_estopAction->setText(tr("&Emergency stop"));
    m_estopAction->setToolTip(
        m_estop->isAvailable()
            ? tr("All motors and outputs off, at once (key: %1)")
                  .arg(EmergencyStop::shortcut().toString(QKeySequence::NativeText))
            : m_estop->toolTip());
}

bool MainWindow::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::LayoutRequest || event->type() == QEvent::LanguageChange) {
        if (auto *page = qobject_cast<Page *>(watched)) {
            if (auto *scroll = qobject_cast<QScrollArea *>(
                    page->parentWidget() ? page->parentWidget()->parentWidget() : nullptr))
                scroll->setMinimumWidth(page->minimumSizeHint().width() +
                                        scroll->verticalScrollBar()->sizeHint().width());
        }
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    arrangeDocks();
}

void MainWindow::updateTitle()
{
    // One title: the platform adds the program's name ("Motor 1 — StepCom"), so the page, or
    // the profile file being edited without a controller, is all we add.
    if (m_replay && m_replay->isActive()) {
        setWindowTitle(tr("%1 — replay, no controller").arg(m_replay->displayName()));
        return;
    }
    const ProfileDocument *file = m_offline ? m_offline->document() : nullptr;
    if (file && file->isOpen()) {
        setWindowTitle(
            tr("%1%2 — profile file, no controller")
                .arg(file->displayName(), file->isModified() ? QStringLiteral("*") : QString()));
        return;
    }
    const Page *page = currentPage();
    setWindowTitle(page ? page->title() : QString());
}

GuideWindow *MainWindow::openGuide(const QString &topic)
{
    if (!m_guide)
        m_guide = new GuideWindow(this);
    const QString what = !topic.isEmpty() ? topic
                         : currentPage()
                             ? QString::fromLatin1(currentPage()->metaObject()->className())
                             : QString();
    QString error;
    if (!m_guide->showTopic(what, Language::instance().current(), &error))
        m_messages->add(DeviceSession::Severity::Warning, error);
    m_guide->show();
    m_guide->raise();
    m_guide->activateWindow();
    return m_guide;
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        // A passing message was made in the old language; the messages dock keeps it.
        m_status->clearText();
    }
    if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        m_session->stopJogging(DeviceSession::JogStop::FocusLost);
    QMainWindow::changeEvent(event);
}

void MainWindow::updateActions()
{
    const bool connected = m_session->connection()->isConnected();
    const bool edits = m_session->parameters()->store()->hasEdits();
    m_readAll->setEnabled(connected);
    m_write->setEnabled(connected && edits);
    m_revert->setEnabled(edits);
    m_save->setEnabled(connected);
    m_disconnect->setEnabled(connected);
}

void MainWindow::writeChanges()
{
    m_writeFlow->openAll();
}

} // namespace stepcom
