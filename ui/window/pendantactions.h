#pragma once

#include <QObject>
#include <QPointer>

class QAction;
class QWidget;

namespace stepcom {

class DeviceSession;
class MachineStrip;
class OfflineActions;
class PendantDialog;
class PendantServer;
class ReplayMode;
class SessionLog;

// The window's phone pendant (Device → Pendant…): owns the server (off at every start of
// StepCom), opens its dialog, notes what the phones do in the session log and says in the
// machine strip who watches or jogs. A replay or a profile file edited without a controller
// serves no pendant, nor does listening beside another master: it is stopped then and cannot
// be started.
class PendantActions : public QObject
{
    Q_OBJECT
public:
    PendantActions(DeviceSession *session, MachineStrip *strip, SessionLog *log, ReplayMode *replay,
                   OfflineActions *offline, QWidget *window);

    QAction *pendantAction() const { return m_action; }
    PendantServer *server() const { return m_server; }
    PendantDialog *openDialog();
    PendantDialog *dialog() const;
    // Why the pendant cannot run now (replay, offline file, listening), or empty.
    QString refusal() const;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void retranslate();
    void update();

    DeviceSession *m_session;
    PendantServer *m_server;
    QPointer<MachineStrip> m_strip; // gone before us when the window closes
    ReplayMode *m_replay;
    OfflineActions *m_offline;
    QWidget *m_window;
    QAction *m_action;
    QPointer<PendantDialog> m_dialog;
};

} // namespace stepcom
