#include "window/windowprobe.h"

#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "window/mainwindow.h"

namespace stepcom {

const QList<Page *> &WindowProbe::pages() const
{
    return m_window.m_pages;
}

Page *WindowProbe::currentPage() const
{
    return m_window.currentPage();
}

void WindowProbe::showPage(int index) const
{
    m_window.showPage(index);
}

EmergencyStop *WindowProbe::emergencyStop() const
{
    return m_window.m_estop;
}

QToolButton *WindowProbe::emergencyStopButton() const
{
    return m_window.m_estopButton;
}

MachineStrip *WindowProbe::machineStrip() const
{
    return m_window.m_strip;
}

PageSidebar *WindowProbe::sidebar() const
{
    return m_window.m_sidebar;
}

StatusDock *WindowProbe::statusDock() const
{
    return m_window.m_statusDock;
}

DeviceListDock *WindowProbe::deviceListDock() const
{
    return m_window.m_deviceDock;
}

TrafficView *WindowProbe::trafficView() const
{
    return m_window.m_traffic;
}

SessionLog *WindowProbe::sessionLog() const
{
    return m_window.m_sessionLog;
}

MessageView *WindowProbe::messageView() const
{
    return m_window.m_messages;
}

MotionPage *WindowProbe::motionPage() const
{
    return m_window.m_motion;
}

ChecklistPage *WindowProbe::checklistPage() const
{
    return m_window.m_checklist;
}

PlotPage *WindowProbe::plotPage() const
{
    return m_window.m_plots;
}

ProfileActions *WindowProbe::profileActions() const
{
    return m_window.m_profiles;
}

OfflineActions *WindowProbe::offlineActions() const
{
    return m_window.m_offline;
}

OfflineBanner *WindowProbe::offlineBanner() const
{
    return m_window.m_offlineBanner;
}

ReplayMode *WindowProbe::replayMode() const
{
    return m_window.m_replay;
}

QAction *WindowProbe::action(const QString &objectName) const
{
    return m_window.findChild<QAction *>(objectName);
}

WriteChangesDialog *WindowProbe::writeDialog() const
{
    return m_window.m_writeFlow->dialog();
}

QMessageBox *WindowProbe::closeQuestion() const
{
    return m_window.m_closeQuestion;
}

QMessageBox *WindowProbe::givenFileError() const
{
    return m_window.m_givenFileError;
}

void WindowProbe::writeChanges() const
{
    m_window.writeChanges();
}

GuideWindow *WindowProbe::openGuide(const QString &topic) const
{
    return m_window.openGuide(topic);
}

void WindowProbe::useDefaultLayout() const
{
    m_window.useDefaultLayout();
}

} // namespace stepcom
