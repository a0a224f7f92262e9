#include "dialogs/supportbundledialog.h"

#include "base/language.h"
#include "report/machinereport.h"
#include "support/supportbundle.h"

#include <QCheckBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QThread>
#include <QVBoxLayout>

#include <atomic>

namespace stepcom {

namespace {

constexpr int kProgressSteps = 1000;
constexpr int kProgressPollMs = 100;

} // namespace

// The bundle being written: its thread, how far it got, Cancel, and the outcome.
struct SupportBundleDialog::Work
{
    QThread *thread = nullptr;
    QString zipPath;
    std::atomic<qint64> done{0};
    std::atomic<qint64> total{0};
    std::atomic<bool> cancel{false};
    bool ok = false; // set on the thread, read after it finished
    QStringList contents;
    QString error;
};

SupportBundleDialog::SupportBundleDialog(const QString &profilePath, ReportSheets sheets,
                                         QWidget *parent)
    : QDialog(parent)
    , m_profilePath(profilePath)
    , m_sheets(std::move(sheets))
    , m_logDirectory(SupportBundle::defaultLogDirectory())
    , m_days(new QSpinBox(this))
    , m_logs(new QLabel(this))
    , m_profile(new QCheckBox(this))
    , m_report(new QCheckBox(this))
    , m_reportContents(new QLabel(this))
    , m_progressBar(new QProgressBar(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("supportBundleDialog"));
    setWindowTitle(tr("Create support bundle"));
    auto *intro = new QLabel(
        tr("One .zip file to send to support: the session logs (every frame of every "
           "connection), the profile and its checklist, the commissioning report of the machine, "
           "StepCom's settings (there are no passwords in them), the versions of StepCom, Qt and "
           "the system, and the serial adapters seen. A README inside lists it all."),
        this);
    intro->setWordWrap(true);
    m_days->setObjectName(QStringLiteral("bundleDays"));
    m_days->setRange(1, 365);
    m_days->setValue(7);
    m_logs->setObjectName(QStringLiteral("bundleLogs"));
    m_profile->setObjectName(QStringLiteral("bundleProfile"));
    const bool haveProfile = !profilePath.isEmpty() && QFileInfo::exists(profilePath);
    m_profile->setText(
        haveProfile
            ? tr("The profile %1 and its checklist").arg(QDir::toNativeSeparators(profilePath))
            : tr("No profile is open"));
    m_profile->setEnabled(haveProfile);
    m_profile->setChecked(haveProfile);
    m_report->setObjectName(QStringLiteral("bundleReport"));
    m_report->setText(tr("The commissioning report of the machine"));
    m_reportContents->setObjectName(QStringLiteral("bundleReportContents"));
    m_reportContents->setWordWrap(true);
    m_progressBar->setObjectName(QStringLiteral("bundleProgress"));
    m_progressBar->setRange(0, kProgressSteps);
    m_progressBar->setVisible(false);
    m_buttons->button(QDialogButtonBox::Save)->setText(tr("&Save bundle…"));
    auto *form = new QFormLayout;
    form->addRow(tr("Session logs of the last days:"), m_days);
    form->addRow(QString(), m_logs);
    form->addRow(tr("Profile:"), m_profile);
    form->addRow(tr("Report:"), m_report);
    form->addRow(QString(), m_reportContents);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_progressBar);
    layout->addWidget(m_buttons);
    connect(m_days, &QSpinBox::valueChanged, this, &SupportBundleDialog::refresh);
    connect(m_profile, &QCheckBox::toggled, this, &SupportBundleDialog::refresh);
    connect(m_report, &QCheckBox::clicked, this, [this](bool on) { m_reportWanted = on; });
    connect(m_buttons, &QDialogButtonBox::accepted, this, &SupportBundleDialog::chooseFile);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &SupportBundleDialog::reject);
    m_poll.setInterval(kProgressPollMs);
    connect(&m_poll, &QTimer::timeout, this, [this] {
        if (m_work && m_work->total > 0)
            m_progressBar->setValue(int(m_work->done * kProgressSteps / m_work->total));
    });
    refresh();
}

