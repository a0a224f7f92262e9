#pragma once

#include <QMainWindow>
#include <QPointer>

class QAction;
class QActionGroup;
class QDockWidget;
class QMessageBox;
class QStackedWidget;
class QToolButton;

namespace stepcom {

class BackupGuard;
class ChecklistPage;
class PlotPage;
class SequencePage;
class DeviceSession;
class EmergencyStop;
class GuideWindow;
class LinkStatus;
class MachineStrip;
class MessageView;
class StatusMessage;
class MotionPage;     // jogging
class OfflineActions; // working without the machine
class OfflineBanner;
class Page;
class PendantActions;
class PageSidebar;
class MachineActions;
class ProfileActions; // profiles
class ReplayMode;     // replaying a session log
class ListenMode;
class DeviceListDock; // several controllers on one line
class SessionLog;
class StatusDock; // monitoring
class TrafficView;
class WriteChangesDialog;
class WriteFlow;

// Composes the pages, docks, toolbar and menus around one DeviceSession. It does no page's
// work: pages are views of the session's store; actions call the session.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(DeviceSession *session, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Shows the window as the user left it; the first time, maximized on a small screen (below
    // 1440×900) and on a larger one sized to most of it, in its middle.
    void showOnScreen();
    PendantActions *pendantActions() const { return m_pendant; } // a phone as the pendant
    ListenMode *listenMode() const { return m_listen; }

    // A file handed to the window (`stepcom FILE`, "Open with StepCom"): a profile is edited
    // without a controller, a session log or a support bundle replayed; anything else is
    // refused with a message naming the file. False when refused at once.
    bool openGivenFile(const QString &path);

protected:
    void closeEvent(QCloseEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    // Tests, stepcom-shots and the benchmark reach the docks, pages and dialogs through it.
    friend class WindowProbe;

    Page *currentPage() const;
    void showPage(int index);
    // The layout of a first start on the window's screen, as if nothing had been saved: the
    // docks where they start, the bottom ones as high as that screen allows, arranged for its
    // width; showOnScreen() then shows it as a first start does. stepcom-shots' laptop scenes
    // take their pictures this way (the real program's path, not an imitation).
    void useDefaultLayout();
    // Ask before writing: opens the write dialog (non-modal to the event loop).
    void writeChanges();
    // Help → User guide (F1): the guide in the window's language at the section of `topic`
    // (a page's or dialog's class name; the current page when empty).
    GuideWindow *openGuide(const QString &topic = QString());
    void createActions();
    void createMenus();
    void createDocks();
    void addPage(Page *page);
    // A proof of an axis that lost steps at the motor's own settings: a warning in the strip,
    // its recommended speed (or the way to find one) one click away (mainwindowlayout.cpp).
    void watchProofs();
    // The Sequence page's run: the strip's line, the run-in to the checklist; the game pad's
    // E-STOP.
    void watchSequence();
    void retranslate();
    void retranslateEmergencyStop();
    void updateActions();
    void updateTitle();
    // Narrow window: the status dock joins the bottom tabs, so the page keeps its width; wide
    // again: back beside the page.
    void arrangeDocks();
    // Inside the available screen, however large the saved or default size.
    void fitIntoScreen();
    // Title and status bar say whether a file or a controller is being edited.
    void showOrigin();
    void restoreLayout();
    // Where the docks start: traffic and messages in tabs below (the messages in front), the
    // status beside the page, the device list a hidden tab beside the messages.
    void placeDocks();
    // A first start's size and docks' heights for the screen, the docks arranged for it.
    void firstStartLayout();
    // The bottom docks' first height: up to 9 lines, less on a low screen (a sixth of it),
    // where the page needs the room (1024×600).
    void resizeBottomDocks();
    void saveLayout();

    DeviceSession *m_session;
    EmergencyStop *m_estop;
    QToolButton *m_estopButton = nullptr;
    PageSidebar *m_sidebar; // the pages in commissioning order, with their states
    QStackedWidget *m_stack;
    QList<Page *> m_pages;
    TrafficView *m_traffic = nullptr;
    SessionLog *m_sessionLog = nullptr;
    MessageView *m_messages = nullptr;
    QDockWidget *m_trafficDock = nullptr;
    QDockWidget *m_messageDock = nullptr;
    StatusDock *m_statusDock = nullptr;     // monitoring
    DeviceListDock *m_deviceDock = nullptr; // several controllers on one line
    LinkStatus *m_linkStatus = nullptr;
    MachineStrip *m_strip = nullptr; // Positions, state and E-STOP on every page
    StatusMessage *m_status = nullptr;
    MotionPage *m_motion = nullptr;       // jogging
    ProfileActions *m_profiles = nullptr; // profiles
    MachineActions *m_machine = nullptr;  // every device of the line
    OfflineActions *m_offline = nullptr;
    OfflineBanner *m_offlineBanner = nullptr;
    ReplayMode *m_replay = nullptr;
    PendantActions *m_pendant = nullptr;
    ListenMode *m_listen = nullptr; // beside another master: heard, never driven
    bool m_jogStopAwaited = false;  // jogging: close waited for the stops once
    WriteFlow *m_writeFlow = nullptr;
    ChecklistPage *m_checklist = nullptr;
    PlotPage *m_plots = nullptr;
    SequencePage *m_sequence = nullptr;
    BackupGuard *m_backups = nullptr;
    QPointer<QMessageBox> m_closeQuestion;
    QPointer<QMessageBox> m_givenFileError;
    bool m_closeConfirmed = false;
    bool m_statusDockMoved = false; // arrangeDocks() put it into the bottom tabs
    bool m_firstStart = false;      // no geometry saved: showOnScreen() chooses one
    bool m_answeredOnce = false;    // this connection's controller answered (the page jumped)

    QAction *m_readAll = nullptr;
    QAction *m_write = nullptr;
    QAction *m_revert = nullptr;
    QAction *m_save = nullptr;
    QAction *m_disconnect = nullptr;
    QAction *m_estopAction = nullptr;
    QAction *m_quit = nullptr;
    QAction *m_about = nullptr;
    QAction *m_guideAction = nullptr;
    QAction *m_whatsThis = nullptr;
    QAction *m_bundle = nullptr; // Help → Create support bundle…
    GuideWindow *m_guide = nullptr;
    QActionGroup *m_languages = nullptr;
    QMenu *m_fileMenu = nullptr;
    QMenu *m_deviceMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QToolBar *m_toolbar = nullptr;
};

} // namespace stepcom
