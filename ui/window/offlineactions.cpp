#include "window/offlineactions.h"

#include "base/errorbox.h"
#include "base/language.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilefilesdialog.h"
#include "profile/profiledocument.h"
#include "profile/profilefile.h"
#include "report/commissioningreport.h"
#include "report/reportinput.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

namespace stepcom {

namespace {
QString lastDirectory()
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("profiles"));
    return settings.value(QStringLiteral("lastDirectory"), QDir::homePath()).toString();
}
} // namespace

OfflineActions::OfflineActions(DeviceSession *session, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_window(window)
    , m_document(new ProfileDocument(session, this))
    , m_new(new QAction(this))
    , m_save(new QAction(this))
    , m_saveAs(new QAction(this))
    , m_close(new QAction(this))
    , m_compare(new QAction(this))
    , m_report(new QAction(this))
{
    m_new->setObjectName(QStringLiteral("newProfile"));
    m_save->setObjectName(QStringLiteral("saveProfile"));
    m_saveAs->setObjectName(QStringLiteral("saveProfileAs"));
    m_close->setObjectName(QStringLiteral("closeProfile"));
    m_compare->setObjectName(QStringLiteral("compareProfiles"));
    m_report->setObjectName(QStringLiteral("reportFromProfile"));
    connect(m_new, &QAction::triggered, this, [this] { newFromFactory(); });
    connect(m_save, &QAction::triggered, this, [this] { save(); });
    connect(m_saveAs, &QAction::triggered, this, &OfflineActions::chooseSaveAs);
    connect(m_close, &QAction::triggered, this, [this] { closeFile(); });
    connect(m_compare, &QAction::triggered, this, &OfflineActions::chooseCompare);
    connect(m_report, &QAction::triggered, this, &OfflineActions::chooseReport);
    connect(m_document, &ProfileDocument::changed, this, &OfflineActions::updateActions);
    connect(m_document, &ProfileDocument::leftForController, this, &OfflineActions::offerCompare);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &OfflineActions::updateActions);
    retranslate();
    updateActions();
}

QMessageBox *OfflineActions::question() const
{
    return m_question;
}

QMessageBox *OfflineActions::errorBox() const
{
    return m_errorBox;
}

ProfileFilesDialog *OfflineActions::filesDialog() const
{
    return m_files;
}

ProfileCompareDialog *OfflineActions::compareDialog() const
{
    return m_compareDialog;
}

void OfflineActions::retranslate()
{
    m_new->setText(tr("&New profile from factory values"));
    m_new->setToolTip(tr("Edit a new profile, starting from the factory values, without a "
                         "controller"));
    m_save->setText(tr("Save p&rofile file"));
    m_save->setToolTip(tr("Save the profile being edited to its file (no controller is "
                          "written)"));
    m_saveAs->setText(tr("Save profile file &as…"));
    m_saveAs->setToolTip(tr("Save the profile being edited to another file"));
    m_close->setText(tr("&Close profile file"));
    m_close->setToolTip(tr("Stop editing the profile file"));
    m_compare->setText(tr("&Compare profiles…"));
    m_compare->setToolTip(tr("Compare two profile files row by row; no controller is needed"));
    m_report->setText(tr("Report from a &profile…"));
    m_report->setToolTip(tr("The commissioning report made from a profile file (or the file "
                            "being edited), not from a controller"));
}

void OfflineActions::updateActions()
{
    const bool idle =
        m_session->connection()->linkState() == SessionConnection::LinkState::Disconnected;
    const bool open = m_document->isOpen();
    m_new->setEnabled(idle);
    m_save->setEnabled(open);
    m_saveAs->setEnabled(open);
    m_close->setEnabled(open);
}

void OfflineActions::showErrors(const QString &title, const QStringList &errors)
{
    showErrorBox(m_errorBox, m_window, QStringLiteral("offlineErrorBox"), title, errors);
    for (const QString &e : errors)
        Q_EMIT finished(false, e);
}

