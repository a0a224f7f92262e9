#include "window/profileactions.h"

#include "base/errorbox.h"
#include "base/language.h"
#include "dialogs/backupsdialog.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilesavedialog.h"
#include "profile/backupstore.h"
#include "profile/profilefile.h"
#include "report/commissioningreport.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QAction>
#include <QDate>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

namespace stepcom {

namespace {
const QString kGroup = QStringLiteral("profiles");
const QString kRecent = QStringLiteral("recent");
const QString kDirectory = QStringLiteral("lastDirectory");
constexpr int kMaxRecent = 8;
} // namespace

ProfileActions::ProfileActions(DeviceSession *session, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_window(window)
    , m_open(new QAction(this))
    , m_saveFromDevice(new QAction(this))
    , m_saveFromEdited(new QAction(this))
    , m_report(new QAction(this))
    , m_backups(new QAction(this))
    , m_recent(new QMenu(window))
{
    m_open->setObjectName(QStringLiteral("openProfile"));
    m_open->setShortcut(QKeySequence::Open);
    m_saveFromDevice->setObjectName(QStringLiteral("saveProfileFromDevice"));
    m_saveFromEdited->setObjectName(QStringLiteral("saveProfileFromEdited"));
    m_report->setObjectName(QStringLiteral("commissioningReport"));
    m_recent->setObjectName(QStringLiteral("recentProfiles"));
    connect(m_open, &QAction::triggered, this, &ProfileActions::chooseOpen);
    connect(m_saveFromDevice, &QAction::triggered, this, [this] { chooseSave(true); });
    connect(m_saveFromEdited, &QAction::triggered, this, [this] { chooseSave(false); });
    connect(m_report, &QAction::triggered, this, &ProfileActions::chooseReport);
    m_backups->setObjectName(QStringLiteral("backups"));
    m_backupDir = BackupStore::defaultDirectory();
    connect(m_backups, &QAction::triggered, this, &ProfileActions::showBackups);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &ProfileActions::updateActions);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            &ProfileActions::updateActions);
    retranslate();
    rebuildRecent();
    updateActions();
}

BackupsDialog *ProfileActions::backupsDialog() const
{
    return m_backupsDialog;
}

void ProfileActions::showBackups()
{
    if (!m_backupsDialog) {
        m_backupsDialog = new BackupsDialog(m_session->map(), m_backupDir, m_window);
        m_backupsDialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_backupsDialog, &BackupsDialog::restoreRequested, this,
                &ProfileActions::openBackupFile);
    }
    m_backupsDialog->reload();
    m_backupsDialog->show();
    m_backupsDialog->raise();
}

bool ProfileActions::openBackupFile(const QString &path)
{
    const ProfileParseResult r = BackupStore::load(path, m_session->map());
    if (!r.ok()) {
        showErrors(tr("The backup cannot be used"), r.errors);
        return false;
    }
    showCompare(*r.profile, QFileInfo(path).fileName());
    Q_EMIT finished(true, tr("Opened backup %1").arg(path));
    return true;
}

ProfileCompareDialog *ProfileActions::compareDialog() const
{
    return m_compare;
}

QMessageBox *ProfileActions::errorBox() const
{
    return m_errorBox;
}

void ProfileActions::retranslate()
{
    m_open->setText(tr("&Open profile…"));
    m_open->setToolTip(m_offlineOpener
                           ? tr("Connected: compare a profile file with the controller (nothing "
                                "is written until you apply checked rows). Without a controller: "
                                "edit the file on the pages")
                           : tr("Compare a profile file with the controller; nothing is written "
                                "until you apply checked rows"));
    m_saveFromDevice->setText(tr("Save profile from &device…"));
    m_saveFromDevice->setToolTip(tr("Read every parameter, then save them as a profile file"));
    m_saveFromEdited->setText(tr("Save profile from &edited values…"));
    m_saveFromEdited->setToolTip(
        tr("Save the values the pages show (edits included) as a profile file"));
    m_report->setText(tr("Commissioning &report…"));
    m_backups->setText(tr("&Backups…"));
    m_backups->setToolTip(tr("The controller's settings saved before each apply, factory "
                             "reset, save to flash and id or baud change"));
    m_report->setToolTip(tr("Read everything, then write the commissioning sheet as PDF or "
                            "HTML"));
    m_recent->setTitle(tr("Recent &profiles"));
    rebuildRecent();
}

