#pragma once

#include "support/replaylog.h"

#include <QObject>
#include <QPointer>

#include <memory>

class QAction;
class QFrame;
class QInputDialog;
class QLabel;
class QMessageBox;
class QProgressDialog;
class QTemporaryDir;
class QWidget;

namespace stepcom {

class ChecklistPage;
class DeviceListDock;
class DeviceSession;
class MachineStrip;
class Page;
class PageSidebar;
class PlotPage;
class ReplayBar;
class ReplayViews;
class SessionLog;
class TrafficView;
class WriteFlow;

// The window's replay of a session log or a support bundle: File → Open session
// log… opens it (off the GUI thread, with progress and Cancel), then every page shows what the
// log says the controller held at the moment chosen on the bar: its values go into the
// session's store as a read would put them (ParameterStore::showReplay); the traffic view, the
// plots and the device list show it as the live window showed them then (ReplayViews). No
// link is opened, so nothing that writes or moves is enabled, as while a profile file is edited;
// connecting, opening a profile file or Close replay ends it. Choosers and messages are non-modal;
// openPath() and openBundleEntry() do the work and are what tests call.
class ReplayMode : public QObject
{
    Q_OBJECT
public:
    ReplayMode(DeviceSession *session, QWidget *window);
    ~ReplayMode() override;

    // What a replay of the window's session logs shows as the user's doing (the log's "user"
    // lines, markers in the timeline): the page chosen, the changes confirmed for writing, the
    // checklist's results; and the names of the devices, in the log's header.
    static void recordActions(SessionLog *log, PageSidebar *sidebar, const QList<Page *> &pages,
                              WriteFlow *writes, ChecklistPage *checklist, DeviceListDock *devices);

    QAction *openAction() const { return m_open; }
    QAction *closeAction() const { return m_close; }
    // For the window to place: the banner above the pages, the bar below them.
    QFrame *banner() const { return m_banner; }
    ReplayBar *bar() const { return m_bar; }
    // What shows the log beside the pages while it runs (the session's again after): the
    // traffic dock, the device list and the plots (ReplayViews), and the strip, the link as the
    // log has it at the moment.
    struct Views
    {
        TrafficView *traffic = nullptr;
        DeviceListDock *devices = nullptr;
        PlotPage *plots = nullptr;
        MachineStrip *strip = nullptr;
    };
    void setViews(const Views &views);
    ReplayViews *views() const { return m_views; }

    bool isActive() const { return m_active; }
    bool isOpening() const { return m_opening != nullptr; }
    const ReplayLog &log() const { return m_log; }
    // "session.log" (or "bundle.zip: logs/session.log").
    QString displayName() const { return m_name; }
    QString bannerText() const;
    // What the link and the device in view were doing at the moment, in words.
    QString momentStateText() const { return m_stateText; }
    qint64 moment() const { return m_moment; }
    int device() const { return m_device; }
    QList<int> devices() const { return m_devices; }
    QMessageBox *errorBox() const;
    QProgressDialog *progress() const;
    QInputDialog *entryChooser() const;
    void retranslate();

    // Opens a session log, or a support bundle (its only log; with several, asks which, the
    // newest first). False when it is refused at once (connected, a profile file open, a bundle
    // without logs); else the opening runs and `opened` or `failed` follows.
    bool openPath(const QString &path);
    bool openBundleEntry(const QString &zipPath, const QString &entry);
    // Shows the moment `ms` (clamped to the log) of the device in view.
    void seek(qint64 ms);
    void showDevice(int id);
    // To the next (+1) or previous (-1) frame of the log.
    void stepFrame(int direction);
    void close();

Q_SIGNALS:
    void activeChanged(bool active);
    void opened();
    // Opening failed or was cancelled: why, in words; the window is as it was.
    void failed(const QString &reason);
    void momentChanged(qint64 ms);
    // Every outcome, for the status bar; ok = false for errors.
    void finished(bool ok, const QString &message);

private:
    struct Opening;
    void choose();
    void chooseEntry(const QString &zipPath, const QStringList &logs);
    bool refused(QString *why) const;
    bool startOpening(const QString &path, const QString &name,
                      std::unique_ptr<QTemporaryDir> unpacked);
    void openingDone();
    void fail(const QString &reason);
    void showMoment();
    QString stateText(const ReplayState &state) const;

    DeviceSession *m_session;
    QWidget *m_window;
    QAction *m_open;
    QAction *m_close;
    QFrame *m_banner;
    QLabel *m_bannerText;
    QLabel *m_bannerState;
    ReplayBar *m_bar;
    ReplayViews *m_views;
    QPointer<MachineStrip> m_strip;
    ReplayLog m_log;
    std::unique_ptr<QTemporaryDir> m_unpacked; // a bundle's log, copied out for the seeks
    std::shared_ptr<Opening> m_opening;
    QString m_name;
    QString m_stateText;
    bool m_active = false;
    qint64 m_moment = 0;
    int m_device = 0;
    QList<int> m_devices;
    QPointer<QMessageBox> m_errorBox;
    QPointer<QProgressDialog> m_progress;
    QPointer<QInputDialog> m_chooser;
};

} // namespace stepcom