bool OfflineActions::whenSettled(const std::function<void()> &then)
{
    if (!m_document->isModified()) {
        then();
        return true;
    }
    if (m_question)
        m_question->close();
    const bool canSave = !m_document->path().isEmpty();
    m_question = new QMessageBox(QMessageBox::Warning, tr("Unsaved edits"),
                                 tr("%n edited value(s) of %1 are not saved in the file.", nullptr,
                                    int(m_session->parameters()->store()->editedKeys().size()))
                                     .arg(m_document->displayName()),
                                 (canSave ? QMessageBox::Save : QMessageBox::NoButton) |
                                     QMessageBox::Discard | QMessageBox::Cancel,
                                 m_window);
    m_question->setObjectName(QStringLiteral("unsavedProfileQuestion"));
    m_question->setAttribute(Qt::WA_DeleteOnClose);
    m_question->setDefaultButton(QMessageBox::Cancel);
    connect(m_question, &QMessageBox::finished, this, [this, then](int result) {
        if (result == QMessageBox::Save && !saveFile(m_document->path()))
            return;
        if (result == QMessageBox::Save || result == QMessageBox::Discard)
            then();
    });
    m_question->open();
    return false;
}

bool OfflineActions::openFile(const QString &path)
{
    return whenSettled([this, path] {
               if (const QStringList errors = m_document->open(path); !errors.isEmpty()) {
                   showErrors(tr("The profile cannot be edited"), errors);
                   return;
               }
               Q_EMIT finished(true,
                               tr("Editing the profile file %1 without a controller").arg(path));
               for (const QString &line : m_document->varianceLines(Language::instance().current()))
                   Q_EMIT finished(false, line);
           }) &&
           m_document->isOpen() && m_document->path() == path;
}

bool OfflineActions::newFromFactory()
{
    return whenSettled([this] {
               if (const QStringList errors = m_document->newFromFactory(); !errors.isEmpty()) {
                   showErrors(tr("New profile"), errors);
                   return;
               }
               Q_EMIT finished(true, tr("Editing a new profile with the factory values; nothing is "
                                        "written to a controller"));
           }) &&
           m_document->isOpen();
}

bool OfflineActions::save()
{
    if (!m_document->isOpen())
        return false;
    if (m_document->path().isEmpty()) {
        chooseSaveAs();
        return false;
    }
    return saveFile(m_document->path());
}

bool OfflineActions::saveFile(const QString &path)
{
    QStringList filled;
    if (const QString e = m_document->save(path, &filled); !e.isEmpty()) {
        showErrors(tr("Save profile"), {e});
        return false;
    }
    Q_EMIT finished(true, tr("Saved the profile to %1 (no controller was written)").arg(path));
    if (!filled.isEmpty())
        Q_EMIT finished(false, tr("The file lacked %n setting(s); they were saved with their "
                                  "factory values: %1",
                                  nullptr, int(filled.size()))
                                   .arg(filled.join(QLatin1String(", "))));
    return true;
}

bool OfflineActions::closeFile()
{
    return whenSettled([this] { m_document->close(); }) && !m_document->isOpen();
}