SupportBundleDialog::~SupportBundleDialog()
{
    if (m_work) { // closed with the window: stop it, nothing is left
        m_work->cancel = true;
        m_work->thread->wait();
    }
}

void SupportBundleDialog::setLogDirectory(const QString &directory)
{
    m_logDirectory = directory;
    refresh();
}

void SupportBundleDialog::setDays(int days)
{
    m_days->setValue(days);
}

int SupportBundleDialog::days() const
{
    return m_days->value();
}

void SupportBundleDialog::setProfileIncluded(bool included)
{
    m_profile->setChecked(included && m_profile->isEnabled());
}

void SupportBundleDialog::setReportIncluded(bool included)
{
    m_reportWanted = included;
    refresh();
}

QList<ReportInput> SupportBundleDialog::availableSheets(QStringList *problems) const
{
    QList<ReportInput> sheets;
    if (m_sheets.known)
        sheets = m_sheets.known();
    if (m_profile->isChecked() && m_sheets.fromProfile) {
        if (const auto sheet = m_sheets.fromProfile(m_profilePath, problems))
            sheets << *sheet;
    }
    return sheets;
}

QList<ReportInput> SupportBundleDialog::reportSheets(QString *noReport) const
{
    QStringList problems;
    QList<ReportInput> sheets = availableSheets(&problems);
    // The reasons go into the README: English, as all of it.
    QString why;
    if (sheets.isEmpty() && problems.isEmpty())
        why = QStringLiteral("no device's settings were read in the session and no profile "
                             "went in");
    else if (sheets.isEmpty())
        why = QStringLiteral("no device's settings were read in the session, and the profile "
                             "could not be read (%1)")
                  .arg(problems.join(QStringLiteral("; ")));
    else if (!m_reportWanted)
        why = QStringLiteral("left out when the bundle was made");
    if (!m_reportWanted)
        sheets.clear();
    if (noReport)
        *noReport = why;
    return sheets;
}

QString SupportBundleDialog::reportText() const
{
    const QList<ReportInput> sheets = availableSheets(nullptr);
    QStringList ids;
    bool profile = false;
    for (const ReportInput &sheet : sheets) {
        if (sheet.fromFile())
            profile = true;
        else
            ids << QString::number(sheet.deviceId);
    }
    QStringList parts;
    if (!ids.isEmpty())
        parts << tr("id(s) %1 as last read", nullptr, int(ids.size()))
                     .arg(ids.join(QStringLiteral(", ")));
    if (profile)
        parts << tr("the profile %1").arg(QFileInfo(m_profilePath).fileName());
    if (parts.isEmpty())
        return tr("None: no device's settings were read in this session and no profile goes in");
    return parts.join(QStringLiteral("; "));
}

BundleInput SupportBundleDialog::input() const
{
    BundleInput in;
    in.logDirectory = m_logDirectory;
    in.days = m_days->value();
    in.profilePath = m_profile->isChecked() ? m_profilePath : QString();
    in.settingsFiles = SupportBundle::defaultSettingsFiles();
    return in;
}

QString SupportBundleDialog::logsText() const
{
    qint64 bytes = 0;
    const QFileInfoList logs = SupportBundle::logsFor(input());
    for (const QFileInfo &log : logs)
        bytes += log.size();
    return tr("%n session log(s), %1", nullptr, int(logs.size()))
        .arg(QLocale().formattedDataSize(bytes));
}

void SupportBundleDialog::refresh()
{
    m_logs->setText(logsText());
    // Nothing to report: off, and it says why; the choice comes back with something to report.
    const bool something = !availableSheets(nullptr).isEmpty();
    m_reportContents->setText(reportText());
    m_report->setEnabled(something);
    m_report->setChecked(something && m_reportWanted);
}