void ProfileActions::updateActions()
{
    const bool connected = m_session->connection()->isConnected();
    m_saveFromDevice->setEnabled(connected);
    m_report->setEnabled(connected);
    m_backups->setEnabled(connected); // a backup is restored onto a controller
    bool known = true;
    for (const Parameter *p : Profile::profileParameters(m_session->map(), false))
        known = known && m_session->parameters()->store()->shownValue(p->key).has_value();
    m_saveFromEdited->setEnabled(known);
}

QString ProfileActions::lastDirectory() const
{
    QSettings settings;
    settings.beginGroup(kGroup);
    return settings.value(kDirectory, QDir::homePath()).toString();
}

QStringList ProfileActions::recentFiles()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    return settings.value(kRecent).toStringList();
}

void ProfileActions::addRecent(const QString &path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList recent = recentFiles();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue(kRecent, recent);
    settings.setValue(kDirectory, QFileInfo(absolute).absolutePath());
    rebuildRecent();
}

void ProfileActions::rebuildRecent()
{
    m_recent->clear();
    const QStringList recent = recentFiles();
    for (int i = 0; i < recent.size(); ++i) {
        const QString path = recent.at(i);
        QAction *a = m_recent->addAction(
            QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
        a->setToolTip(path);
        connect(a, &QAction::triggered, this, [this, path] { openFile(path); });
    }
    if (recent.isEmpty())
        m_recent->addAction(tr("(none)"))->setEnabled(false);
}

void ProfileActions::showErrors(const QString &title, const QStringList &errors)
{
    showErrorBox(m_errorBox, m_window, QStringLiteral("profileErrorBox"), title, errors,
                 tr("Nothing was written to the controller."));
    for (const QString &e : errors)
        Q_EMIT finished(false, e);
}

void ProfileActions::chooseOpen()
{
    auto *dialog = new QFileDialog(m_window, tr("Open profile"), lastDirectory(),
                                   tr("StepCom profiles (*.json);;All files (*)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, &ProfileActions::openFile);
    dialog->open();
}

ProfileSaveDialog *ProfileActions::saveDialog() const
{
    return m_saveDialog;
}

QString ProfileActions::suggestedName() const
{
    return ProfileSaveDialog::suggestName(
        m_machine,
        m_session->connection()->isConnected() ? m_session->connection()->settings().deviceId : 0,
        QDate::currentDate());
}

void ProfileActions::chooseSave(bool fromDevice)
{
    // First the name and notes, then where: the file is named after the profile.
    if (m_saveDialog)
        m_saveDialog->close();
    m_saveDialog = new ProfileSaveDialog(fromDevice, suggestedName(), m_window);
    m_saveDialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_saveDialog, &QDialog::accepted, this, [this, fromDevice] {
        const QString name = m_saveDialog->name();
        const QString notes = m_saveDialog->notes();
        auto *dialog =
            new QFileDialog(m_window,
                            fromDevice ? tr("Save profile from the device")
                                       : tr("Save profile from the edited values"),
                            QDir(lastDirectory()).filePath(ProfileSaveDialog::fileNameFor(name)),
                            tr("StepCom profiles (*.json)"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setAcceptMode(QFileDialog::AcceptSave);
        dialog->setDefaultSuffix(QStringLiteral("json"));
        connect(dialog, &QFileDialog::fileSelected, this,
                [this, fromDevice, name, notes](const QString &path) {
                    if (fromDevice)
                        saveFromDeviceFile(path, name, notes);
                    else
                        saveFromEditedFile(path, name, notes);
                });
        dialog->open();
    });
    m_saveDialog->open();
}

void ProfileActions::chooseReport()
{
    auto *notes = new QInputDialog(m_window);
    notes->setAttribute(Qt::WA_DeleteOnClose);
    notes->setWindowTitle(tr("Commissioning report"));
    notes->setLabelText(tr("Notes for the report (machine, place, who commissioned it):"));
    notes->setOption(QInputDialog::UsePlainTextEditForTextInput);
    connect(notes, &QInputDialog::textValueSelected, this, [this](const QString &text) {
        auto *dialog = new QFileDialog(m_window, tr("Save the commissioning report"),
                                       lastDirectory(), tr("PDF (*.pdf);;HTML (*.html)"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setAcceptMode(QFileDialog::AcceptSave);
        dialog->setDefaultSuffix(QStringLiteral("pdf"));
        connect(dialog, &QFileDialog::fileSelected, this,
                [this, text](const QString &path) { reportFile(path, text); });
        dialog->open();
    });
    notes->open();
}

void ProfileActions::setOfflineOpener(std::function<bool(const QString &)> opener)
{
    m_offlineOpener = std::move(opener);
    retranslate();
}

bool ProfileActions::openFile(const QString &path)
{
    if (m_offlineOpener &&
        m_session->connection()->linkState() == SessionConnection::LinkState::Disconnected) {
        const bool opened = m_offlineOpener(path);
        if (opened)
            addRecent(path);
        return opened;
    }
    // A profile of another map opens too: the comparison lists what this map cannot take.
    const ProfileParseResult r =
        ProfileFile::load(path, m_session->map(), ProfileFile::OtherMaps::Accept);
    if (!r.ok()) {
        showErrors(tr("The profile cannot be used"), r.errors);
        return false;
    }
    addRecent(path);
    // The profile's software travel limits are StepCom's settings: they take effect now.
    if (!r.profile->travelLimits.isEmpty() &&
        r.profile->travelLimits != m_session->travelLimits()) {
        m_session->setTravelLimits(r.profile->travelLimits);
        Q_EMIT finished(
            true,
            tr("The software travel limits of %1 are in use now").arg(QFileInfo(path).fileName()));
    }
    m_machine = r.profile->name.isEmpty() ? QFileInfo(path).completeBaseName() : r.profile->name;
    showCompare(*r.profile, QFileInfo(path).fileName());
    Q_EMIT finished(true, tr("Opened profile %1").arg(path));
    return true;
}

void ProfileActions::showCompare(const Profile &profile, const QString &title)
{
    if (m_compare)
        m_compare->close();
    m_compare = new ProfileCompareDialog(m_session, profile, title, m_window);
    m_compare->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_compare, &ProfileCompareDialog::applied, this,
            [this](bool ok, const QStringList &verified, const QStringList &problems) {
                Q_EMIT finished(ok, tr("Profile applied: %n value(s) written and verified", nullptr,
                                       int(verified.size())));
                for (const QString &p : problems)
                    Q_EMIT finished(false, p);
            });
    m_compare->open();
}

void ProfileActions::saveFromDeviceFile(const QString &path, const QString &name,
                                        const QString &notes)
{
    if (!m_session->connection()->isConnected()) {
        showErrors(tr("Save profile"), {tr("Connect to a controller first.")});
        return;
    }
    const QList<const Parameter *> params = Profile::profileParameters(m_session->map(), true);
    QPointer<ProfileActions> self(this);
    m_session->parameters()->read(params, [self, path, name, notes](const ReadOutcome &r) {
        if (!self)
            return;
        self->m_session->parameters()->store()->setDeviceValues(r.values);
        if (!r.ok) {
            self->showErrors(tr("Save profile"), QStringList{tr("Nothing was saved: the "
                                                                "controller could not be read "
                                                                "completely.")} +
                                                     r.errors);
            return;
        }
        Profile profile = Profile::fromValues(self->m_session->map(), r.values, true);
        profile.unsupported = r.unsupported; // not "missing" when the file is read again
        profile.name = name.isEmpty() ? QFileInfo(path).completeBaseName() : name;
        profile.notes = notes;
        profile.deviceId = self->m_session->connection()->settings().deviceId;
        profile.fromSimulator = self->m_session->connection()->isSimulator();
        profile.travelLimits = self->m_session->travelLimits();
        if (const QString e = ProfileFile::save(path, profile, self->m_session->map());
            !e.isEmpty()) {
            self->showErrors(tr("Save profile"), {e});
            return;
        }
        self->addRecent(path);
        self->m_machine = profile.name;
        Q_EMIT self->finished(true, tr("Saved the controller's %n parameter(s) to %1", nullptr,
                                       int(profile.values.size()))
                                        .arg(path));
    });
}

bool ProfileActions::saveFromEditedFile(const QString &path, const QString &name,
                                        const QString &notes)
{
    QHash<QString, qint64> values;
    QStringList unknown;
    for (const Parameter *p : Profile::profileParameters(m_session->map(), true)) {
        if (const auto v = m_session->parameters()->store()->shownValue(p->key))
            values.insert(p->key, *v);
        else if (!Profile::isLinkSetting(p->key))
            unknown << p->key;
    }
    if (!unknown.isEmpty()) {
        showErrors(tr("Save profile"), {tr("%n value(s) are not known yet (read all first): %1",
                                           nullptr, int(unknown.size()))
                                            .arg(unknown.join(QLatin1String(", ")))});
        return false;
    }
    Profile profile = Profile::fromValues(m_session->map(), values, true);
    profile.name = name.isEmpty() ? QFileInfo(path).completeBaseName() : name;
    profile.notes = notes;
    if (m_session->connection()->isConnected()) {
        profile.deviceId = m_session->connection()->settings().deviceId;
        profile.fromSimulator = m_session->connection()->isSimulator();
    }
    profile.travelLimits = m_session->travelLimits();
    if (const QString e = ProfileFile::save(path, profile, m_session->map()); !e.isEmpty()) {
        showErrors(tr("Save profile"), {e});
        return false;
    }
    addRecent(path);
    m_machine = profile.name;
    Q_EMIT finished(true, tr("Saved %n value(s) as shown (edits included) to %1", nullptr,
                             int(profile.values.size()))
                              .arg(path));
    return true;
}

void ProfileActions::reportFile(const QString &path, const QString &notes)
{
    if (!m_session->connection()->isConnected()) {
        showErrors(tr("Commissioning report"), {tr("Connect to a controller first.")});
        return;
    }
    QPointer<ProfileActions> self(this);
    m_session->parameters()->readAll([self, path, notes](const ReadOutcome &r) {
        if (!self)
            return;
        self->m_session->parameters()->store()->setDeviceValues(r.values);
        if (!r.ok) {
            self->showErrors(tr("Commissioning report"),
                             QStringList{tr("No report: the controller could not be read "
                                            "completely.")} +
                                 r.errors);
            return;
        }
        // Read just now, for this report.
        ReportInput input =
            ReportInput::fromSession(*self->m_session, self->m_session->line()->deviceInView(),
                                     r.values, QDateTime::currentDateTime());
        input.unsupported = r.unsupported;
        input.notes = notes;
        input.locale = Language::instance().current();
        if (self->m_checklist) {
            if (const auto c = self->m_checklist()) {
                input.checklist = c->first;
                input.checklistFile = c->second;
            }
        }
        if (const QString e = CommissioningReport(input).write(path); !e.isEmpty()) {
            self->showErrors(tr("Commissioning report"), {e});
            return;
        }
        Q_EMIT self->finished(true, tr("Commissioning report written to %1").arg(path));
    });
}

} // namespace stepcom
