#pragma once

#include <QDialog>
#include <QPointer>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QMessageBox;
class QSpinBox;

namespace stepcom {

struct BundleInput;

// Help → Create support bundle… (issue 26): how many days of session logs (their number and
// size shown), whether the open profile and its checklist go in, then where to save; the
// bundle is written by SupportBundle, as `stepcomctl bundle` writes it, and a message says what
// is in it. Non-modal; createFile() does the work and is what tests call.
class SupportBundleDialog : public QDialog
{
    Q_OBJECT
public:
    // `profilePath`: the profile open in the window (empty: none).
    explicit SupportBundleDialog(const QString &profilePath, QWidget *parent = nullptr);

    void setLogDirectory(const QString &directory);
    void setDays(int days);
    int days() const;
    void setProfileIncluded(bool included);
    // "3 session logs, 1.2 MB" for the days chosen.
    QString logsText() const;
    BundleInput input() const;
    // Writes the bundle; the message (what was written, or why not) opens and `written` follows.
    bool createFile(const QString &zipPath);
    QMessageBox *resultBox() const;

Q_SIGNALS:
    void written(bool ok, const QString &message);

private:
    void refresh();
    void chooseFile();

    QString m_profilePath;
    QString m_logDirectory;
    QSpinBox *m_days;
    QLabel *m_logs;
    QCheckBox *m_profile;
    QDialogButtonBox *m_buttons;
    QPointer<QMessageBox> m_result;
};

} // namespace stepcom
