#pragma once

#include "profile/profile.h"

#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QMessageBox;
class QWidget;

namespace stepcom {

class DeviceSession;
class ProfileCompareDialog;
class ProfileDocument;
class ProfileFilesDialog;

// Working without the machine, in the File menu: edit a profile file on the usual pages (new
// from factory values, save, save as, close), compare two files, and the commissioning report
// made from a file. Nothing here reaches a controller; connecting while a file is edited
// opens the usual compare-and-apply with the file's values. Choosers and questions are
// non-modal; the *File() methods do the work and are what tests call.
class OfflineActions : public QObject
{
    Q_OBJECT
public:
    OfflineActions(DeviceSession *session, QWidget *window);

    ProfileDocument *document() const { return m_document; }
    QAction *newAction() const { return m_new; }
    QAction *saveAction() const { return m_save; }
    QAction *saveAsAction() const { return m_saveAs; }
    QAction *closeAction() const { return m_close; }
    QAction *compareAction() const { return m_compare; }
    QAction *reportAction() const { return m_report; }
    // The question about unsaved edits, while it is open.
    QMessageBox *question() const;
    QMessageBox *errorBox() const;
    ProfileFilesDialog *filesDialog() const;
    // The comparison opened when a controller connected while a file was edited.
    ProfileCompareDialog *compareDialog() const;
    void retranslate();

    // Edit this profile without a controller. With unsaved edits the question comes first and
    // this returns false; the answer decides.
    bool openFile(const QString &path);
    bool newFromFactory();
    // Save to the file's own path (a new profile asks for one).
    bool save();
    // Save as `path`; it becomes the file edited.
    bool saveFile(const QString &path);
    // Stop editing (asks first about unsaved edits, then false).
    bool closeFile();
    // Two files row by row, no controller.
    bool compareFiles(const QString &pathA, const QString &pathB);
    // The commissioning report of a profile file, or of the file being edited (its edits
    // included), as PDF or HTML by `out`'s suffix; marked as made from a file.
    bool reportFromFile(const QString &profilePath, const QString &out, const QString &notes);
    bool reportFromDocument(const QString &out, const QString &notes);

Q_SIGNALS:
    // Every outcome, for the message dock; ok = false for errors.
    void finished(bool ok, const QString &message);

private:
    // Run `then` now when there are no unsaved edits; else ask (save, discard, cancel) and
    // run it after a save or a discard. Returns whether it ran now.
    bool whenSettled(const std::function<void()> &then);
    void chooseSaveAs();
    void chooseCompare();
    void chooseReport();
    void askNotesThenReport(const QString &profilePath);
    void showErrors(const QString &title, const QStringList &errors);
    void offerCompare(const Profile &values, const QString &path, int unsavedEdits);
    void updateActions();

    DeviceSession *m_session;
    QWidget *m_window;
    ProfileDocument *m_document;
    QAction *m_new;
    QAction *m_save;
    QAction *m_saveAs;
    QAction *m_close;
    QAction *m_compare;
    QAction *m_report;
    QPointer<QMessageBox> m_question;
    QPointer<QMessageBox> m_errorBox;
    QPointer<ProfileFilesDialog> m_files;
    QPointer<ProfileCompareDialog> m_compareDialog;
};

} // namespace stepcom
