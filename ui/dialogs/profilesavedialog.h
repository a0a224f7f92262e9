#pragma once

#include <QDialog>

class QDate;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace stepcom {

// Before a profile is saved: its name (suggested from the machine or the controller's id and
// the date) and notes, both stored in the file; the file name follows the name.
class ProfileSaveDialog : public QDialog
{
    Q_OBJECT
public:
    ProfileSaveDialog(bool fromDevice, const QString &suggestedName, QWidget *parent = nullptr);

    QString name() const;
    QString notes() const;
    QLineEdit *nameEdit() const { return m_name; }
    QPlainTextEdit *notesEdit() const { return m_notes; }

    // "Machine A 2026-11-24", or "Controller id 3 2026-11-24" when the machine has no name yet;
    // a date already ending the machine's name is replaced.
    static QString suggestName(const QString &machine, int deviceId, const QDate &date);
    // A file name for the name: characters no file system takes become '-', ".json" added.
    static QString fileNameFor(const QString &name);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    bool m_fromDevice;
    QLabel *m_what;
    QLabel *m_nameLabel;
    QLabel *m_notesLabel;
    QLineEdit *m_name;
    QPlainTextEdit *m_notes;
    QDialogButtonBox *m_buttons;
};

} // namespace stepcom