void SupportBundleDialog::chooseFile()
{
    const QString name =
        QStringLiteral("stepcom-support-%1.zip")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")));
    auto *dialog = new QFileDialog(this, tr("Save support bundle"), QDir::home().filePath(name),
                                   tr("Zip files (*.zip)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("zip"));
    connect(dialog, &QFileDialog::fileSelected, this, &SupportBundleDialog::createFile);
    dialog->open();
}

bool SupportBundleDialog::createFile(const QString &zipPath)
{
    if (m_work)
        return false; // one at a time: Save is off while it runs
    QString noReport;
    const QList<ReportInput> sheets = reportSheets(&noReport);
    BundleInput in = input();
    in.noReport = noReport;
    const QString locale = Language::instance().current();
    auto work = std::make_shared<Work>();
    work->zipPath = zipPath;
    Work *w = work.get();
    // Many MB of logs take a while to pack: not on the GUI thread. The dialog waits for it
    // before it goes, so `w` outlives the thread.
    w->thread = QThread::create([w, in, sheets, locale]() mutable {
        if (!sheets.isEmpty()) { // a machine of many devices takes a moment to draw too
            const MachineReport report(sheets, QString(), QString(), locale);
            in.reportHtml = report.selfContainedHtml().toUtf8();
            in.reportSheets = report.sheetLines();
        }
        SupportBundle::Callbacks callbacks;
        callbacks.progress = [w](qint64 done, qint64 total) {
            w->done = done;
            w->total = total;
        };
        callbacks.cancelled = [w] { return w->cancel.load(); };
        w->ok = SupportBundle::create(w->zipPath, in, &w->contents, &w->error, callbacks);
    });
    m_work = work;
    connect(w->thread, &QThread::finished, this, &SupportBundleDialog::workDone);
    connect(w->thread, &QThread::finished, w->thread, &QObject::deleteLater);
    setBusy(true);
    w->thread->start();
    return true;
}

void SupportBundleDialog::cancelWork()
{
    if (m_work)
        m_work->cancel = true;
}

void SupportBundleDialog::reject()
{
    if (m_work) {
        cancelWork(); // the dialog stays until the work has stopped and said so
        return;
    }
    QDialog::reject();
}

void SupportBundleDialog::setBusy(bool busy)
{
    m_days->setEnabled(!busy);
    m_profile->setEnabled(!busy && QFileInfo::exists(m_profilePath));
    m_buttons->button(QDialogButtonBox::Save)->setEnabled(!busy);
    m_progressBar->setValue(0);
    m_progressBar->setVisible(busy);
    if (busy) {
        m_report->setEnabled(false);
        m_poll.start();
    } else {
        m_poll.stop();
        refresh();
    }
}

void SupportBundleDialog::workDone()
{
    const std::shared_ptr<Work> w = std::exchange(m_work, nullptr);
    if (!w)
        return;
    setBusy(false);
    const QString zipPath = w->zipPath;
    if (!w->ok && w->cancel) {
        showResult(false, tr("The support bundle was cancelled: nothing was written."),
                   QMessageBox::Information);
        return;
    }
    showResult(w->ok,
               w->ok ? tr("Support bundle written: %1 (%2). It holds:")
                               .arg(QDir::toNativeSeparators(zipPath),
                                    QLocale().formattedDataSize(QFileInfo(zipPath).size())) +
                           QStringLiteral("\n• ") + w->contents.join(QStringLiteral("\n• "))
                     : tr("The support bundle was not written: %1").arg(w->error),
               w->ok ? QMessageBox::Information : QMessageBox::Warning);
}

void SupportBundleDialog::showResult(bool ok, const QString &message, int icon)
{
    if (m_result)
        m_result->deleteLater();
    m_result = new QMessageBox(QMessageBox::Icon(icon), tr("Create support bundle"), message,
                               QMessageBox::Ok, parentWidget() ? parentWidget() : this);
    m_result->setAttribute(Qt::WA_DeleteOnClose);
    m_result->open();
    Q_EMIT written(ok, message);
    if (ok)
        accept();
}

QMessageBox *SupportBundleDialog::resultBox() const
{
    return m_result;
}

} // namespace stepcom
