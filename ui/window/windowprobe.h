#pragma once

#include <QList>
#include <QString>

class QAction;
class QMessageBox;
class QToolButton;

namespace stepcom {

class ChecklistPage;
class DeviceListDock;
class EmergencyStop;
class GuideWindow;
class MachineStrip;
class MainWindow;
class MessageView;
class MotionPage;
class OfflineActions;
class OfflineBanner;
class Page;
class PageSidebar;
class PlotPage;
class ProfileActions;
class ReplayMode;
class SessionLog;
class StatusDock;
class TrafficView;
class WriteChangesDialog;

// The window's insides for those who drive it from outside the program -- the tests, stepcom-shots
// and the benchmark: its docks, pages, actions and open dialogs, and the steps a user takes
// through the sidebar and menus. MainWindow keeps public only what the program itself calls.
class WindowProbe
{
public:
    explicit WindowProbe(MainWindow &window)
        : m_window(window)
    {}

    const QList<Page *> &pages() const;
    Page *currentPage() const;
    void showPage(int index) const;
    EmergencyStop *emergencyStop() const;
    QToolButton *emergencyStopButton() const;
    MachineStrip *machineStrip() const;
    PageSidebar *sidebar() const;
    StatusDock *statusDock() const;
    DeviceListDock *deviceListDock() const;
    TrafficView *trafficView() const;
    SessionLog *sessionLog() const;
    MessageView *messageView() const;
    MotionPage *motionPage() const;
    ChecklistPage *checklistPage() const;
    PlotPage *plotPage() const;
    ProfileActions *profileActions() const;
    OfflineActions *offlineActions() const;
    OfflineBanner *offlineBanner() const;
    ReplayMode *replayMode() const;
    // A menu or toolbar action by its object name ("writeAll", "emergencyStop", ...).
    QAction *action(const QString &objectName) const;
    // The dialogs open at the moment, or null.
    WriteChangesDialog *writeDialog() const;
    QMessageBox *closeQuestion() const;
    QMessageBox *givenFileError() const;
    // Device → Write changes… and Help → User guide, as the menus do them.
    void writeChanges() const;
    GuideWindow *openGuide(const QString &topic = QString()) const;
    // A first start's layout on the window's screen (stepcom-shots' laptop scenes).
    void useDefaultLayout() const;

private:
    MainWindow &m_window;
};

} // namespace stepcom
