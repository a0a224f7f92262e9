#pragma once

#include <QObject>
#include <QPointer>

class QAction;
class QWidget;

namespace stepcom {

class DeviceListDock;
class DeviceSession;
class IdAssistantDialog;

// The window's actions for a line of several controllers (Device menu): "Assign device ids…"
// opens the id assistant (non-modal); the controllers it names go on the device list, which
// is shown. Kept out of MainWindow, which only adds the action to its menu.
class BusActions : public QObject
{
    Q_OBJECT
public:
    BusActions(DeviceSession *session, DeviceListDock *dock, QWidget *window);

    QAction *assignIdsAction() const { return m_assignIds; }
    // "Reset the built-in simulator to factory": disconnects from it, forgets what it saved.
    QAction *resetSimulatorAction() const { return m_resetSim; }
    void resetSimulator();
    // Opens (or raises) the assistant.
    IdAssistantDialog *openAssistant();
    IdAssistantDialog *assistant() const;

Q_SIGNALS:
    // What happened, for the window's messages.
    void message(const QString &text);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void retranslate();

    DeviceSession *m_session;
    DeviceListDock *m_dock;
    QWidget *m_window;
    QAction *m_assignIds;
    QAction *m_resetSim;
    QPointer<IdAssistantDialog> m_assistant;
};

} // namespace stepcom
