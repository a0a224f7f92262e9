#pragma once

#include "commissioning/checklist.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>
#include <optional>

class QAction;
class QMenu;
class QMessageBox;
class QWidget;

namespace stepcom {

class DeviceSession;
class BackupsDialog;
class ProfileCompareDialog;
struct Profile;
class ProfileSaveDialog;

// The File menu's profile and report actions: open a profile (compare, never write by itself),
// save one from the device or from the edited values, recent profiles, the commissioning
// report. File choosers and messages are non-modal; the *File() methods do the work and are
// what tests call.
class ProfileActions : public QObject
{
    Q_OBJECT
public:
    ProfileActions(DeviceSession *session, QWidget *window);

    QAction *openAction() const { return m_open; }
    QAction *saveFromDeviceAction() const { return m_saveFromDevice; }
    QAction *saveFromEditedAction() const { return m_saveFromEdited; }
    QAction *reportAction() const { return m_report; }
    QAction *backupsAction() const { return m_backups; }
    BackupsDialog *backupsDialog() const;
    // The checklist run in the window and its file, for the report (none: no checklist).
    using ChecklistSource = std::function<std::optional<std::pair<Checklist, QString>>()>;
    void setChecklistSource(ChecklistSource source) { m_checklist = std::move(source); }
    // Where File → Backups looks (the backup guard's folder).
    void setBackupDirectory(const QString &directory) { m_backupDir = directory; }
    QMenu *recentMenu() const { return m_recent; }
    ProfileCompareDialog *compareDialog() const;
    // Asks for the profile's name and notes before the file chooser (open while it asks).
    ProfileSaveDialog *saveDialog() const;
    // What a new profile is called at first: the machine (the last profile opened or saved)
    // or the controller's id, and today's date.
    QString suggestedName() const;
    QMessageBox *errorBox() const;

    static QStringList recentFiles();
    void retranslate();

    // Parse, then show the comparison; a bad file shows every problem and writes nothing.
    // Without a controller the file goes to `opener` (editing it offline) when one is set.
    bool openFile(const QString &path);
    void setOfflineOpener(std::function<bool(const QString &)> opener);
    // A backup, through the same compare and apply (not added to the recent profiles).
    bool openBackupFile(const QString &path);
    void showBackups();
    // Read everything from the controller, then save (done reports the outcome).
    // An empty name names the profile after the file.
    void saveFromDeviceFile(const QString &path, const QString &name = QString(),
                            const QString &notes = QString());
    // Save what the window shows: the edits where there are any, else the controller's values.
    bool saveFromEditedFile(const QString &path, const QString &name = QString(),
                            const QString &notes = QString());
    // Read everything, then write the report as PDF or HTML by the file's suffix.
    void reportFile(const QString &path, const QString &notes);

Q_SIGNALS:
    // Every outcome, for the message dock; ok = false for errors.
    void finished(bool ok, const QString &message);

private:
    void chooseOpen();
    void showCompare(const Profile &profile, const QString &title);
    void chooseSave(bool fromDevice);
    void chooseReport();
    void addRecent(const QString &path);
    void rebuildRecent();
    void showErrors(const QString &title, const QStringList &errors);
    void updateActions();
    QString lastDirectory() const;

    DeviceSession *m_session;
    QWidget *m_window;
    QAction *m_open;
    QAction *m_saveFromDevice;
    QAction *m_saveFromEdited;
    QAction *m_report;
    QAction *m_backups;
    QPointer<BackupsDialog> m_backupsDialog;
    ChecklistSource m_checklist;
    QString m_backupDir;
    QMenu *m_recent;
    QPointer<ProfileCompareDialog> m_compare;
    QPointer<ProfileSaveDialog> m_saveDialog;
    QString m_machine; // the name of the last profile opened or saved
    QPointer<QMessageBox> m_errorBox;
    std::function<bool(const QString &)> m_offlineOpener;
};

} // namespace stepcom