void OfflineActions::chooseSaveAs()
{
    auto *dialog = new QFileDialog(m_window, tr("Save profile file as"), lastDirectory(),
                                   tr("StepCom profiles (*.json)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("json"));
    connect(dialog, &QFileDialog::fileSelected, this, &OfflineActions::saveFile);
    dialog->open();
}

void OfflineActions::chooseCompare()
{
    auto *dialog = new QFileDialog(m_window, tr("Compare profiles: choose two files"),
                                   lastDirectory(), tr("StepCom profiles (*.json);;All files (*)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFiles);
    connect(dialog, &QFileDialog::filesSelected, this, [this](const QStringList &files) {
        if (files.size() != 2) {
            showErrors(tr("Compare profiles"), {tr("Choose exactly two profile files (%n chosen).",
                                                   nullptr, int(files.size()))});
            return;
        }
        compareFiles(files.at(0), files.at(1));
    });
    dialog->open();
}

bool OfflineActions::compareFiles(const QString &pathA, const QString &pathB)
{
    const RegisterMap &map = m_session->map();
    const ProfileParseResult a = ProfileFile::load(pathA, map, ProfileFile::OtherMaps::Accept);
    const ProfileParseResult b = ProfileFile::load(pathB, map, ProfileFile::OtherMaps::Accept);
    QStringList errors;
    for (const auto &[path, r] : {std::pair{pathA, &a}, std::pair{pathB, &b}}) {
        for (const QString &e : r->errors)
            errors << QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), e);
    }
    if (!errors.isEmpty()) {
        showErrors(tr("The profiles cannot be compared"), errors);
        return false;
    }
    if (m_files)
        m_files->close();
    m_files = new ProfileFilesDialog(map, *a.profile, QFileInfo(pathA).fileName(), *b.profile,
                                     QFileInfo(pathB).fileName(), m_window);
    m_files->setAttribute(Qt::WA_DeleteOnClose);
    m_files->open();
    Q_EMIT finished(true, tr("Compared %1 with %2").arg(pathA, pathB));
    return true;
}

void OfflineActions::chooseReport()
{
    if (m_document->isOpen()) {
        askNotesThenReport(QString());
        return;
    }
    auto *dialog = new QFileDialog(m_window, tr("Report from a profile: choose the profile"),
                                   lastDirectory(), tr("StepCom profiles (*.json);;All files (*)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, &OfflineActions::askNotesThenReport);
    dialog->open();
}

// An empty `profilePath`: the file being edited.
void OfflineActions::askNotesThenReport(const QString &profilePath)
{
    auto *notes = new QInputDialog(m_window);
    notes->setAttribute(Qt::WA_DeleteOnClose);
    notes->setWindowTitle(tr("Report from a profile"));
    notes->setLabelText(tr("Notes for the report (empty: the profile's own notes):"));
    notes->setOption(QInputDialog::UsePlainTextEditForTextInput);
    connect(notes, &QInputDialog::textValueSelected, this, [this, profilePath](const QString &t) {
        auto *dialog = new QFileDialog(m_window, tr("Save the report made from the profile"),
                                       lastDirectory(), tr("PDF (*.pdf);;HTML (*.html)"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setAcceptMode(QFileDialog::AcceptSave);
        dialog->setDefaultSuffix(QStringLiteral("pdf"));
        connect(dialog, &QFileDialog::fileSelected, this,
                [this, profilePath, t](const QString &out) {
                    if (profilePath.isEmpty())
                        reportFromDocument(out, t);
                    else
                        reportFromFile(profilePath, out, t);
                });
        dialog->open();
    });
    notes->open();
}

bool OfflineActions::reportFromFile(const QString &profilePath, const QString &out,
                                    const QString &notes)
{
    const ProfileParseResult r =
        ProfileFile::load(profilePath, m_session->map(), ProfileFile::OtherMaps::Accept);
    if (!r.ok()) {
        showErrors(tr("Report from a profile"), r.errors);
        return false;
    }
    ReportInput input = ReportInput::fromProfile(m_session->map(), *r.profile, profilePath,
                                                 Language::instance().current());
    if (!notes.isEmpty())
        input.notes = notes;
    if (const QString e = CommissioningReport(input).write(out); !e.isEmpty()) {
        showErrors(tr("Report from a profile"), {e});
        return false;
    }
    Q_EMIT finished(true, tr("Report made from the profile file %1 (no controller was read) "
                             "written to %2")
                              .arg(profilePath, out));
    return true;
}

bool OfflineActions::reportFromDocument(const QString &out, const QString &notes)
{
    if (!m_document->isOpen())
        return false;
    ReportInput input =
        ReportInput::fromProfile(m_session->map(), m_document->current(), m_document->path(),
                                 Language::instance().current());
    // Made from the file being edited: say so, and that the edits are not in the file yet.
    input.sourceFile = m_document->displayName();
    if (m_document->isModified())
        input.sourceFile += QLatin1Char(' ') + tr("(with edits not saved in the file)");
    if (!notes.isEmpty())
        input.notes = notes;
    if (const QString e = CommissioningReport(input).write(out); !e.isEmpty()) {
        showErrors(tr("Report from a profile"), {e});
        return false;
    }
    Q_EMIT finished(true, tr("Report made from the profile file %1 (no controller was read) "
                             "written to %2")
                              .arg(input.sourceFile, out));
    return true;
}

void OfflineActions::offerCompare(const Profile &values, const QString &path, int unsavedEdits)
{
    const QString name = path.isEmpty() ? tr("new profile") : QFileInfo(path).fileName();
    if (m_compareDialog)
        m_compareDialog->close();
    m_compareDialog = new ProfileCompareDialog(m_session, values, name, m_window);
    m_compareDialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_compareDialog, &ProfileCompareDialog::applied, this,
            [this](bool ok, const QStringList &verified, const QStringList &problems) {
                Q_EMIT finished(ok, tr("Profile applied: %n value(s) written and verified", nullptr,
                                       int(verified.size())));
                for (const QString &p : problems)
                    Q_EMIT finished(false, p);
            });
    m_compareDialog->open();
    Q_EMIT finished(true, tr("Connected: the values of %1 are compared with the controller's; "
                             "nothing is written until you apply checked rows")
                              .arg(name));
    if (unsavedEdits > 0)
        Q_EMIT finished(false, tr("%n edit(s) of %1 were never saved: they are in the "
                                  "comparison, not in the file",
                                  nullptr, unsavedEdits)
                                   .arg(name));
}

} // namespace stepcom
