#pragma once

#include "dialogs/reportsheets.h"

#include <QHash>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

class QAction;
class QMenu;
class QWidget;

namespace stepcom {

class ApplyToDevicesDialog;
class BusSweep;
class DeviceListDock;
class DeviceSession;
struct Parameter;
struct ReportInput;

// The File menu's actions for every device of the line (enabled with several devices on the
// list): apply one profile to several of them, save each one as a profile into a folder, and
// the commissioning report of the whole machine. File choosers are non-modal; the *File()
// methods do the work and are what tests call.
class MachineActions : public QObject
{
    Q_OBJECT
public:
    MachineActions(DeviceSession *session, QWidget *window);

    // Adds the actions to `menu`; `list` gives the window's device list (null before it is
    // made): what it calls each id. Backups before writing: the session's risk guard.
    void addTo(QMenu *menu, std::function<DeviceListDock *()> list = {});
    QAction *applyAction() const { return m_apply; }
    QAction *dumpAction() const { return m_dump; }
    QAction *reportAction() const { return m_report; }
    ApplyToDevicesDialog *applyDialog() const;
    bool isBusy() const;

    // Opens the apply dialog for this profile file; false (and why) for a file that cannot be
    // used.
    bool applyProfileFile(const QString &path);
    // Reads every device of the list, then saves each into `folder`.
    void dumpIntoFolder(const QString &folder);
    // Reads every device of the list, then writes one report of them all (.pdf or .html).
    void reportFile(const QString &path, const QString &title, const QString &notes);
    // The machine's sheets as the window knows them now, nothing read for them: each device of
    // the line whose settings were read (as last read), for a support bundle's report.
    QList<ReportInput> knownSheets() const;
    // The sheet of a profile file (and its checklist); nullopt and why not.
    std::optional<ReportInput> profileSheet(const QString &path, QStringList *problems) const;
    // Both, for a support bundle's dialog; empty once this is gone.
    ReportSheets reportSheets();

Q_SIGNALS:
    // Every outcome, for the message dock; ok = false for errors.
    void finished(bool ok, const QString &message);

private:
    void retranslate();
    void updateActions();
    void chooseApply();
    void chooseDump();
    void chooseReport();
    QHash<int, QString> names() const;
    // Device `id`'s sheet with these values, read at `read` (invalid: not just now).
    ReportInput sheet(int id, const QHash<QString, qint64> &values, const QString &name,
                      const QDateTime &read) const;
    // Reads every device of the list, then runs `done` (the sweep is deleted after it).
    void sweep(const QString &what, const QList<const Parameter *> &params,
               std::function<void(BusSweep *)> done);

    DeviceSession *m_session;
    QWidget *m_window;
    QAction *m_apply;
    QAction *m_dump;
    QAction *m_report;
    std::function<DeviceListDock *()> m_list;
    QPointer<ApplyToDevicesDialog> m_applyDialog;
    QPointer<BusSweep> m_sweep;
};

} // namespace stepcom
