#pragma once

#include "dialogs/reportsheets.h"

#include <QDialog>
#include <QPointer>
#include <QTimer>

#include <memory>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QMessageBox;
class QProgressBar;
class QSpinBox;

namespace stepcom {

struct BundleInput;
struct ReportInput;

// Help → Create support bundle…: how many days of session logs (their number and
// size shown), whether the open profile and its checklist go in, whether the machine's
// commissioning report goes in (the devices as the window last read them, the profile's sheet),
// then where to save; the bundle is written by SupportBundle, as `stepcomctl bundle` writes it,
// on a thread of its own: a progress bar fills, Cancel stops it (nothing is left), and a message
// says what is in it. Non-modal; createFile() starts the work and is what tests call.
class SupportBundleDialog : public QDialog
{
    Q_OBJECT
public:
    // `profilePath`: the profile open in the window (empty: none); `sheets`: the window's
    // devices, for the report (empty functions: none).
    SupportBundleDialog(const QString &profilePath, ReportSheets sheets, QWidget *parent = nullptr);
    ~SupportBundleDialog() override;

    void setLogDirectory(const QString &directory);
    void setDays(int days);
    int days() const;
    void setProfileIncluded(bool included);
    void setReportIncluded(bool included);
    // "3 session logs, 1.2 MB" for the days chosen.
    QString logsText() const;
    // What the report covers ("ids 1, 2 as last read; the profile machine-a.json"), or why
    // there is none.
    QString reportText() const;
    BundleInput input() const;
    // The sheets of the machine's report as chosen (empty: no report; `noReport` says why).
    QList<ReportInput> reportSheets(QString *noReport = nullptr) const;
    // Starts writing the bundle; false (and `written`, with why) when it cannot start. The
    // message (what was written, why not, or that it was cancelled) opens and `written`
    // follows when the work ends.
    bool createFile(const QString &zipPath);
    bool isBusy() const { return bool(m_work); }
    // Stops the bundle being written (also Cancel and Escape while it runs).
    void cancelWork();
    QProgressBar *progressBar() const { return m_progressBar; }
    QMessageBox *resultBox() const;

    void reject() override;

Q_SIGNALS:
    void written(bool ok, const QString &message);

private:
    struct Work;
    void refresh();
    // The sheets there are (the devices read, the profile's when it goes in), chosen or not.
    QList<ReportInput> availableSheets(QStringList *problems) const;
    void chooseFile();
    void setBusy(bool busy);
    void workDone();
    // `icon`: a QMessageBox::Icon.
    void showResult(bool ok, const QString &message, int icon);

    QString m_profilePath;
    ReportSheets m_sheets;
    QString m_logDirectory;
    QSpinBox *m_days;
    QLabel *m_logs;
    QCheckBox *m_profile;
    QCheckBox *m_report;
    QLabel *m_reportContents;
    bool m_reportWanted = true; // the user's choice, kept while there is nothing to report
    QProgressBar *m_progressBar;
    QDialogButtonBox *m_buttons;
    QPointer<QMessageBox> m_result;
    std::shared_ptr<Work> m_work;
    QTimer m_poll;
};

} // namespace stepcom
